# contour -c r^2 of z = x^2 + y^2 on a 101 x 101 grid over [-1, 1]^2
# writes image.cont: for r = 0.3, 0.5, 0.8 it must hold one closed curve
# (first point = last) whose points all lie within 1% of r from the
# origin (the analytic contour is the circle of radius r; linear
# interpolation along grid edges is off by at most h^2/(8r) relative,
# well under 1%).  The picture renders in ghostscript.  The same for the
# -old format (a 50 x 50 grid, first line xmin ymin xlength ylength) at
# r = 0.5.
. "$TOP/tests/lib/common.sh"
awk 'BEGIN { n = 101; print -1, 1, -1, 1; print n, n
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		x = -1 + 2 * i / (n - 1); y = -1 + 2 * j / (n - 1); printf "%.17g\n", x * x + y * y } }' >par.cont
for r in 0.3 0.5 0.8; do
	lv=$(awk -v r=$r 'BEGIN { printf "%.17g", r * r }')
	contour -noplot -c "$lv" par.cont </dev/null || fail "contour -c $lv"
	gs_check dataplot.ps
	awk -v r=$r 'NR == 2 && $1 != 1 { print "curves: " $1; bad = 1 }
		NR == 3 { n = $1 }
		NR == 4 { fx = $1; fy = $2 }
		NR > 3 && NF == 2 { lx = $1; ly = $2; d = sqrt($1 * $1 + $2 * $2) / r - 1
			if (d < 0) d = -d; if (d > worst) worst = d; np++ }
		END { if (np + 0 != n + 0) { print "points " np " of " n; bad = 1 }
			if (fx != lx || fy != ly) { print "not closed"; bad = 1 }
			printf "r = %s: %d points, worst relative error %.2e\n", r, np, worst
			if (worst > 0.01) bad = 1; exit bad }' image.cont || fail "contour at r = $r"
done
awk 'BEGIN { n = 50; print -1, -1, 2, 2
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		x = -1 + 2 * i / (n - 1); y = -1 + 2 * j / (n - 1); printf "%.17g\n", x * x + y * y } }' >old.cont
contour -noplot -old -c 0.25 old.cont </dev/null || fail "contour -old"
awk 'NR > 3 && NF == 2 { d = sqrt($1 * $1 + $2 * $2) / 0.5 - 1; if (d < 0) d = -d
		if (d > w) w = d; n++ }
	END { printf "-old: %d points, worst %.2e\n", n, w; exit !(n > 20 && w <= 0.01) }' image.cont ||
	fail "-old: the contour is not the circle of radius 0.5"
exit 0
