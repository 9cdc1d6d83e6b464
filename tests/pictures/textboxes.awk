# textboxes.awk - the texts of our PostScript (draw_ps.c's "(s) x y size
# angle halign valign T" lines) and their boxes on the page, from
# Helvetica's advance widths (per 1000 of the size, the AFM's; an unknown
# character counts as 667, a capital's) with the prolog's alignment: the
# baseline 0.72 size (va + 1) / 2 below y, the box from 0.21 size below
# the baseline (descenders) to 0.72 above (capitals).
#   awk -v mode=overlap -f textboxes.awk FILE.ps: prints each pair of
#     texts of a page whose boxes overlap by more than SLACK points each
#     way, exits 1 if there is one;
#   awk -v mode=texts -f textboxes.awk FILE.ps: prints "page<TAB>text" for
#     every text.
BEGIN {
	SLACK = 0.5
	w["0"] = w["1"] = w["2"] = w["3"] = w["4"] = w["5"] = w["6"] = w["7"] = w["8"] = w["9"] = 556
	w[" "] = w["."] = w[","] = w[":"] = w["/"] = w["f"] = w["t"] = 278
	w["-"] = w["("] = w[")"] = w["r"] = 333
	w["="] = w["+"] = 584; w["i"] = w["j"] = w["l"] = 222
	w["m"] = 833; w["w"] = 722; w["I"] = 278; w["M"] = 833; w["W"] = 944
	split("a b d e g h n o p q u", s5, " "); for (k in s5) w[s5[k]] = 556
	split("c k s v x y z", s4, " "); for (k in s4) w[s4[k]] = 500
	page = 0; n = 0; bad = 0
}
/^%%Page: / { page = $2 }
/ T$/ && /^\(/ {
	# the string: up to the last ")" not escaped
	line = $0
	e = 0
	for (i = 2; i <= length(line); i++) {
		ch = substr(line, i, 1)
		if (ch == "\\") { i++; continue }
		if (ch == ")") e = i
	}
	str = substr(line, 2, e - 2)
	gsub(/\\\(/, "(", str); gsub(/\\\)/, ")", str); gsub(/\\\\/, "\\", str)
	split(substr(line, e + 1), f, " ")
	x = f[1]; y = f[2]; sz = f[3]; an = f[4]; ha = f[5]; va = f[6]
	if (mode == "texts") { printf "%d\t%s\n", page, str; next }
	W = 0
	for (i = 1; i <= length(str); i++) {
		ch = substr(str, i, 1)
		W += (ch in w ? w[ch] : 667) * sz / 1000
	}
	lx0 = -W * (ha + 1) / 2; lx1 = lx0 + W
	yb = -sz * 0.72 * (va + 1) / 2
	ly0 = yb - 0.21 * sz; ly1 = yb + 0.72 * sz
	c = cos(an * 3.141592653589793 / 180); s = sin(an * 3.141592653589793 / 180)
	X0 = Y0 = 1e30; X1 = Y1 = -1e30
	for (k = 0; k < 4; k++) {
		px = k % 2 ? lx1 : lx0; py = k < 2 ? ly0 : ly1
		qx = x + c * px - s * py; qy = y + s * px + c * py
		if (qx < X0) X0 = qx; if (qx > X1) X1 = qx
		if (qy < Y0) Y0 = qy; if (qy > Y1) Y1 = qy
	}
	for (j = 0; j < n; j++)
		if (pg[j] == page && X0 + SLACK < bx1[j] && bx0[j] + SLACK < X1 &&
		    Y0 + SLACK < by1[j] && by0[j] + SLACK < Y1) {
			printf "page %d: \"%s\" overlaps \"%s\"\n", page, str, txt[j]
			bad = 1
		}
	pg[n] = page; txt[n] = str; bx0[n] = X0; bx1[n] = X1; by0[n] = Y0; by1[n] = Y1; n++
}
END { if (mode != "texts") exit bad }
