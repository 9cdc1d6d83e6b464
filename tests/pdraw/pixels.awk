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
# Only the pixels that are not white (255) are kept: a plot is mostly
# white page, and a row of white is counted, not split (the pixel loop in
# awk was nearly all of a pixel test's time); a pixel not kept is white.
# The dark ones (< 128), in reading order, are listed in D[img, k].
function load(img,    line, n, i, a, tok, v) {
	tok = 0
	N[img] = 0
	while ((getline line < img) > 0) {
		if (line ~ /^#/) continue
		if (tok >= 4 && line ~ /^[ \t]*255([ \t]+255)*[ \t]*$/) {
			tok += gsub(/255/, "", line)
			continue
		}
		n = split(line, a)
		for (i = 1; i <= n; i++) {
			tok++
			if (tok == 1) continue
			if (tok == 2) { W[img] = a[i]; continue }
			if (tok == 3) { H[img] = a[i]; continue }
			if (tok == 4) continue
			v = a[i] + 0
			if (v == 255) continue
			P[img, tok - 5] = v
			if (v < 128) D[img, ++N[img]] = tok - 5
		}
	}
	close(img)
}
function at(img, c, r,    k) {
	if (c < 0 || r < 0 || c >= W[img] || r >= H[img]) return 255
	k = r * W[img] + c
	return (img, k) in P ? P[img, k] : 255
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
# dark IMG BOUND OTHER: the dark pixels of IMG inside BOUND's size
# ("ndark"), and how many of them have no dark pixel within one pixel in
# OTHER ("nonly")
function dark(img, bound, other,    k, i, c, r) {
	ndark = nonly = 0
	for (k = 1; k <= N[img]; k++) {
		i = D[img, k]
		c = i % W[img]; r = int(i / W[img])
		if (c >= W[bound] || r >= H[bound]) continue
		ndark++
		if (near_min(other, c, r) >= 128) nonly++
	}
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
		# every pixel of A's size, as a scan of A's rows would count them
		dark(A, A, B); da = ndark; oa = nonly
		dark(B, A, A); db = ndark; ob = nonly
		print da, db, oa, ob
	}
	exit 0
}
