#!/bin/sh
# The delooped surface meets the box's edge where a side wall stands on
# the substrate: examples/corner-defect in Kodak 820 at 88 mJ/cm2, etch
# -et 20 -deloop (one set).  Along the wall y = -5 (a mirror plane) the
# cleared space left of the large square reaches the substrate; the
# wall's profile ended just above the substrate (z = -1.15 um, on the
# wall) and the floor just short of the wall (y = -4.98 um, on the
# substrate), and each end of that 2.2 um stretch was a segment joining
# the two across the corner: open border, 0.367 um of it in all (with the
# one on the wall x = 5), and measure refused the space's section near the
# substrate ("passes through a gap ... 2.22 um wide").  The closing now
# adds a node on the box's edge and closes each such segment with a
# triangle whose other sides lie on the two faces.  Checked:
#   - etch's summary reports 0 um of border left open and 0 crossings
#     left;
#   - measure reads the space at y = -4.999 um (0.001 um from the wall)
#     at 2, 3, 4 and 10 % height without -force and with nothing on
#     stderr, and each cd is within TOL = 3 % of the fast-marching
#     surface's (etch -et 20 -method fmm on the same rate file, measured
#     the same way; its cds are written here, FMM, as that run costs 15 s
#     of CPU).  The ray-string measured 2.2639 2.2824 2.3016 2.4486 um,
#     at most 1.1 % from fmm.
. "$TOP/tests/lib/common.sh"
TOL=0.03
FMM="2.2386 2.266991 2.294961 2.446097"
E=$TOP/examples/corner-defect
cp "$E/mask.in" mask.in
splat -q mask.in || fail "splat"
bleach -q -o k.bin image.cont "$E/resist-kodak820-88.in" || fail "bleach"
etch -et 20 -deloop -o ray.plot k.bin >/dev/null 2>ray.log || fail "etch -deloop: $(tail -n 1 ray.log)"
line=$(grep 'etch: deloop:' ray.log) || fail "no deloop summary"
echo "$line"
echo "$line" | grep -q ' 0 crossings left' || fail "crossings left: $line"
echo "$line" | grep -q ' 0 um of border left open' || fail "border left open: $line"
measure -rel 2,3,4,10 -space -1.5 -4.999 x ray.plot >ray.txt 2>ray.err || fail "measure refused: $(cat ray.err)"
[ ! -s ray.err ] || fail "measure warned: $(cat ray.err)"
r=$(awk '!/^#/ { printf "%s ", $2 }' ray.txt)
echo "space cds at 2 3 4 10 %: fast marching $FMM, ray-string $r"
echo "$FMM $r" | awk -v t=$TOL '{ if (NF != 8) exit 1; for (i = 1; i <= 4; i++) { a = $i; b = $(i + 4)
	if (!(a > 1)) exit 1; d = (a - b) / a; if (d < 0) d = -d; if (d > t) exit 1 } }' ||
	fail "the ray-string's cds differ from fast marching's by more than $TOL"
exit 0
