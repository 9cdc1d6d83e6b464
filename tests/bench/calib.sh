#!/bin/sh
# tests/bench/calib.sh [BUILD] - calib at full size: the contact of
# examples/contact-highna as it is (81 x 81 grid, 11-plane image stack,
# nz 81, fast marching, bottom CD) through 5 foci x 3 doses = 15 points,
# "measured" from a hidden development (Mth 0.56, n 6.5) plus fixed
# offsets of about 1 nm, fitted from the example's (Mth 0.5, n 5) with
# -j 2; and a mismatched model (Mth and n free, but the hidden process also
# has a different Dill C) that must report its larger rms.  Prints the
# recovered values against the truth, their stderr, the rms, the
# validation rms on 4 other points, the iterations, wall and CPU time.
# Aim: under 15 minutes wall on 2 idle cores.  Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
PATH=$BUILD/bin:$PATH
E=$TOP/examples/contact-highna
dir=$(mktemp -d "${TMPDIR:-/tmp}/calibbench.XXXXXX")
trap 'rm -rf "$dir"' EXIT INT TERM
cd "$dir" || exit 1
M="-rel 5 -hole 0 0"
sed 's/^develop mack 0.1 0.0001 0.5 5$/develop mack 0.1 0.0001 0.56 6.5/' "$E/resist.in" >hidden.in
sed 's/dill 0.8 0.05 0.014/dill 0.8 0.05 0.017/' hidden.in >hidden-c.in
noise() {
	awk -v off="$1" 'BEGIN { split(off, o, " ") }
		!/^#/ { k++; printf "%s %s %.4f\n", $1, $2, $3 + o[k] / 1000 }' "$2"
}
OFF="0.9 -1.2 0.4 1.3 -0.7 -0.8 1.1 -0.3 0.6 -1.4 0.2 -0.1 1.5 -0.4 0.3"
for h in hidden hidden-c; do
	fem -q -if "$E/mask.in" -bf $h.in -et 60 -method fmm -measure "$M" -focus -0.9:0.3:0.3 \
		-dose 70,80,90 -d $h -j 2 || { echo "fem on $h.in failed"; exit 1; }
	fem -q -if "$E/mask.in" -bf $h.in -et 60 -method fmm -measure "$M" \
		-points -0.45:75,-0.15:85,0.15:75,0.15:85 -d $h-other -j 2 || exit 1
	noise "$OFF" $h/fem.dat >$h.dat
	noise "-0.5 1.0 0.7 -0.9" $h-other/fem.dat >$h-other.dat
done
fit() { # fit NAME DATA
	t0=$(date +%s.%N)
	/usr/bin/time -f '%U %S' -o cpu-$1.txt calib -q -if "$E/mask.in" -bf "$E/resist.in" -et 60 \
		-data $2.dat -validate $2-other.dat -measure "$M" -free "develop 3 0.3:0.8" \
		-free "develop 4 2:12" -j 2 -d $1 2>err-$1.txt || { echo "calib $1 failed: $(tail -n 2 err-$1.txt)"; return; }
	t1=$(date +%s.%N)
	printf 'calib %s, 15 points, -j 2: %.0f s wall, %.0f s CPU\n' "$1" \
		"$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" "$(awk '{ print $1 + $2 }' cpu-$1.txt)"
	awk '$1 == "develop" { printf "  develop %d: %.5g +- %.2g (truth %s)\n", $2, $3, $4, $2 == 3 ? 0.56 : 6.5 }
		/^# (rms_nm|validate_rms_nm|points)/ { print "  " $0 }' $1/calib.dat
	sed 's/^/  /' err-$1.txt
}
fit matched hidden
fit mismatched hidden-c
