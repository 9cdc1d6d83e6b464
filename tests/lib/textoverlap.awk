# textoverlap.awk - test tool: reads an SVG written by our drawing back
# end (one <text> element a line) and prints every pair of texts on the
# same picture whose boxes overlap; exits 1 if there is one.  Widths come
# from Helvetica's font metrics (the Adobe AFM advance widths, in 1/1000
# em, for the characters labels use; 0.6 em for any other), heights are
# the font size (cap height plus descender, rounded up), so the check is
# independent of the estimate the plot programs use to place labels.
# Rotation by any angle is taken into account through the rotated box's
# axis-aligned extent.  The SVG stacks its pages one under the other, so
# texts of different pages never meet.
function adv(c) {
	if (c ~ /[0-9]/) return 556
	if (c == "-") return 333
	if (c == "." || c == " " || c == ",") return 278
	if (c == "(" || c == ")") return 333
	if (c == "+") return 584
	if (c == "=") return 584
	if (c == "e" || c == "u" || c == "n" || c == "s" || c == "a" || c == "o") return 556
	if (c == "m") return 833
	if (c == "t" || c == "f") return 278
	if (c == "i" || c == "l") return 222
	if (c == "x" || c == "y" || c == "z") return 500
	return 600
}
function attr(s, name,    r) {
	if (match(s, name "=\"[^\"]*\"")) {
		r = substr(s, RSTART + length(name) + 2, RLENGTH - length(name) - 3)
		return r
	}
	return ""
}
/<text/ {
	x = attr($0, "x") + 0; y = attr($0, "y") + 0; size = attr($0, "font-size") + 0
	anchor = attr($0, "text-anchor"); tr = attr($0, "transform")
	s = $0; sub(/^.*<text[^>]*>/, "", s); sub(/<\/text>.*$/, "", s)
	gsub(/&lt;/, "<", s); gsub(/&gt;/, ">", s); gsub(/&amp;/, "\\&", s)
	w = 0
	for (i = 1; i <= length(s); i++) w += adv(substr(s, i, 1))
	w = w * size / 1000; h = size
	dy = 0; ang = 0
	if (match(tr, /rotate\([-0-9.e]+/)) ang = substr(tr, RSTART + 7, RLENGTH - 7) + 0
	if (match(tr, /translate\(0 [-0-9.e]+/)) dy = substr(tr, RSTART + 12, RLENGTH - 12) + 0
	# box in the text's own frame: baseline at y + dy (SVG y grows down)
	if (anchor == "middle") { x0 = -w / 2 } else if (anchor == "end") { x0 = -w } else { x0 = 0 }
	x1 = x0 + w; by = dy; y0 = by - 0.72 * size; y1 = by + 0.22 * size
	a = ang * 3.14159265358979 / 180; ca = cos(a); sa = sin(a)
	lx = 1e30; ly = 1e30; hx = -1e30; hy = -1e30
	for (k = 0; k < 4; k++) {
		px = (k % 2) ? x1 : x0; py = (k < 2) ? y0 : y1
		qx = x + px * ca - py * sa; qy = y + px * sa + py * ca
		if (qx < lx) lx = qx; if (qx > hx) hx = qx
		if (qy < ly) ly = qy; if (qy > hy) hy = qy
	}
	n++; LX[n] = lx; LY[n] = ly; HX[n] = hx; HY[n] = hy; S[n] = s
}
END {
	bad = 0
	for (i = 1; i <= n; i++)
		for (j = i + 1; j <= n; j++)
			if (LX[i] < HX[j] && LX[j] < HX[i] && LY[i] < HY[j] && LY[j] < HY[i]) {
				printf "overlap: \"%s\" and \"%s\"\n", S[i], S[j]
				bad = 1
			}
	exit bad
}
