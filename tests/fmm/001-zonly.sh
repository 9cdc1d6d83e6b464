#!/bin/sh
# tests/fmm/001-zonly.sh - the fast-marching engine end to end on a rate
# file written by mkrate: a z-only rate R = 1/(1 - z/2) over a 1 um resist
# (slowness 1 - z/2, so T(z) = -z + z^2/4 exactly; developed through at
# T = 1.25 s).  Checks, against that closed form, that every vertex of
# curves.plot at t = 0.3 and 0.8 s lies at the depth where T = t within
# 2e-4 um (1/50 of a rate-grid cell; measured 3.4e-5: a second-order solve
# on a rate whose linear interpolation error is 1e-5 s); that t = 0 is the flat top and
# t = 2 s the substrate exactly; that the bounds line is the rate box; that
# curves.plot.2D holds the same triangles projected on x-y; and that the
# ASCII and binary rate files give byte-identical outputs.
. "$TOP/tests/lib/common.sh"
drv=$BUILD/tests/etch/fmm_exact
mk=$BUILD/tests/lib/mkrate
[ -x "$drv" ] || fail "$drv not built"
[ -x "$mk" ] || fail "$mk not built"
expr="1/(1-z/2)"
"$mk" -o r.bin 5 4 101 0 0.4 0 0.3 -1 0 "$expr" || fail "mkrate"
"$mk" -ascii -o r.asc 5 4 101 0 0.4 0 0.3 -1 0 "$expr" || fail "mkrate -ascii"
"$drv" curves r.bin 1 c.plot 0 0.3 0.8 2 || fail "solve r.bin"
"$drv" curves r.asc 1 a.plot 0 0.3 0.8 2 || fail "solve r.asc"
same c.plot a.plot
same c.plot.2D a.plot.2D

# walk the sets of curves.plot: per set the bounds line, the count, then
# 4-point curves; z of every vertex against the depth where T = t
awk -v tol=2e-4 '
function depth(t,   lo, hi, mid, k) {   # solve -z + z^2/4 = t on [-1, 0]
	if (t <= 0) return 0
	if (t >= 1.25) return -1
	lo = -1; hi = 0
	for (k = 0; k < 80; k++) { mid = (lo + hi) / 2; if (-mid + mid * mid / 4 > t) lo = mid; else hi = mid }
	return (lo + hi) / 2
}
BEGIN { split("0 0.3 0.8 2", T, " "); set = 0; state = "bounds" }
NF == 0 || /^#/ { next }
state == "bounds" {
	set++
	if ($0 != "0 0.4 0 0.3 -1 0") { print "set " set ": bounds " $0; bad++ }
	want = depth(T[set]); state = "count"; next
}
state == "count" { ncurves = $1; if (ncurves < 1) { print "set " set ": no curves"; bad++ }
	tri[set] = ncurves; c = 0; state = ncurves ? "npts" : "bounds"; next }
state == "npts" { if ($1 != 4) { print "set " set ": curve of " $1 " points"; bad++ }
	left = $1; state = "pts"; next }
state == "pts" {
	d = $3 - want; if (d < 0) d = -d
	if (d > worst[set]) worst[set] = d
	if (d > tol) bad++
	if (--left == 0) { if (++c == ncurves) state = "bounds"; else state = "npts" }
	next
}
END {
	if (set != 4) { print set " sets, want 4"; bad++ }
	for (s = 1; s <= set; s++) printf "t = %s s: %d triangles, max |z - z(t)| %.3g um\n", T[s], tri[s], worst[s]
	if (worst[1] != 0 || worst[4] != 0) { print "t = 0 or developed through is not exact"; bad++ }
	exit bad != 0
}' c.plot || fail "curves.plot does not match T(z) = -z + z^2/4"

# the 2D file: the 3D file with z dropped (bounds: the x-y box)
# (each file's '#' labels line aside: plot3d(5), plot2d(5))
awk '/^#/ { next } NF == 6 { print $1, $2, $3, $4; next } NF == 3 { print $1, $2; next } { print }' c.plot >proj.txt
grep -v '^#' c.plot.2D >c2.txt
same proj.txt c2.txt
