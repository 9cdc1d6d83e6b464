# drawmask draws polygon and gds shapes filled by transmission, as rects
# (gray 0.3 + 0.7 |t|^2 on a 0..255 raster: opaque 77, t = 0.5 121, clear
# 255, tolerance 3 levels): a clear triangle, a t = 0.5 polygon, and the
# gds union of tests/gds/data/boxes.gds painted over them; pixels sampled
# inside each, and outside the triangle beside its slanted edge.  A phase
# other than 0 is a dashed outline and a label; the picture renders in
# ghostscript.
. "$TOP/tests/lib/common.sh"
need gs
cp "$TOP/tests/gds/data/boxes.gds" . || fail "no boxes.gds"
cat >mask.in <<'M'
wavelength 0.436
window -5 5 -5 5
background dark
polygon -4.5 -4.5 -0.5 -4.5 -4.5 -0.5
polygon 0.5 -4.5 4.5 -4.5 4.5 -3 0.5 -3 t 0.5 0
gds boxes.gds layer 1/0 cell TOP 1 180
M
drawmask -noplot mask.in </dev/null 2>err.txt || fail "drawmask: $(cat err.txt)"
gs_check dataplot.ps
grep -q '^(180 deg) ' dataplot.ps || fail "phase label of the gds union missing"
set -- $(awk '$1 == "closepath" || $1 ~ /^closepath/ { print prev; exit } { prev = $0 }' dataplot.ps)
x0=$1 y0=$2 x1=$4 y1=$8
awk -v x0="$x0" -v y0="$y0" -v x1="$x1" -v y1="$y1" 'BEGIN {
	sx = (x1 - x0) / 10; sy = (y1 - y0) / 10
	print x0 + 1.5 * sx, y0 + 1.5 * sy   # inside the triangle: clear
	print x0 + 3.0 * sx, y0 + 3.0 * sy   # beyond its slanted edge: opaque
	print x0 + 7.5 * sx, y0 + 1.2 * sy   # the t = 0.5 polygon
	print x0 + 5.8 * sx, y0 + 5.0 * sy   # a box of the gds union: clear
}' >q.txt
gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=pgm -r72 -sOutputFile=m.pgm dataplot.ps </dev/null >/dev/null 2>&1
set -- $(awk -v mode=query -f "$TOP/tests/pdraw/pixels.awk" q.txt m.pgm)
echo "triangle $1, outside $2, half $3, gds $4"
close "$1" 255 3 "clear triangle gray"
close "$2" 77 3 "opaque beside the slanted edge"
close "$3" 121 3 "t = 0.5 polygon gray"
close "$4" 255 3 "gds box gray"
exit 0
