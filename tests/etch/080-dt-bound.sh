#!/bin/sh
# A smaller time step does not grow the ray-string mesh: on a smooth
# off-centre Gaussian rate (0.01 + 0.3 exp(-r^2/0.1) um/s centred at
# (0.3, 0.2) in a 2 x 2 x 1 um box, so that the rays near the corner
# x = y = 1 lean out of the box), etch 3 s with -dt 0.1, 0.02 and 0.005.
# Before clipping stopped cutting segments a hair from a node (ray_clip.c,
# CLIP_SNAP), every clip left new nodes beside the old ones at the walls
# and -dt 0.02 and 0.005 died with "mesh grew past its bound" (at 2.4 and
# 0.65 s).  Checked, for each step: the run succeeds, its final mesh has
# at most 1.25 times the triangles of the -dt 0.1 run (the mesh follows
# the surface's area, not the number of steps or clips; measured 6863,
# 6961 and 7030), and -xcheck puts 95 % of its nodes within 0.01 um (a
# fifth of S_ideal 0.05 um) of the fast-marching surface (measured
# 0.0049 um at each step).
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
$MKRATE -o rate.bin 41 41 21 -1 1 -1 1 -1 0 '0.01 + 0.3 * exp(-((x - 0.3)^2 + (y - 0.2)^2) / 0.1)' ||
	fail "mkrate"
ref=
for dt in 0.1 0.02 0.005; do
	etch -et 3 -dt $dt -xcheck -o s.plot rate.bin >/dev/null 2>log.txt || fail "-dt $dt: $(grep bound log.txt)"
	tris=$(awk '/final mesh/ { for (i = 1; i <= NF; i++) if ($i ~ /^triangles/) { print $(i - 1); exit } }' log.txt)
	p95=$(awk '/xcheck t = / { for (i = 1; i <= NF; i++) if ($i == "95%") { print $(i + 1); exit } }' log.txt)
	echo "-dt $dt: $tris triangles, 95 % of the nodes within $p95 um of fast marching"
	[ -n "$tris" ] && [ -n "$p95" ] || fail "-dt $dt: no mesh size or xcheck line"
	[ -n "$ref" ] || ref=$tris
	awk -v a="$tris" -v b="$ref" 'BEGIN { exit !(a <= 1.25 * b) }' ||
		fail "-dt $dt: $tris triangles, more than 1.25 times the $ref of -dt 0.1"
	awk -v p="$p95" 'BEGIN { exit !(p <= 0.01) }' || fail "-dt $dt: 95 % at $p95 um"
done
exit 0
