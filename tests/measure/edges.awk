# tests/measure/edges.awk - the roughness figures of known edges, computed
# independently of measure from the definitions of measure(1), ROUGHNESS,
# for the roughness tests.  Not a test itself (the runner takes only *.sh).
#
#   awk -v at=rows|sub|mid -v n=N -f edges.awk truth.txt
#
# truth.txt: "y left right" per mesh row, rows 0 .. M, the edges straight
# between rows, the last row the first again (roughsurf's truth file).
# The edges are read at:
#   rows  the rows 0 .. M-1;
#   sub   n lines evenly spaced from row 0 (every row divided into n/M);
#   mid   the middles of n equal parts of y0 .. yM.
# Prints "ler_left ler_right lwr corr_length" in um: 3 x the population
# sigma of each edge and of the width, and the mean over the two edges of
# the first 1/e crossing of the periodic autocorrelation
# R(k) = sum_j d_j d_(j+k mod n) / sum_j d_j^2, interpolated linearly
# between lags (-1 if an edge never falls below 1/e).
{ Y[NR - 1] = $1; L[NR - 1] = $2; R[NR - 1] = $3 }
# the edge e (L or R) at y, straight between rows
function at_y(y, e,   a, b, m, f) {
	a = 0; b = NR - 1
	while (b - a > 1) { m = int((a + b) / 2); if (Y[m] <= y) a = m; else b = m }
	f = (y - Y[a]) / (Y[b] - Y[a])
	return e == "L" ? L[a] + f * (L[b] - L[a]) : R[a] + f * (R[b] - R[a])
}
function sigma(v, n,   j, m, s) {
	m = 0; for (j = 0; j < n; j++) m += v[j]; m /= n
	s = 0; for (j = 0; j < n; j++) { D[j] = v[j] - m; s += D[j] * D[j] }
	return sqrt(s / n)
}
# correlation length of v (n values dl apart), from D after sigma()
function corr(v, n, dl,   j, k, s0, a, b, e, s) {
	sigma(v, n)
	s0 = 0; for (j = 0; j < n; j++) s0 += D[j] * D[j]
	e = exp(-1); a = 1
	for (k = 1; k <= n / 2; k++) {
		s = 0; for (j = 0; j < n; j++) s += D[j] * D[(j + k) % n]
		b = s / s0
		if (b < e) return (k - 1 + (a - e) / (a - b)) * dl
		a = b
	}
	return -1
}
END {
	M = NR - 1; len = Y[M] - Y[0]
	if (at == "rows") n = M
	for (j = 0; j < n; j++) {
		if (at == "rows") { l[j] = L[j]; r[j] = R[j]; continue }
		y = at == "sub" ? Y[0] + j * len / n : Y[0] + (j + 0.5) * len / n
		l[j] = at_y(y, "L"); r[j] = at_y(y, "R")
	}
	for (j = 0; j < n; j++) w[j] = r[j] - l[j]
	cl = corr(l, n, len / n); cr = corr(r, n, len / n)
	printf "%.9g %.9g %.9g %.9g\n", 3 * sigma(l, n), 3 * sigma(r, n), 3 * sigma(w, n),
		(cl < 0 || cr < 0) ? -1 : 0.5 * (cl + cr)
}
