# The negative chemically amplified resist (thesis 9.3.2, Figure 9.26):
# 0.4 um lines and spaces at 0.248 um, the example's parameters
# (examples/resists/ca-negative.in).  The exposed (bright) regions
# crosslink and stay; the lines must be narrower near the substrate than
# at the top ("necking").  The image is the fundamental of the grating,
# I = 0.5 + 0.45 cos(2 pi x / 0.8), which is all an NA 0.42 lens passes
# well at this pitch.  Line width is measured as the length of x where the
# rate is below 0.005 um/s (the rate that removes 0.6 um in the 120 s
# development); the mean width over the top 0.2 um must exceed the mean
# over the bottom 0.2 um by at least 0.04 um, and the line must stand
# (width > 0.2 um at the top), and the spaces must clear (rate at the
# space centre above 0.01 um/s at every depth).
. "$TOP/tests/lib/common.sh"
awk 'BEGIN { n = 81; print "-0.4 0.4 0 0.1"; print n, 2
	for (j = 0; j < 2; j++) for (i = 0; i < n; i++) {
		x = -0.4 + 0.8 * i / (n - 1)
		printf "%.12g\n", 0.5 + 0.45 * cos(2 * 3.141592653589793 * x / 0.8) } }' >ls.cont
bleach -q -ascii ls.cont "$TOP/examples/resists/ca-negative.in" || fail "bleach failed"
awk '
	NR == 2 { nz = $3 }
	/^rate$/ { a = 1; next }
	/^M$/ { a = 0 }
	a && NF > 2 { row++
		if ((row - 1) % 2 == 0) {
			k = (row - 1) / 2; c = 0
			for (i = 1; i <= NF; i++) if ($i < 0.005) c++
			w[k] = c * 0.01
			if ($1 < 0.01) { print "space does not clear at plane " k ": " $1; bad = 1 }
		} }
	END {
		T = 1.0; dz = T / (nz - 1)
		for (k = 0; k < nz; k++) {
			depth = T - k * dz
			if (depth < 0.2) { top += w[k]; nt++ }
			if (depth > T - 0.2) { bot += w[k]; nb++ }
		}
		top /= nt; bot /= nb
		printf "line width: top %.3f um, bottom %.3f um\n", top, bot
		if (top < 0.2) { print "no line"; bad = 1 }
		if (top - bot < 0.04) { print "no necking"; bad = 1 }
		exit bad
	}' rval.3D || fail "necking not reproduced"
exit 0
