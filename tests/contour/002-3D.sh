# contour -3D contours a pdraw triangle file; -ex writes the triangle mesh.
# The mesh of -ex must be byte-identical to conv -t's (an independent
# writer of the same mesh), and contouring it with -3D -c 0.25 must give
# the circle of radius 0.5 within 1%, as on the grid.  A curve that is not
# a triangle is an error naming the file and a line.
. "$TOP/tests/lib/common.sh"
awk 'BEGIN { n = 41; print -1, 1, -1, 1; print n, n
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		x = -1 + 2 * i / (n - 1); y = -1 + 2 * j / (n - 1); printf "%.17g\n", x * x + y * y } }' >par.cont
contour -noplot -ex -cstep 0.2 par.cont </dev/null || fail "contour -ex"
[ -s par.cont.3D ] || fail "-ex wrote no par.cont.3D"
conv -t -o conv.3D par.cont || fail "conv -t"
same par.cont.3D conv.3D
contour -noplot -3D -c 0.25 par.cont.3D </dev/null || fail "contour -3D"
gs_check dataplot.ps
awk 'NR > 3 && NF == 2 { d = sqrt($1 * $1 + $2 * $2) / 0.5 - 1; if (d < 0) d = -d
		if (d > w) w = d; n++ }
	END { printf "%d points, worst %.2e\n", n, w; exit !(n > 20 && w <= 0.01) }' image.cont ||
	fail "-3D contour is not the circle of radius 0.5"
printf '0 1 0 1 0 1\n1\n5\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 0\n' >quad.3D
expect_file_error contour quad.3D -noplot -3D quad.3D
exit 0
