#!/bin/sh
# 45 nm lines and spaces at ArF in water (NA 1.35), TE against TM polarised light, vector imaging through the film, developed and measured.
# Usage: sh run.sh [sample3D options, e.g. -q]; outputs go to $OUT (default: out/ here).
# Each polarisation runs in its own directory: sample3D passes resist.in to
# splat (-bf: the image inside the resist, BARC and silicon) and to bleach,
# etch develops it by fast marching, and measure (when built) writes the
# resist line's width at 10, 50 and 90 % of the thickness to cd.txt.  TE
# prints a 45 nm line; TM, whose two beams barely interfere at this angle,
# leaves the film nearly uniform and the line does not resolve.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
for pol in te tm; do
	mkdir -p "$out/$pol" && cd "$out/$pol"
	sample3D -if "$here/mask-$pol.in" -bf "$here/resist.in" -et 10 -pt 5 -method fmm -hidden "$@"
	if command -v measure >/dev/null 2>&1; then
		measure -rel 10,50,90 -line 0.045 0 x curves.plot >cd.txt 2>measure.log || true
		echo "$pol: line width at 10, 50, 90 % of the thickness:" \
			$(awk '!/^#/ { printf " %.1f nm", 1000 * $2 }' cd.txt)
	fi
done
