# contour on an array's image: 8 x 8 Gaussian spots (sigma 0.15 um) on a
# 1 um pitch, centred at +-0.5, +-1.5, ... um, on a 161 x 161 grid over
# [-4, 4]^2.  Checked:
# - -cutrow prints 0.5: the rows through the spots' centres vary most
#   (those at +-0.5 are equal by symmetry, and of equals the one nearest
#   the middle, the upper first, wins); the middle row y = 0 runs between
#   two rows of spots (its variance is exp(-1/(2 0.15^2))^2 ~ 1e-5 of
#   theirs), so a cut there misses the features;
# - with ~10 levels the page has 64 spots x 10 rings > 100 curves, so by
#   default it is a grey map: two images (the map and its scale bar's
#   ramp), no contour labels (none of the level values is drawn as a
#   text inside the frame) and no curves, and the texts do not overlap
#   (tests/pictures/textboxes.awk);
# - -nomap draws curves and labels, no image, and its labels do not
#   overlap either;
# - the single contact of 001 (a few curves) stays contours by default.
. "$TOP/tests/lib/common.sh"
awk 'BEGIN { n = 161; print -4, 4, -4, 4; print n, n; s = 0.15
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		x = -4 + 8 * i / (n - 1); y = -4 + 8 * j / (n - 1)
		dx = x - (int(x + 4) - 4 + 0.5); dy = y - (int(y + 4) - 4 + 0.5)
		if (x >= 4) dx = 0.5; if (y >= 4) dy = 0.5
		printf "%.17g\n", exp(-(dx * dx + dy * dy) / (2 * s * s)) } }' >arr.cont
[ "$(contour -cutrow arr.cont)" = 0.5 ] || fail "-cutrow: $(contour -cutrow arr.cont), not 0.5"
contour -noplot -cstep 0.1 -tl array -psfile map.ps arr.cont </dev/null || fail "contour (map)"
[ "$(grep -c 'RunLengthDecode filter image' map.ps)" -eq 2 ] || fail "map: not a map and a scale bar"
! grep -q '^(0\.[1-9]) [0-9.]* [0-9.]* 8 ' map.ps || fail "map: contour labels drawn"
awk -v mode=overlap -f "$TOP/tests/pictures/textboxes.awk" map.ps || fail "map: texts overlap"
contour -noplot -nomap -cstep 0.1 -psfile nomap.ps arr.cont </dev/null || fail "contour -nomap"
! grep -q 'RunLengthDecode' nomap.ps || fail "-nomap drew a map"
grep -q '^(0\.5) [0-9.]* [0-9.]* 8 ' nomap.ps || fail "-nomap: no contour label"
awk -v mode=overlap -f "$TOP/tests/pictures/textboxes.awk" nomap.ps || fail "-nomap: labels overlap"
awk 'BEGIN { n = 41; print -1, 1, -1, 1; print n, n
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		x = -1 + 2 * i / (n - 1); y = -1 + 2 * j / (n - 1); printf "%.17g\n", x * x + y * y } }' >par.cont
contour -noplot -cstep 0.2 -psfile one.ps par.cont </dev/null || fail "contour (one feature)"
! grep -q 'RunLengthDecode' one.ps || fail "a single feature drawn as a map"
if command -v gs >/dev/null 2>&1; then gs_check map.ps; fi
exit 0
