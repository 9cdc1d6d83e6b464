#!/bin/sh
# Calibrate to measured CDs: the contact of examples/contact-highna (a
# coarser grid) through focus and dose.  The "measured" CDs are made here
# by fem from hidden.in (the hidden process) plus fixed offsets of about
# 1 nm standing for measurement noise; calib then fits the development's
# Mth and n of resist.in (which starts from other values) to them, and
# checks the result on four other points.
# Usage: sh calibrate.sh [calib options, e.g. -q]; outputs in $OUT (default
# out/ here); JOBS simulations at once (default 2).  Prints the table of
# README's "Calibrate to measured CDs" (also in $OUT/table.txt).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v calib >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
M="-rel 5 -hole 0 0"
# measured.dat: 3 foci x 2 doses; other.dat: 4 points between them
fem -q -if "$here/mask.in" -bf "$here/hidden.in" -et 60 -method fmm -measure "$M" \
	-focus -0.6,-0.15,0.3 -dose 70,90 -d hidden -j "${JOBS:-2}"
fem -q -if "$here/mask.in" -bf "$here/hidden.in" -et 60 -method fmm -measure "$M" \
	-points -0.45:75,-0.15:85,0.15:75,0.15:85 -d hidden-other -j "${JOBS:-2}"
noise() { # noise "OFFSETS (nm)" fem.dat: focus dose cd + offset, row by row
	awk -v off="$1" 'BEGIN { split(off, o, " "); print "# focus dose cd (um)" }
		!/^#/ { k++; printf "%s %s %.4f\n", $1, $2, $3 + o[k] / 1000 }' "$2"
}
noise "0.9 -1.2 0.4 1.1 -0.7 -0.6" hidden/fem.dat >measured.dat
noise "-0.5 1.0 0.7 -0.9" hidden-other/fem.dat >other.dat

calib -if "$here/mask.in" -bf "$here/resist.in" -et 60 -data measured.dat -measure "$M" \
	-free "develop 3 0.3:0.8" -free "develop 4 2:12" -validate other.dat -d calib \
	-j "${JOBS:-2}" "$@"

# the table: hidden, start and fitted values with their 1-sigma errors
{
	echo "| parameter | hidden | start | fitted | stderr |"
	echo "|---|---|---|---|---|"
	awk 'NR == FNR { if ($1 == "develop") { h3 = $5; h4 = $6 }; next }
		FILENAME ~ /resist.in$/ { if ($1 == "develop") { s3 = $5; s4 = $6 }; next }
		$1 == "develop" { name = $2 == 3 ? "Mth (develop 3)" : "n (develop 4)"
			printf "| %s | %s | %s | %.4f | %.4f |\n", name, $2 == 3 ? h3 : h4,
				$2 == 3 ? s3 : s4, $3, $4 }
		$2 == "rms_nm" { rms = $3 } $2 == "validate_rms_nm" { vrms = $3 }
		$2 == "points" { n = $3; it = $9 }
		END { printf "\nrms %.2f nm over the %d measured points, %.2f nm over the 4 others; %d iterations\n",
			rms, n, vrms, it }' "$here/hidden.in" "$here/resist.in" calib/calib.dat
} >table.txt
cat table.txt
