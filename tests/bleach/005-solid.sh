# -solid writes mxyz.solid.3D, the surface M = level (Figure 8.15): a
# pdraw file of one set whose curves are all closed triangles (4 points,
# last = first), inside the rate file's bounds, with as many curves as
# the set header promises; -m moves the surface (a lower level encloses
# less exposed resist, so fewer triangles here); pdraw -h -nosort reads
# it when pdraw is built.  Watertightness is checked by
# tests/bleach/solid.c.
. "$TOP/tests/lib/common.sh"
awk 'BEGIN { n = 21; print "-1 1 -1 1"; print n, n
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		x = -1 + 2 * i / (n - 1); y = -1 + 2 * j / (n - 1)
		printf "%.12g\n", 0.02 + 0.9 * exp(-(x * x + y * y) / 0.2) } }' >spot.cont
sed 's/^grid .*/grid nz 60/' "$TOP/examples/resists/olinhunt6512.in" >o.in
bleach -q -solid spot.cont o.in || fail "bleach -solid failed"
[ -s mxyz.solid.3D ] || fail "no mxyz.solid.3D"
check() {
	grep -v '^#' "$1" | awk '
		NR == 1 { for (i = 1; i <= 6; i++) b[i] = $i; next }
		NR == 2 { ncurves = $1; next }
		NF == 1 { if (np && np != 4) { print "curve of " np " points"; exit 1 } np = $1; got++; i = 0; next }
		NF == 3 { i++
			for (d = 0; d < 3; d++) if ($(d + 1) < b[2 * d + 1] - 1e-9 || $(d + 1) > b[2 * d + 2] + 1e-9) { print "outside: " $0; exit 1 }
			if (i == 1) f = $0; if (i == 4 && $0 != f) { print "not closed: " f " / " $0; exit 1 } }
		END { if (got != ncurves || got < 50) { print got " curves, header says " ncurves; exit 1 } print got }'
}
# the labels line (plot3d(5)): axes in micrometres
head -n 1 mxyz.solid.3D | grep -q '^# labels .* x "x (um)" y "y (um)" z "z (um)"$' ||
	fail "mxyz.solid.3D labels: $(head -n 1 mxyz.solid.3D)"

n8=$(check mxyz.solid.3D) || fail "mxyz.solid.3D: $n8"
bleach -q -solid -m 0.3 spot.cont o.in || fail "bleach -m 0.3 failed"
n3=$(check mxyz.solid.3D) || fail "mxyz.solid.3D at 0.3: $n3"
[ "$n3" -lt "$n8" ] || fail "-m 0.3 gave $n3 triangles, -m 0.8 $n8"
built pdraw
pdraw -h -nosort -ps mxyz.solid.3D >solid.ps 2>pdraw.err </dev/null ||
	fail "pdraw -h -nosort cannot draw mxyz.solid.3D: $(head -3 pdraw.err)"
echo "M = 0.8: $n8 triangles, M = 0.3: $n3"
exit 0
