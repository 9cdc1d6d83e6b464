#!/bin/sh
# etch: a radially symmetric rate with standing waves, R = exp(-4(x^2 +
# y^2))(1.05 - cos(8 pi z)) (thesis Figure 6.20's function), 1.5 s.
# Loops form at the standing-wave fingers (thesis 7.5.4, 8.5): the run
# must finish (within 60 s) with the mesh checker clean after every step
# (-check) and -deloop accepted.  Symmetry, against the problem's own
# symmetry: the profile cut by x = 0 (as y, z) matches the one cut by
# y = 0 (as x, z), and each matches itself mirrored.  Distances from each
# cut point to the other polyline: the median within MED_TOL of S_ideal,
# the largest within MAX_TOL (near loop cusps, where rays cross, merges
# that are not commutative (thesis 8.4.1.2) and chords between distant
# nodes make the cuts differ most).
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
SEG=0.0666667
MED_TOL=0.01
MAX_TOL=0.3
$MKRATE -o rate.bin 41 41 151 -1 1 -1 1 -1.5 0 'exp(-4*(x^2+y^2))*(1.05-cos(8*pi*z))' || fail "mkrate"
timeout 60 etch -et 1.5 -pt 0.5 -check -deloop -q -cut x 0 -o cx.plot rate.bin || fail "etch -cut x failed"
timeout 60 etch -et 1.5 -pt 0.5 -check -q -cut y 0 -o cy.plot rate.bin || fail "etch -cut y failed"
n=$(awk 'NF == 4' cx.cut | wc -l)
[ "$n" -eq 3 ] || fail "cx.cut has $n sets, expected 3"
# compare the last sets: distance of every point of A to polyline B
cmpcut() { # A B mirror
	awk -v mir="$3" '
	FNR == 1 { file++; set = 0 }
	NF == 4 { set++; np[file, set] = 0; nc[file, set] = 0; hdr = 1; next }
	NF == 1 { if (hdr) { hdr = 0; next }            # the curve count
		  nc[file, set]++; next }                  # a point count
	NF == 2 { k = ++np[file, set]; X[file, set, k] = (file == 1 && mir) ? -$1 : $1
		  Z[file, set, k] = $2; C[file, set, k] = nc[file, set]; next }
	END {
		for (s = 1; (1, s) in np; s++) sa = s
		for (s = 1; (2, s) in np; s++) sb = s
		m = 0; n = 0
		for (i = 1; i <= np[1, sa]; i++) {
			best = 1e9
			for (j = 1; j < np[2, sb]; j++) {
				if (C[2, sb, j] != C[2, sb, j + 1]) continue
				ax = X[2, sb, j]; az = Z[2, sb, j]; dx = X[2, sb, j + 1] - ax; dz = Z[2, sb, j + 1] - az
				L = dx * dx + dz * dz; t = L > 0 ? ((X[1, sa, i] - ax) * dx + (Z[1, sa, i] - az) * dz) / L : 0
				if (t < 0) t = 0; if (t > 1) t = 1
				ex = X[1, sa, i] - ax - t * dx; ez = Z[1, sa, i] - az - t * dz; d = sqrt(ex * ex + ez * ez)
				if (d < best) best = d
			}
			d_[++n] = best; if (best > m) m = best
		}
		# median by selection (n is small)
		for (i = 1; i <= n; i++) { below = 0; for (j = 1; j <= n; j++) if (d_[j] < d_[i]) below++
			if (below <= n / 2 && (med == "" || d_[i] > med)) med = d_[i] }
		printf "%d points, median %.3g, max %.3g\n", n, med, m
	}' "$1" "$2"
}
check() { # label, output of cmpcut
	echo "$1: $2"
	med=$(echo "$2" | awk '{ print $4 }' | tr -d ,)
	max=$(echo "$2" | awk '{ print $6 }')
	awk -v m="$med" -v s=$SEG -v t=$MED_TOL 'BEGIN { exit !(m <= t * s) }' || fail "$1: median $med over $MED_TOL S"
	awk -v m="$max" -v s=$SEG -v t=$MAX_TOL 'BEGIN { exit !(m <= t * s) }' || fail "$1: max $max over $MAX_TOL S"
}
check "x = 0 cut vs y = 0 cut" "$(cmpcut cx.cut cy.cut 0)"
check "y = 0 cut vs its mirror" "$(cmpcut cy.cut cy.cut 1)"
check "x = 0 cut vs its mirror" "$(cmpcut cx.cut cx.cut 1)"
exit 0
