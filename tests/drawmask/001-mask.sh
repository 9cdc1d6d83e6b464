# drawmask paints the window with the background and the rects on top,
# gray by intensity transmission |t|^2: 0.3 (opaque) + 0.7 |t|^2, so on a
# 0..255 raster (ghostscript, one pixel per point) opaque is 77, t = 0.5
# is 121, clear 255 (tolerance 3 levels for gray rounding).  The page box
# is the first rectangle of the PostScript (the window).  A phase-shifted
# rect is hatched (clipped hatch lines) and labelled "180 deg"; -lbl labels
# every feature; overlapping rects are reported on stderr with both line
# numbers; and the picture renders in ghostscript.
. "$TOP/tests/lib/common.sh"
need gs
cat >mask.in <<'M'
wavelength 0.436
window 0 10 0 10
background dark
rect 1 1 4 4
rect 6 1 9 4 0.5 0
rect 1 6 4 9 1 180
rect 3.5 3.5 5 5
M
drawmask -noplot mask.in </dev/null 2>err.txt || fail "drawmask: $(cat err.txt)"
gs_check dataplot.ps
grep -q '^drawmask: mask.in:7: rect overlaps the rect of line 4' err.txt || fail "overlap not reported: $(cat err.txt)"
[ "$(wc -l <err.txt)" -eq 1 ] || fail "expected one overlap report: $(cat err.txt)"
grep -q '^(180 deg) ' dataplot.ps || fail "phase label missing"
grep -q 'rectclip' dataplot.ps || fail "no hatching of the phase-shifted rect"
set -- $(awk '$1 == "closepath" || $1 ~ /^closepath/ { print prev; exit } { prev = $0 }' dataplot.ps)
x0=$1 y0=$2 x1=$4 y1=$8
awk -v x0="$x0" -v y0="$y0" -v x1="$x1" -v y1="$y1" 'BEGIN {
	sx = (x1 - x0) / 10; sy = (y1 - y0) / 10
	print x0 + 2 * sx, y0 + 2 * sy       # clear
	print x0 + 7.5 * sx, y0 + 2 * sy     # t = 0.5
	print x0 + 7 * sx, y0 + 7 * sy       # opaque background
}' >q.txt
gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=pgm -r72 -sOutputFile=m.pgm dataplot.ps </dev/null >/dev/null 2>&1
set -- $(awk -v mode=query -f "$TOP/tests/pdraw/pixels.awk" q.txt m.pgm)
echo "clear $1, half $2, opaque $3"
close "$1" 255 3 "clear area gray"
close "$2" 121 3 "t = 0.5 area gray"
close "$3" 77 3 "opaque area gray"
drawmask -noplot -lbl mask.in </dev/null 2>/dev/null || fail "drawmask -lbl"
grep -q '^(#1: transmission 1, phase 0 deg) ' dataplot.ps || fail "-lbl: feature label missing"
exit 0
