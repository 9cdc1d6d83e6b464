# probe.awk - reads a contour-file (man/man5/contour.5) and answers the
# queries in -v q="QUERY; QUERY; ...", one number per line:
#   at X Y              bilinear intensity at (X, Y)
#   xwidth Y X0 T       along the row nearest Y, the length of the run of
#                       I >= T that contains X0 (edges interpolated linearly)
#   ywidth X Y0 T       the same along the column nearest X
#   max X1 X2 Y1 Y2     largest grid value in the box;  min: the smallest
#   xcentroid           intensity-weighted mean x over the grid
# Used by the splat example tests.
BEGIN { OFMT = "%.12g" }
/^#/ { next }    # comment and labels lines (contour.5)
{ for (i = 1; i <= NF; i++) v[n++] = $i }
END {
	gsub(",", " ", v[0]);
	xmin = v[0]; xmax = v[1]; ymin = v[2]; ymax = v[3]; nx = v[4]; ny = v[5];
	dx = (xmax - xmin) / (nx - 1); dy = (ymax - ymin) / (ny - 1);
	for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) z[i, j] = v[6 + j * nx + i];
	nq = split(q, qs, ";");
	for (k = 1; k <= nq; k++) {
		na = split(qs[k], a, " ");
		if (na == 0) continue;
		if (a[1] == "at") print at(a[2], a[3]);
		else if (a[1] == "xwidth") print run(0, a[2], a[3], a[4]);
		else if (a[1] == "ywidth") print run(1, a[2], a[3], a[4]);
		else if (a[1] == "max" || a[1] == "min") print ext(a[1], a[2], a[3], a[4], a[5]);
		else if (a[1] == "xcentroid") print cen();
		else { print "probe.awk: bad query " a[1] > "/dev/stderr"; exit 1 }
	}
}
function at(x, y,   fi, fj, i, j, tx, ty) {
	fi = (x - xmin) / dx; fj = (y - ymin) / dy;
	i = int(fi); j = int(fj); if (i >= nx - 1) i = nx - 2; if (j >= ny - 1) j = ny - 2;
	tx = fi - i; ty = fj - j;
	return (1 - tx) * (1 - ty) * z[i, j] + tx * (1 - ty) * z[i + 1, j] + \
	       (1 - tx) * ty * z[i, j + 1] + tx * ty * z[i + 1, j + 1];
}
function val(col, line, k) { return col ? z[line, k] : z[k, line] }
function run(col, c, p0, t,   line, n, k0, k, lo, hi, a, b) {
	if (col) { line = int((c - xmin) / dx + 0.5); n = ny; k0 = int((p0 - ymin) / dy + 0.5); a = ymin; b = dy }
	else     { line = int((c - ymin) / dy + 0.5); n = nx; k0 = int((p0 - xmin) / dx + 0.5); a = xmin; b = dx }
	if (val(col, line, k0) < t) return 0;
	for (k = k0; k > 0 && val(col, line, k - 1) >= t; k--) ;
	lo = k > 0 ? k - (val(col, line, k) - t) / (val(col, line, k) - val(col, line, k - 1)) : 0;
	for (k = k0; k < n - 1 && val(col, line, k + 1) >= t; k++) ;
	hi = k < n - 1 ? k + (val(col, line, k) - t) / (val(col, line, k) - val(col, line, k + 1)) : n - 1;
	return (hi - lo) * b;
}
function ext(op, x1, x2, y1, y2,   i, j, x, y, r, first) {
	first = 1;
	for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
		x = xmin + i * dx; y = ymin + j * dy;
		if (x < x1 - 1e-9 || x > x2 + 1e-9 || y < y1 - 1e-9 || y > y2 + 1e-9) continue;
		if (first || (op == "max" && z[i, j] > r) || (op == "min" && z[i, j] < r)) r = z[i, j];
		first = 0;
	}
	return r;
}
function cen(   i, j, s, sx) {
	for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) { s += z[i, j]; sx += z[i, j] * (xmin + i * dx) }
	return sx / s;
}
