# pdraw -h on three bars that overlap cyclically (A over B, B over C,
# C over A, seen from +z): no order of whole polygons can paint this, so
# a plain depth sort must fail somewhere, while the BSP painter splits
# them.  The expected picture follows from the geometry: at each crossing
# the upper bar's edge is visible (dark pixel, < 128 within one pixel) and
# the lower bar's edge is hidden (white, > 200).  Page positions come from
# the x axis drawn along the box edge y = 3 from x = 0 to x = 3 (the first
# axis line, width 0.8, in the SVG), so the test does not depend on the
# page layout.
. "$TOP/tests/lib/common.sh"
need gs
# A: y 0..0.6, z rising with x; B: x 2.4..3, z rising with y; C: the
# diagonal strip |y - x| <= 0.6 at z = 1.
cat >bars.3D <<'D'
0 3 0 3 0 3
3
5
0 0 -0.25
3 0 2.25
3 0.6 2.25
0 0.6 -0.25
0 0 -0.25
5
2.4 0 0.75
3 0 0.75
3 3 3.25
2.4 3 3.25
2.4 0 0.75
5
0.6 0 1
3 2.4 1
2.4 3 1
0 0.6 1
0.6 0 1
D
pdraw -noplot -h -v 0 0 1 -svg b.svg bars.3D </dev/null || fail "pdraw -h"
gs_check dataplot.ps
set -- $(grep 'stroke-width="0.8"' b.svg | head -n 1 | sed 's/.*points="\([^"]*\)".*/\1/' | tr ',' ' ')
x0=$1 y0=$2 x1=$3
# page point of data (x, y): x axis runs along y = 3; scale from its length
awk -v x0="$x0" -v y0="$y0" -v x1="$x1" 'BEGIN {
	a = (x1 - x0) / 3; top = 792 - y0
	n = split("2.7 0.6  0.9 0.3  2.4 2.6  2.4 0.3  0.6 0.6  2.7 2.1", p, " +")
	for (i = 1; i < n; i += 2) print x0 + a * p[i], top - a * (3 - p[i + 1])
}' >q.txt
gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=pgm -r72 -sOutputFile=b.pgm dataplot.ps </dev/null >/dev/null 2>&1
set -- $(awk -v mode=query -f "$TOP/tests/pdraw/pixels.awk" q.txt b.pgm)
echo "visible edges: $1 $2 $3; hidden edges: $4 $5 $6"
[ "$1" -lt 128 ] || fail "A's edge over B is not drawn ($1)"
[ "$2" -lt 128 ] || fail "C's edge over A is not drawn ($2)"
[ "$3" -lt 128 ] || fail "B's edge over C is not drawn ($3)"
[ "$4" -gt 200 ] || fail "B's edge under A shows ($4)"
[ "$5" -gt 200 ] || fail "A's edge under C shows ($5)"
[ "$6" -gt 200 ] || fail "C's edge under B shows ($6)"
exit 0
