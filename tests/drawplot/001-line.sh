# drawplot puts a known line on the expected pixels: with -ar the axes
# are exactly the bounds 0..10, so data (x, y) lands at box origin +
# (x/10, y/10) times the box size; the box is read from the PostScript
# (the first rectangle drawn).  ghostscript renders at one pixel per
# point; points on the diagonal y = x and on the horizontal y = 2.5 must
# be dark (gray < 128 within one pixel), points 6 pt beside them white
# (> 200).  Then autorange: bounds 0.13..9.7 must become round limits
# 0..10 (tick labels 0 and 10 present).
. "$TOP/tests/lib/common.sh"
need gs
printf '0 10 0 10\n2\n2\n0 0\n10 10\n2\n0 2.5\n10 2.5\n' >l.2D
drawplot -noplot -ar l.2D </dev/null || fail "drawplot -ar"
gs_check dataplot.ps
set -- $(awk '$1 == "closepath" { print prev; exit } { prev = $0 }' dataplot.ps)
x0=$1 y0=$2 x1=$4 y1=$8
echo "box $x0 $y0 $x1 $y1"
awk -v x0="$x0" -v y0="$y0" -v x1="$x1" -v y1="$y1" 'BEGIN {
	w = x1 - x0; h = y1 - y0
	for (t = 0.2; t < 0.85; t += 0.15) {
		print x0 + t * w, y0 + t * h                 # on the diagonal
		print x0 + t * w, y0 + 0.25 * h              # on y = 2.5
	}
	for (t = 0.2; t < 0.85; t += 0.15) {
		print x0 + t * w - 6, y0 + t * h + 6        # beside the diagonal
		print x0 + t * w + 3, y0 + 0.25 * h + 6      # above y = 2.5
	}
}' >q.txt
gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=pgm -r72 -sOutputFile=p.pgm dataplot.ps </dev/null >/dev/null 2>&1
awk -v mode=query -f "$TOP/tests/pdraw/pixels.awk" q.txt p.pgm >v.txt
n=$(wc -l <v.txt)
[ "$n" -eq 20 ] || fail "expected 20 pixel values, got $n"
head -n 10 v.txt | awk '$1 >= 128 { bad++ } END { exit bad > 0 }' || fail "line pixels not dark: $(head -n 10 v.txt | tr '\n' ' ')"
tail -n 10 v.txt | awk '$1 <= 200 { bad++ } END { exit bad > 0 }' || fail "pixels beside the lines not white: $(tail -n 10 v.txt | tr '\n' ' ')"
printf '0.13 9.7 0.13 9.7\n1\n2\n0.13 0.13\n9.7 9.7\n' >a.2D
drawplot -noplot a.2D </dev/null || fail "drawplot autorange"
grep -q '^(0) .* T$' dataplot.ps && grep -q '^(10) .* T$' dataplot.ps || fail "autorange did not round the axes to 0..10"
exit 0
