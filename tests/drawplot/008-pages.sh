# Several sets in one file (separated by a blank line) are one page each,
# for drawplot, pdraw and contour -3D (%%Pages in the PostScript, and the
# SVG stacks the pages: its height is pages x 792 pt); several files add
# their pages.  -l (drawplot, drawmask) writes a landscape page: the
# PostScript says so and rotates, the SVG is 792 pt wide.
. "$TOP/tests/lib/common.sh"
printf '0 1 0 1\n1\n2\n0 0\n1 1\n\n0 2 0 2\n1\n2\n0 2\n2 0\n' >two.2D
drawplot -noplot -svg two.svg two.2D </dev/null || fail "drawplot two sets"
grep -q '^%%Pages: 2$' dataplot.ps || fail "drawplot: two sets are not two pages"
grep -q 'height="1584pt"' two.svg || fail "drawplot: SVG does not stack two pages"
gs_check dataplot.ps
drawplot -noplot two.2D two.2D </dev/null || fail "drawplot two files"
grep -q '^%%Pages: 4$' dataplot.ps || fail "drawplot: two files of two sets are not four pages"
printf '0 1 0 1 0 1\n1\n4\n0 0 0\n1 0 1\n0 1 1\n0 0 0\n\n0 1 0 1 0 1\n1\n4\n0 0 1\n1 0 0\n0 1 0\n0 0 1\n' >two.3D
pdraw -noplot -h two.3D </dev/null || fail "pdraw two sets"
grep -q '^%%Pages: 2$' dataplot.ps || fail "pdraw: two sets are not two pages"
contour -noplot -3D -cstep 0.25 two.3D </dev/null || fail "contour -3D two sets"
grep -q '^%%Pages: 2$' dataplot.ps || fail "contour -3D: two sets are not two pages"
gs_check dataplot.ps
drawplot -noplot -l -svg land.svg two.2D </dev/null || fail "drawplot -l"
grep -q '^%%Orientation: Landscape$' dataplot.ps || fail "drawplot -l: not landscape"
grep -q '90 rotate' dataplot.ps || fail "drawplot -l: page not rotated"
grep -q 'width="792pt"' land.svg || fail "drawplot -l: SVG not landscape"
printf 'window 0 4 0 4\nrect 1 1 3 3\n' >m.in
drawmask -noplot -l m.in </dev/null || fail "drawmask -l"
grep -q '^%%Orientation: Landscape$' dataplot.ps || fail "drawmask -l: not landscape"
gs_check dataplot.ps
exit 0
