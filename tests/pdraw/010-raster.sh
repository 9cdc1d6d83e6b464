# pdraw -h on a mesh finer than the page's pixels (a 300 x 300 grid of
# triangles, a cosine bump on a 3 x 3 um sheet: 180000 triangles, 1.6 x
# 1.6 points each on the page) draws it as one shaded picture: checked
# that the PostScript holds one image (RunLengthDecode) and no polygon of
# the mesh (fewer than 100 fill operators: the axes and walls are not
# filled), is under 1 MB (a polygon per triangle wrote 18 MB), is the
# same byte for byte when drawn again, that its SVG embeds one PNG (under
# 2 MB), and that ghostscript renders it;
# -vector draws the polygons instead (more than 100000 fills; on a 200 x
# 200 grid, 2.4 x 2.4 points a cell, still drawn as a picture by default,
# as checked: the 300 grid's 57 MB of polygons cost 3 s, this one's 0.9),
# and a coarse mesh (a 20 x 20 grid) stays vector by default.  -window 0 1 0 1
# cuts the sets to that square: its x ticks end at 1 (the data's at 3),
# a window holding none of the data is an empty page, not an error, and
# an empty window is a usage error.  -window auto draws the central 6 x 6
# um of a 20 um sheet (its title says so) and a 3 um box whole.  -walls
# puts a wall under an edge whose node is 1e-6 um inside the side.
. "$TOP/tests/lib/common.sh"
mesh() { # mesh N: the bump as 2 N^2 triangles
	awk -v n="$1" 'function z(i, j) { return 0.2 * cos((i / n - 0.5) * 3.14159) * cos((j / n - 0.5) * 3.14159) }
	BEGIN { print "0 3 0 3 0 0.3"; print 2 * n * n
		for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
			x0 = 3 * i / n; x1 = 3 * (i + 1) / n; y0 = 3 * j / n; y1 = 3 * (j + 1) / n
			print 4; print x0, y0, z(i, j); print x1, y0, z(i + 1, j); print x1, y1, z(i + 1, j + 1); print x0, y0, z(i, j)
			print 4; print x0, y0, z(i, j); print x1, y1, z(i + 1, j + 1); print x0, y1, z(i, j + 1); print x0, y0, z(i, j)
		} }'
}
mesh 300 >fine.3D
mesh 20 >coarse.3D
pdraw -noplot -h -walls -psfile fine.ps fine.3D </dev/null || fail "pdraw -h fine"
[ "$(grep -c 'RunLengthDecode filter image' fine.ps)" -eq 1 ] || fail "fine mesh: not one picture"
nf=$(grep -c ' F' fine.ps || true)
[ "$nf" -lt 100 ] || fail "fine mesh: $nf fills beside the picture"
[ "$(wc -c <fine.ps)" -lt 1000000 ] || fail "fine mesh: $(wc -c <fine.ps) bytes"
pdraw -noplot -h -walls -psfile again.ps -svg fine.svg fine.3D </dev/null || fail "pdraw -h fine, again"
same fine.ps again.ps
# the SVG embeds the picture as one PNG (its signature, base64 iVBORw0KGgo)
[ "$(grep -c 'xlink:href="data:image/png;base64,iVBORw0KGgo' fine.svg)" -eq 1 ] ||
	fail "fine mesh: the SVG holds no PNG picture"
[ "$(wc -c <fine.svg)" -lt 2000000 ] || fail "fine mesh: the SVG has $(wc -c <fine.svg) bytes"
mesh 200 >mid.3D
pdraw -noplot -h -psfile mid.ps mid.3D </dev/null || fail "pdraw -h mid"
[ "$(grep -c 'RunLengthDecode filter image' mid.ps)" -eq 1 ] || fail "the 200 x 200 mesh: not a picture by default"
pdraw -noplot -h -vector -psfile vec.ps mid.3D </dev/null || fail "pdraw -h -vector"
[ "$(grep -c ' F' vec.ps)" -gt 100000 ] || fail "-vector: the polygons are not drawn"
! grep -q RunLengthDecode vec.ps || fail "-vector drew a picture"
pdraw -noplot -h -psfile coarse.ps coarse.3D </dev/null || fail "pdraw -h coarse"
! grep -q RunLengthDecode coarse.ps || fail "a coarse mesh drawn as a picture"
pdraw -noplot -h -vector -window 0 1 0 1 -psfile win.ps coarse.3D </dev/null || fail "-window"
grep -q '^(1\.0) ' win.ps || fail "-window 0 1 0 1: no tick at 1"
! grep -q '^([23]\(\.0\)*) ' win.ps || fail "-window 0 1 0 1: ticks beyond the window"
pdraw -noplot -h -window 5 6 5 6 -psfile none.ps coarse.3D </dev/null || fail "-window outside the data"
pdraw -noplot -h -window 1 0 0 1 coarse.3D </dev/null >/dev/null 2>err.txt
[ $? -eq 2 ] || fail "-window 1 0 0 1: not a usage error"
grep -q '^pdraw: option -window: x0 x1 y0 y1 with x0 < x1 and y0 < y1' err.txt ||
	fail "-window 1 0 0 1: $(head -n 1 err.txt)"
# -window auto: a 20 x 20 um sheet is drawn in its central 6 x 6 um, the
# title saying so and the x ticks ending at +-2 (-3..3 by 2s); the 3 x 3
# um bump whole
awk 'BEGIN { print "-10 10 -10 10 0 0.3"; print 1; print 5
	print -10, -10, 0.3; print 10, -10, 0.3; print 10, 10, 0.3; print -10, 10, 0.3; print -10, -10, 0.3 }' >big.3D
pdraw -noplot -h -window auto -tl sheet -psfile big.ps big.3D </dev/null || fail "-window auto"
grep -q '^(sheet, the central 6 x 6 um) ' big.ps || fail "-window auto: no title of the central 6 x 6 um"
! grep -q '^(-\{0,1\}10) ' big.ps || fail "-window auto: ticks at +-10"
pdraw -noplot -h -window auto -tl bump -psfile small.ps coarse.3D </dev/null || fail "-window auto, small"
grep -q '^(bump) ' small.ps || fail "-window auto cut a 3 um box"
# -walls: a sheet whose corner node lies 1e-6 um inside the side x = 0
# (etch's clipping once left such nodes) still gets its four walls (0.82
# grey fills), not three and a white slit
awk 'BEGIN { print "0 3 0 3 0 0.3"; print 1; print 5
	print 0, 0, 0.3; print 3, 0, 0.3; print 3, 3, 0.3; print 0.000001, 3, 0.3; print 0, 0, 0.3 }' >hair.3D
pdraw -noplot -h -walls -vector -psfile hair.ps hair.3D </dev/null || fail "-walls, a node a hair inside"
[ "$(grep -c ' 0.82 F' hair.ps)" -eq 4 ] || fail "-walls: $(grep -c ' 0.82 F' hair.ps) walls, not 4"
gs_check fine.ps
