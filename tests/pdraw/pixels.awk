# pixels.awk - reads ghostscript's plain PGM (gs -sDEVICE=pgm -r72, one
# pixel per PostScript point) for the plot tests.
#   awk -v mode=query -f pixels.awk QUERIES IMAGE.pgm
#       QUERIES: lines "x y" in points (origin bottom left); prints for
#       each the darkest gray (0 black .. 255 white) within one pixel, so a
#       1-point line is found despite rounding.
#   awk -v mode=diff -f pixels.awk A.pgm B.pgm
#       prints "darkA darkB onlyA onlyB": dark (< 128) pixel counts, and
#       dark pixels of one image with no dark pixel within one pixel in
#       the other.
function load(img,    line, n, i, a, tok) {
	tok = 0
	while ((getline line < img) > 0) {
		if (line ~ /^#/) continue
		n = split(line, a)
		for (i = 1; i <= n; i++) {
			tok++
			if (tok == 1) continue
			if (tok == 2) { W[img] = a[i]; continue }
			if (tok == 3) { H[img] = a[i]; continue }
			if (tok == 4) continue
			P[img, tok - 5] = a[i]
		}
	}
	close(img)
}
function at(img, c, r) {
	if (c < 0 || r < 0 || c >= W[img] || r >= H[img]) return 255
	return P[img, r * W[img] + c] + 0
}
function near_min(img, c, r,    m, dc, dr, v) {
	m = 255
	for (dr = -1; dr <= 1; dr++)
		for (dc = -1; dc <= 1; dc++) {
			v = at(img, c + dc, r + dr)
			if (v < m) m = v
		}
	return m
}
BEGIN {
	if (mode == "query") {
		nq = 0
		while ((getline line < ARGV[1]) > 0) {
			split(line, a)
			qx[++nq] = a[1]; qy[nq] = a[2]
		}
		load(ARGV[2])
		img = ARGV[2]
		for (i = 1; i <= nq; i++)
			print near_min(img, int(qx[i]), H[img] - 1 - int(qy[i]))
	} else if (mode == "diff") {
		A = ARGV[1]; B = ARGV[2]
		load(A); load(B)
		da = db = oa = ob = 0
		for (r = 0; r < H[A]; r++)
			for (c = 0; c < W[A]; c++) {
				va = at(A, c, r); vb = at(B, c, r)
				if (va < 128) { da++; if (near_min(B, c, r) >= 128) oa++ }
				if (vb < 128) { db++; if (near_min(A, c, r) >= 128) ob++ }
			}
		print da, db, oa, ob
	}
	exit 0
}
