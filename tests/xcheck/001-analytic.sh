# Cross-check of etch's two engines on analytic rate fields without loops:
# the vertices of the ray-string surface against the fast-marching surface
# T = t (tests/etch/fmm_exact xcheck: fmm_distance_stats).  Pass: median
# distance under half a rate-grid z cell, 95th percentile under two cells,
# once the fast-marching solve is refined in z until it has converged.
# On the 10:1 standing-wave column the plain solve must pass too: its
# differences stand for the slowness integrated over the cells (fmm.c),
# measured 0.074 cells (with the node's own slowness, the published
# scheme, it was 1.27 cells off; x4 0.17, x16 0.011).
. "$TOP/tests/lib/common.sh"
MK=$BUILD/tests/lib/mkrate
X=$BUILD/tests/etch/fmm_exact
ok() { # ok LINE: "... median M um (C cells), 95% P um (Q cells)" within limits
	echo "$1"
	echo "$1" | awk '{ for (i = 1; i <= NF; i++) if ($i ~ /^\([0-9.]/) c[n++] = substr($i, 2) }
		END { exit !(c[0] + 0 < 0.5 && c[1] + 0 < 2) }' || fail "engines disagree: $1"
}
# 1. z only, 10:1 standing waves (period 0.13 um, as a resist)
$MK -o z.bin 11 11 101 -1 1 -1 1 -1 0 '0.05+0.045*sin(2*pi*z/0.13)' || fail "mkrate"
etch -q -et 10 -pt 5 z.bin || fail "etch (z only)"
plain=$($X xcheck z.bin curves.plot 1 5 10 | tail -n 1)
ok "plain: $plain"
$X xcheck z.bin curves.plot 16 5 10 >z16.txt || fail "xcheck z x16"
while read -r line; do ok "$line"; done <z16.txt
# 2. thesis Figure 8.7's ridge R = exp(-4 x^2)(1.05 - cos(2 pi z)), 1.5 s
$MK -o r.bin 41 11 101 -1 1 -0.25 0.25 -1 0 'exp(-4*x^2)*(1.05-cos(2*pi*z))' || fail "mkrate"
etch -q -et 1.5 -pt 0.5 -seg 0.05 r.bin || fail "etch (ridge)"
$X xcheck r.bin curves.plot 4 0.5 1 1.5 >r4.txt || fail "xcheck ridge"
while read -r line; do ok "$line"; done <r4.txt
exit 0
