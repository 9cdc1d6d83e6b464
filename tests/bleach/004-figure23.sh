# Thesis Figures 2.3 and 4.6: on the Kodak 820 stack of Figure 2.2 (1.0 um
# on 0.0741 um oxide, examples/resists/kodak820-fig22.in), the rate along
# the centre line of the 1.25 um isolated space swings, with the standing
# waves, between about 0.009 and 0.11 um/s.  The centre of a space of
# 0.8 lambda/NA at sigma 0.5 sees nearly the clear-field intensity, so a
# clear field stands in for it.  Checked, below the surface-retarded top
# 0.3 um (3 R4):
#  - every local maximum of the rate within 0.095..0.125 um/s;
#  - the local minima within 0.004..0.02 um/s, their median within
#    0.006..0.014 ("about 0.009");
#  - successive minima lambda / (2 n) = 0.12976 um apart, within one grid
#    step (1/300 um).  (The minima, not the maxima: the rate saturates
#    at R1 = 0.1143 in the bright fringes, which leaves their peaks flat.)
. "$TOP/tests/lib/common.sh"
printf '0 1 0 1\n2 2\n1 1 1 1\n' >clear.cont
bleach -q -ascii clear.cont "$TOP/examples/resists/kodak820-fig22.in" || fail "bleach failed"
awk '
	NR == 2 { nz = $3 }
	/^rate$/ { a = 1; next }
	/^M$/ { a = 0 }
	a && NF == 2 { n++; if (n % 2 == 1) r[(n - 1) / 2] = $1 }
	END {
		T = 1.0; dz = T / (nz - 1); period = 0.436 / (2 * 1.68)
		nmax = 0; nmin = 0; bad = 0
		for (k = 1; k < nz - 1; k++) {
			depth = T - k * dz
			if (depth < 0.3) continue
			if (r[k] > r[k - 1] && r[k] >= r[k + 1]) {
				++nmax
				if (r[k] < 0.095 || r[k] > 0.125) { print "maximum " r[k] " at " depth; bad = 1 }
			}
			if (r[k] < r[k - 1] && r[k] <= r[k + 1]) {
				mins[++nmin] = r[k]; pos[nmin] = depth
				if (r[k] < 0.004 || r[k] > 0.02) { print "minimum " r[k] " at " depth; bad = 1 }
			}
		}
		if (nmax < 4 || nmin < 4) { print nmax " maxima, " nmin " minima"; bad = 1 }
		for (i = 2; i <= nmin; i++) {
			d = pos[i - 1] - pos[i]; if (d < 0) d = -d
			if (d - period > dz || period - d > dz) { print "minima " d " apart, period " period; bad = 1 }
		}
		# median of the minima
		for (i = 1; i <= nmin; i++) for (j = i + 1; j <= nmin; j++)
			if (mins[j] < mins[i]) { t = mins[i]; mins[i] = mins[j]; mins[j] = t }
		med = mins[int((nmin + 1) / 2)]
		printf "%d maxima, %d minima, median minimum %.4f um/s\n", nmax, nmin, med
		if (med < 0.006 || med > 0.014) { print "median minimum " med; bad = 1 }
		exit bad
	}' rval.3D || fail "Figure 2.3 rate swing not reproduced"
exit 0
