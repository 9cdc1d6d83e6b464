# contour draws an image stack (stack(5)) one page per plane: a stack of
# three paraboloids z_k = (x^2 + y^2) / s_k (s = 1, 2, 4) on [-1, 1]^2 at
# 101 x 101 points, contoured at 0.16 with -c, must give image.cont with
# one set per plane, each one closed curve within 1% of the analytic
# circle of radius sqrt(0.16 s_k) (0.4, 0.566, 0.8); the picture has three
# pages, each labelled with its plane's depth, and renders in ghostscript;
# the levels are shared by all pages; -ex refuses a stack in one line.
. "$TOP/tests/lib/common.sh"
{ echo "stack planes 3 thickness 1 index 1.6"
  for k in 0 1 2; do
	echo "depth $(awk -v k=$k 'BEGIN { print k / 2 }')"
	awk -v s=$((1 << k)) 'BEGIN { n = 101; print -1, 1, -1, 1; print n, n
		for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
			x = -1 + 2 * i / (n - 1); y = -1 + 2 * j / (n - 1); printf "%.17g\n", (x * x + y * y) / s } }'
  done; } >par.stack
contour -noplot -c 0.16 par.stack </dev/null || fail "contour -c on a stack"
gs_check dataplot.ps
[ "$(grep -c '^showpage' dataplot.ps)" -eq 3 ] || [ "$(grep -c 'showpage' dataplot.ps)" -eq 3 ] ||
	fail "expected 3 pages, found $(grep -c showpage dataplot.ps)"
for d in 0 0.5 1; do
	grep -aq "depth $d um" dataplot.ps || fail "no page labelled depth $d um"
done
awk 'BEGIN { r[0] = 0.4; r[1] = sqrt(0.32); r[2] = 0.8; set = -1 }
	NF == 4 { set++; st = 1; next }
	st == 1 { if ($1 != 1) { print "set " set ": " $1 " curves"; bad = 1 } st = 2; next }
	st == 2 { st = 3; next }
	NF == 2 { d = sqrt($1 * $1 + $2 * $2) / r[set] - 1; if (d < 0) d = -d
		if (d > w) w = d; n[set]++ }
	END { if (set != 2) { print "sets: " set + 1; bad = 1 }
		printf "3 pages, worst relative error %.2e\n", w
		if (!(w <= 0.01) || !n[0] || !n[1] || !n[2]) bad = 1; exit bad }' image.cont ||
	fail "the contours of the stack's planes are not the circles"
expect_error contour -noplot -ex -cstep 0.1 par.stack
exit 0
