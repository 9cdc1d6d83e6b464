#!/bin/sh
# etch: uniform rate 1 um/s from the flat top, resist 1 um thick.
# Checks against the exact answer: at every print time t before the
# substrate every node is at depth R t within 1e-6 um and the front stays
# flat (every set has triangles; x and y of every point untouched: the
# same as in the first set, which spans the box), at 1.5 s every node has stopped on the
# substrate z = -1, and the mesh checker is clean after every step
# (-check).  Also: two runs give byte-identical outputs (determinism),
# ASCII and binary rate files give identical outputs (told apart by
# content, not name), and curves.plot.2D projects the same triangles.
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
$MKRATE -o rate.bin 11 9 21 -1 1 -0.8 0.8 -1 0 1 || fail "mkrate"
$MKRATE -ascii -o rate.txt 11 9 21 -1 1 -0.8 0.8 -1 0 1 || fail "mkrate"
etch -et 1.5 -pt 0.25 -seg 0.1 -check -q rate.bin || fail "etch failed"
# sets at 0.25 0.5 0.75 1 1.25 1.5 s: depth min(t, 1); every set has
# triangles, the same number of points as the first, and each point's x y
# exactly those of the same point in the first set (the nodes move straight
# down), which spans the whole box (x -1 to 1, y -0.8 to 0.8)
awk -v tol=1e-6 '
	function bad_(msg) { print msg; bad = 1; exit 1 }
	/^#/ { next }
	BEGIN { set = 0; need = 0 }
	need == 0 && NF == 6 { set++; t = set * 0.25; want = t < 1 ? -t : -1; need = -1; k = 0; next }
	need == -1 { nc = $1; if (nc < 1) bad_("set " set ": no triangles"); need = nc * 5; next }
	need > 0 { need--; if (NF == 3) { n++; d = $3 - want; if (d < 0) d = -d;
		if (d > tol) bad_("set " set ": z " $3 " not " want)
		k++; np[set] = k
		if (set == 1) {
			xy[k] = $1 " " $2
			if (k == 1 || $1 < x0) x0 = $1; if (k == 1 || $1 > x1) x1 = $1
			if (k == 1 || $2 < y0) y0 = $2; if (k == 1 || $2 > y1) y1 = $2
		} else if (xy[k] != $1 " " $2)
			bad_("set " set ": point " k " moved sideways to " $1 " " $2 " from " xy[k]) } }
	END { if (bad) exit 1
		if (set != 6) { print "expected 6 sets, got " set; exit 1 }
		for (s = 2; s <= 6; s++) if (np[s] != np[1]) { print "set " s ": " np[s] " points, the first " np[1]; exit 1 }
		if (x0 != -1 || x1 != 1 || y0 != -0.8 || y1 != 0.8) {
			print "the front spans x " x0 " to " x1 ", y " y0 " to " y1 ", not the box"; exit 1 }
	}
' curves.plot || fail "front not at depth R t, or moved sideways"
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
