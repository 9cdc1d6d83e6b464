#!/bin/sh
# 16 nm lines at 32 nm pitch at EUV (13.5 nm, NA 0.33) with photon and acid shot noise (bleach(5) stochastic), at 30 and 60 mJ/cm2.
# Usage: sh run.sh [sample3D options]; outputs go to $OUT (default: out/ here),
# one directory a dose (d30, d60), each with sample3D's files and cd.txt,
# measure's table of the line width at 10, 50 and 90 % of the thickness.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
splat -q "$here/mask.in"
for dose in 30 60; do
	mkdir -p "d$dose"
	sed "s/^dose .*/dose $dose/" "$here/resist.in" >"d$dose/resist.in"
	(cd "d$dose" && sample3D -cf ../image.cont -bf resist.in -et 20 -pt 20 -method fmm -h \
		-cut y 0 -measure "-rel 10,50,90 -line 0 0 x" "$@" >cd.txt)
	echo "$dose mJ/cm2: line width (um) at 10, 50, 90 % of the thickness:" \
		$(awk '!/^#/ { print $2 }' "d$dose/cd.txt")
done
