# pdraw's projection, checked on the SVG coordinates of the data lines
# (stroke width 0.6, the axes use 0.8) against the geometry of a parallel
# projection: seen from +z (-v 0 0 1) a segment along x is horizontal and
# one along y vertical and upwards; from the front (-v 0 -1 0) the
# z segment is vertical; seen along x (-v 1 0 0) the x segment shrinks to
# a point.  Equal scales keep the 10:1 length ratio of the data, -e makes
# the box a cube (ratio 1).  Tolerance 0.02 pt (the SVG's 0.01 rounding).
. "$TOP/tests/lib/common.sh"
cat >seg.3D <<'D'
0 10 0 1 0 1
3
2
0 0 0
10 0 0
2
0 0 0
0 1 0
2
0 0 0
0 0 1
D
# prints "x0 y0 x1 y1" of the n-th data polyline (SVG y is downwards)
line() {
	grep 'stroke-width="0.6"' out.svg | sed -n "${1}p" |
		sed 's/.*points="\([^"]*\)".*/\1/' | tr ',' ' '
}
pdraw -noplot -ps -svg out.svg -v 0 0 1 seg.3D </dev/null || fail "pdraw -v 0 0 1"
set -- $(line 1); close "$2" "$4" 0.02 "x segment from +z: y0 - y1"
lx=$(awk -v a="$1" -v b="$3" 'BEGIN { print b - a }')
set -- $(line 2); close "$1" "$3" 0.02 "y segment from +z: x0 - x1"
ly=$(awk -v a="$2" -v b="$4" 'BEGIN { print a - b }')
close "$(awk -v a="$lx" -v b="$ly" 'BEGIN { print a / b }')" 10 0.01 "length ratio x/y, equal scales"
pdraw -noplot -ps -svg out.svg -v 0 0 1 -e seg.3D </dev/null || fail "pdraw -e"
set -- $(line 1); lx=$(awk -v a="$1" -v b="$3" 'BEGIN { print b - a }')
set -- $(line 2); ly=$(awk -v a="$2" -v b="$4" 'BEGIN { print a - b }')
close "$(awk -v a="$lx" -v b="$ly" 'BEGIN { print a / b }')" 1 0.01 "length ratio x/y with -e"
pdraw -noplot -ps -svg out.svg -v 0 -1 0 seg.3D </dev/null || fail "pdraw -v 0 -1 0"
set -- $(line 3); close "$1" "$3" 0.02 "z segment from the front: x0 - x1"
awk -v a="$2" -v b="$4" 'BEGIN { exit !(a > b) }' || fail "z does not point up from the front"
pdraw -noplot -ps -svg out.svg -v 1 0 0 seg.3D </dev/null || fail "pdraw -v 1 0 0"
set -- $(line 1); close "$1" "$3" 0.02 "x segment seen along x: x"; close "$2" "$4" 0.02 "x segment seen along x: y"
# the default view writes a valid PostScript picture
pdraw -noplot seg.3D </dev/null || fail "pdraw default view"
gs_check dataplot.ps
exit 0
