#!/bin/sh
# A 5 x 5 array of 24 nm contact holes at EUV (13.5 nm, NA 0.33) with photon and acid shot noise (bleach(5) stochastic): the local CD uniformity.
# Usage: sh run.sh [sample3D options]; outputs go to $OUT (default: out/ here):
# sample3D's files and holes.txt, measure -lcdu -holes at half the
# thickness: every opening's centroid and diameter, and their 3 sigma.
# The noise may open small pockets besides the 25 holes: the summary
# counts the holes (openings of half the drawn 24 nm or more) and those
# pockets apart, and gives the holes' mean and 3 sigma (the LCDU).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
# -refine 8: fast marching's automatic z refinement follows the
# largest rate ratio between neighbouring z nodes, meant for standing
# waves (off here); the shot noise of every 2 nm voxel takes it to its
# cap, 16.  Eight gives the same summary (22.7 nm, 4.8 nm, 2 pockets;
# every hole's diameter within 0.06 nm of 16's) in under half the time.
sample3D -if "$here/mask.in" -bf "$here/resist.in" -et 20 -pt 20 -method fmm -refine 8 "$@"
# -force: the noisy surface may touch itself
measure -force -rel 50 -lcdu -holes -o holes.txt curves.plot
awk '/^#/ { next } { if ($3 >= 0.012) { s += $3; s2 += $3 * $3; n++ } else p++ }
     END { m = n ? s / n : 0; sd = n > 1 ? sqrt((s2 - n * m * m) / (n - 1)) : 0
	   printf "%d holes of 25, mean diameter %.4f um, LCDU (3 sigma) %.4f um; %d smaller pockets\n",
		  n, m, 3 * sd, p }' holes.txt
