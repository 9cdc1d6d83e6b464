#!/bin/sh
# tests/fmm/032-tile-copy.sh - a decimation tile whose nodes all developed
# before the previous print time is copied from that set instead of
# extracted again (fmm_write_curves).  A 14 x 0.6 x 1 um rate box of
# 140 x 6 x 10 cells (two tiles, seam at x = 0) with R = 1 um/s for
# x < -0.1 and 0.1 um/s for x > 0 (linear between): the x < 0 tile is
# developed through by about 1.1 s, the other one is not by 3 s.  Checks,
# against the same surface written alone (-last: no previous set, nothing
# copied), that the t = 3 s set of -pt 1 (sets 1, 2, 3 s) has the same triangles, area,
# volume, vertices and edges (tests/lib/meshcheck stat, as text), that it
# is conforming (no bad edge, no open edge off the box), and that the
# t = 2 s and t = 3 s sets of the copied tile agree (both the substrate:
# the count of triangles with every vertex at z = -1 and x < 0 is the same
# and not zero).
. "$TOP/tests/lib/common.sh"
mk=$BUILD/tests/lib/mkrate
M=$BUILD/tests/lib/meshcheck
[ -x "$mk" ] || fail "$mk not built"
[ -x "$M" ] || fail "$M not built"
"$mk" -o r.bin 141 7 11 -7 7 -0.3 0.3 -1 0 "0.1 + 0.9*min(1, max(0, -x/0.1))" || fail "mkrate"
etch -q -et 3 -pt 1 -method fmm -o all.plot r.bin || fail "etch -pt 1"
etch -q -et 3 -last -method fmm -o last.plot r.bin || fail "etch -last"
$M stat all.plot >all.txt && $M stat last.plot >last.txt || fail "meshcheck"
[ "$(grep -c '' all.txt)" -eq 3 ] || fail "$(grep -c '' all.txt) sets, want 3 (1, 2, 3 s)"
tail -n 1 all.txt | cut -d' ' -f3- >a.txt
cut -d' ' -f3- last.txt >b.txt
same a.txt b.txt
awk '{ if ($18 != 0 || $20 != 0) { print "set " $2 ": open off the box " $18 ", bad " $20; f = 1 } }
	END { exit f }' all.txt || fail "not conforming"
# triangles of the copied tile's substrate per set: every vertex at the
# substrate (z = -1, to 1e-9 um) and x <= 0 (plot3d(5): a set opens with
# its bounds line, then its count, then each curve's count and points)
awk '/^#/ { next }
	NF == 6 { s++; n = 0; next }
	NF == 1 { n = 0; next }
	NF == 3 { z[n] = $3; x[n] = $1; n++
		if (n == 4) { ok = 1
			for (i = 0; i < 3; i++) if (z[i] > -1 + 1e-9 || x[i] > 1e-9) ok = 0
			if (ok) cnt[s]++ } }
	END { print cnt[2] + 0, cnt[3] + 0 }' all.plot >sub.txt
read -r s2 s3 <sub.txt
[ "$s2" -gt 0 ] && [ "$s2" -eq "$s3" ] || fail "substrate triangles of the x < 0 tile at 2 s and 3 s: $s2, $s3"
exit 0
