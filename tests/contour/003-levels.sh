# Contour levels and joining.  z = x + 2y on [0,1]^2 (range 0..3):
#   -cstep 0.5 gives the levels 0.5 .. 2.5, five straight curves (count of
#   stroked paths inside the plot's clip, from the PS);
#   no step and stdin not a terminal: no prompt (the run must finish under
#   the timeout) and 5 to 20 round levels, labelled;
#   the step from the options-file keyword cstep;
#   -l suppresses the labels (no level text in the PostScript).
# z = x^2 + y^2 on [-1,1]^2 at level 1.5 gives open curves ending on the
# border; -j high closes them along the border (first point = last).
. "$TOP/tests/lib/common.sh"
awk 'BEGIN { n = 11; print 0, 1, 0, 1; print n, n
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) print i / (n - 1) + 2 * j / (n - 1) }' >lin.cont
curves() { awk '/rectclip/ { in_clip = 1 } /^grestore/ { in_clip = 0 }
	in_clip && $0 == "S" { n++ } END { print n + 0 }' dataplot.ps; }
contour -noplot -l -cstep 0.5 lin.cont </dev/null || fail "contour -cstep"
[ "$(curves)" -eq 5 ] || fail "-cstep 0.5: expected 5 curves, got $(curves)"
grep -q ' 8 0 0 0 T$' dataplot.ps && fail "-l: labels drawn"
timeout 20 contour -noplot lin.cont </dev/null || fail "contour without a step (blocked?)"
n=$(curves)
[ "$n" -ge 5 ] && [ "$n" -le 20 ] || fail "automatic levels: expected 5 to 20 curves, got $n"
grep -q ' 8 0 0 0 T$' dataplot.ps || fail "labels missing"
printf 'cstep 1\n' >opts
contour -noplot -l -o opts lin.cont </dev/null || fail "contour -o opts"
[ "$(curves)" -eq 2 ] || fail "cstep 1 from the options-file: expected 2 curves, got $(curves)"
awk 'BEGIN { n = 21; print -1, 1, -1, 1; print n, n
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		x = -1 + 2 * i / (n - 1); y = -1 + 2 * j / (n - 1); print x * x + y * y } }' >par.cont
closed() { awk 'NR == 2 { nc = $1 } NR > 2 && NF == 1 { if (np) { if (fx == lx && fy == ly) c++ } np = 0; next }
	NR > 2 && NF == 2 { if (!np) { fx = $1; fy = $2 } lx = $1; ly = $2; np++ }
	END { if (np && fx == lx && fy == ly) c++; print c + 0, nc }' image.cont; }
contour -noplot -c 1.5 par.cont </dev/null || fail "contour -c 1.5"
set -- $(closed)
[ "$1" -eq 0 ] && [ "$2" -eq 4 ] || fail "level 1.5 without -j: expected 4 open curves, got $1 closed of $2"
contour -noplot -c 1.5 -j high par.cont </dev/null || fail "contour -j high"
set -- $(closed)
[ "$1" -eq "$2" ] && [ "$2" -ge 1 ] || fail "-j high: expected closed curves, got $1 closed of $2"
contour -noplot -j middle par.cont </dev/null >out.txt 2>err.txt
[ $? -eq 2 ] || fail "-j middle: expected a usage error (exit 2)"
grep -q '^contour: option -j: expected high or low' err.txt || fail "-j middle: $(head -1 err.txt)"
exit 0
