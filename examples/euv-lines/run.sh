#!/bin/sh
# 16 nm lines at 32 nm pitch at EUV (13.5 nm, NA 0.33) with photon and acid shot noise (bleach(5) stochastic), at 30 and 60 mJ/cm2.
# Usage: sh run.sh [sample3D options]; outputs go to $OUT (default: out/ here),
# one directory a dose (d30, d60), each with sample3D's files, cd.txt
# (measure's line width at 10, 50 and 90 % of the thickness), and, where
# the line stands along the whole window at half height, ler.txt (measure
# -ler: LER, LWR, correlation length) and psd.ps, the edges' spectrum.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
splat -q "$here/mask.in"
for dose in 30 60; do
	mkdir -p "d$dose"
	sed "s/^dose .*/dose $dose/" "$here/resist.in" >"d$dose/resist.in"
	cd "d$dose"
	# -refine 8: fast marching's automatic z refinement, meant for
	# standing waves (off here), follows the shot noise of every voxel
	# to its cap, 16; eight gives the same figures (width, LER, LWR,
	# correlation length within 0.05 nm) in about half the time
	sample3D -cf ../image.cont -bf resist.in -et 20 -pt 20 -method fmm -refine 8 -cut y 0 \
		-measure "-force -rel 10,50,90 -line 0 0 x" "$@" >cd.txt
	echo "$dose mJ/cm2: line width (um) at 10, 50, 90 % of the thickness:" \
		$(awk '!/^#/ { print $2 }' cd.txt)
	if measure -force -rel 50 -line 0 0 x -ler -psd psd.plot -o ler.txt curves.plot 2>ler.err; then
		drawplot -noplot -xlog -ylog -psfile psd.ps psd.plot </dev/null >/dev/null
		grep '^# ler\|^# lwr\|^# corr' ler.txt | sed "s/^# /$dose mJ\/cm2: /"
		rm -f ler.err
	else
		echo "$dose mJ/cm2: no roughness: $(sed 's/^measure: //' ler.err) (the line broke)"
	fi
	cd ..
done
