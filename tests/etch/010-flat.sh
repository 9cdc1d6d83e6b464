#!/bin/sh
# etch: uniform rate 1 um/s from the flat top, resist 1 um thick.
# Checks against the exact answer: at every print time t before the
# substrate every node is at depth R t within 1e-6 um (the front stays
# flat: x and y untouched), at 1.5 s every node has stopped on the
# substrate z = -1, and the mesh checker is clean after every step
# (-check).  Also: two runs give byte-identical outputs (determinism),
# ASCII and binary rate files give identical outputs (told apart by
# content, not name), and curves.plot.2D projects the same triangles.
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
[ -x "$MKRATE" ] || fail "mkrate not built"
$MKRATE -o rate.bin 11 9 21 -1 1 -0.8 0.8 -1 0 1 || fail "mkrate"
$MKRATE -ascii -o rate.txt 11 9 21 -1 1 -0.8 0.8 -1 0 1 || fail "mkrate"
etch -et 1.5 -pt 0.25 -seg 0.1 -check -q rate.bin || fail "etch failed"
# sets at 0.25 0.5 0.75 1 1.25 1.5 s: depth min(t, 1)
awk -v tol=1e-6 '
	BEGIN { set = 0; need = 0 }
	need == 0 && NF == 6 { set++; t = set * 0.25; want = t < 1 ? -t : -1; need = -1; next }
	need == -1 { nc = $1; need = nc * 5; ncur = nc; next }
	need > 0 { need--; if (NF == 3) { n++; d = $3 - want; if (d < 0) d = -d;
		if (d > tol) { print "set " set ": z " $3 " not " want; bad = 1; exit 1 } } }
	END { if (set != 6) { print "expected 6 sets, got " set; exit 1 } if (bad) exit 1 }
' curves.plot || fail "front not at depth R t"
cp curves.plot first.plot
cp curves.plot.2D first.plot.2D
etch -et 1.5 -pt 0.25 -seg 0.1 -q rate.bin || fail "second run"
same first.plot curves.plot
same first.plot.2D curves.plot.2D
etch -et 1.5 -pt 0.25 -seg 0.1 -q rate.txt || fail "ASCII run"
same first.plot curves.plot
# the 2D file holds the x y of the 3D file's points, set by set
# (each file's '#' labels line aside: plot3d(5), plot2d(5))
awk '/^#/ { next } NF == 3 { print $1, $2 } NF == 6 { print $1, $2, $3, $4 } NF <= 1 { print }' first.plot >proj.txt
grep -v '^#' first.plot.2D >first2.txt
same proj.txt first2.txt
exit 0
