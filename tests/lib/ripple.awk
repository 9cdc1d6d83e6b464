# ripple.awk: from a curves.cut (2D plot file), the last set's right-hand wall of a
# contact: points with x > 0 and zlo < z < zhi of the curve with most such points;
# prints the excess total variation of x along the wall, sum |dx| - |x_last - x_first|
# (um; 0 for a monotone wall) and the number of wall points used.
/^#/ { next }            # the labels line (plot2d(5))
NF == 0 { set++; n = 0; next }
{ line[set, ++n] = $0 }
END {
	# parse the last set: bounds, ncurves, then curves
	k = 1; split(line[set, k++], b); nc = line[set, k++]
	best = 0
	for (c = 0; c < nc; c++) {
		np = line[set, k++]; tv = 0; first = ""; m = 0
		for (i = 0; i < np; i++) {
			split(line[set, k++], p)
			if (p[1] > 0 && p[2] > zlo && p[2] < zhi) {
				if (m > 0) { d = p[1] - px; tv += d < 0 ? -d : d }
				if (m == 0) x0 = p[1]
				px = p[1]; m++
			}
		}
		if (m > 1) { net = px - x0; if (net < 0) net = -net; r = tv - net; if (m > best) { best = m; res = r } }
	}
	printf "%.6f %d\n", res, best
}
