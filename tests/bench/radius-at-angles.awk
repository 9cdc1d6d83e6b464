# radius / t of the first set's profile along rays from the origin at 0, 22.5, 45, 67.5 and 90
# degrees from straight down (etch2d bench: the octagon of Dill's cells, thesis Figure 3.3)
NF == 4 { set++; next }
NF == 1 { np = 0; next }
NF == 2 && set == 1 { x[np] = $1; z[np] = $2; if (np > 0) { n++; ax[n] = x[np-1]; az[n] = z[np-1]; bx[n] = $1; bz[n] = $2 } np++ }
END {
	split("0 22.5 45 67.5 90", A, " ")
	for (q = 1; q <= 5; q++) {
		th = A[q] * atan2(1, 1) / 45; dx = sin(th); dz = -cos(th); best = 0
		for (i = 1; i <= n; i++) {
			# solve a + u (b - a) = s (dx, dz)
			ex = bx[i] - ax[i]; ez = bz[i] - az[i]; den = ex * dz - ez * dx
			if (den == 0) continue
			u = (ax[i] * dz - az[i] * dx) / -den; s = (ax[i] * ez - az[i] * ex) / -den
			if (u >= 0 && u <= 1 && s > best) best = s
		}
		printf "%s:%.4f ", A[q], best / t
	}
	printf "\n"
}
