#!/bin/sh
# etch: uniform rate 1 um/s from a seed point (thesis Figure 8.3), 1 s.
# Checks against the exact answer, a sphere of radius 1 um about the
# seed: with arc interpolation (default) every node lies within 1% of
# radius 1; with -linear the largest error is bigger than with arc
# interpolation (the thesis' observation: the linear mesh falls short).
# The mesh checker runs after every step (-check).  A seed at a corner of
# the box is clipped to an eighth of a sphere, still within 1%.
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
$MKRATE -o rate.bin 5 5 5 -1.5 1.5 -1.5 1.5 -3 0 1 || fail "mkrate"
radius_err() {   # max | |p - c| - 1 | over the nodes of the last set
	awk -v cx="$2" -v cy="$3" -v cz="$4" 'NF == 3 {
		r = sqrt(($1 - cx)^2 + ($2 - cy)^2 + ($3 - cz)^2); d = r - 1; if (d < 0) d = -d
		if (d > m) m = d } END { printf "%.6f\n", m }' "$1"
}
etch -et 1 -seg 0.1 -seed 0 0 -1.5 -check -q rate.bin || fail "etch failed"
arc=$(radius_err curves.plot 0 0 -1.5)
etch -et 1 -seg 0.1 -seed 0 0 -1.5 -linear -check -q -o lin.plot rate.bin || fail "etch -linear failed"
lin=$(radius_err lin.plot 0 0 -1.5)
echo "radius error: arc $arc, linear $lin"
close "$arc" 0 0.01 "arc-interpolated sphere radius error"
awk -v a="$arc" -v l="$lin" 'BEGIN { exit !(l > a) }' || fail "linear ($lin) not worse than arc ($arc)"
etch -et 1 -seg 0.1 -seed 1.5 1.5 0 -check -q -o corner.plot rate.bin || fail "corner seed"
c=$(radius_err corner.plot 1.5 1.5 0)
echo "corner seed: radius error $c"
close "$c" 0 0.01 "corner sphere radius error"
n=$(grep -v '^#' corner.plot | awk 'NF == 1 && NR == 2')
[ "$n" -gt 100 ] || fail "corner sphere has only $n triangles"
exit 0
