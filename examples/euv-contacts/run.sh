#!/bin/sh
# A 5 x 5 array of 24 nm contact holes at EUV (13.5 nm, NA 0.33) with photon and acid shot noise (bleach(5) stochastic): the local CD uniformity.
# Usage: sh run.sh [sample3D options]; outputs go to $OUT (default: out/ here):
# sample3D's files and holes.txt, every hole's diameter at half the
# thickness (measure -hole, -force: the noisy surface may touch itself;
# 0 where the hole did not open), then the mean,
# 3 sigma (the LCDU) and the count of holes that did not open.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
sample3D -if "$here/mask.in" -bf "$here/resist.in" -et 20 -pt 20 -method fmm -h "$@"
: >holes.txt
for j in 0 1 2 3 4; do
	for i in 0 1 2 3 4; do
		x=$(awk -v i="$i" 'BEGIN { print -0.096 + 0.048 * i }')
		y=$(awk -v j="$j" 'BEGIN { print -0.096 + 0.048 * j }')
		measure -force -rel 50 -hole "$x" "$y" -o hole.txt curves.plot
		printf '%s %s %s\n' "$x" "$y" "$(awk '!/^#/ { print $2; exit }' hole.txt)" >>holes.txt
	done
done
rm -f hole.txt
awk '{ d = $3 + 0; if (d > 0) { s += d; s2 += d * d; n++ } else miss++ }
     END { m = n ? s / n : 0; sd = n > 1 ? sqrt((s2 - n * m * m) / (n - 1)) : 0
	   printf "%d holes open of %d: mean diameter %.4f um, LCDU (3 sigma) %.4f um\n",
		  n, n + miss, m, 3 * sd }' holes.txt | tee -a holes.txt
