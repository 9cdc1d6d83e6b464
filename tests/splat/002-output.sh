# splat's outputs: the contour-file and cutlines are written where the
# input and -o say, are byte-identical from run to run (no dates, fixed
# summation order), -q silences the progress lines, and without -q there
# is one line per stage.  The cutline agrees with the grid where they
# share points (same spectrum, 1e-12).
. "$TOP/tests/lib/common.sh"
cat >in.txt <<'IN'
# a contact with an outrigger and a cutline
window -2 2 -2 2
rect -0.6 -0.6 0.6 0.6
rect 1 -0.15 1.3 0.15 1 180
sigma 0.4
grid 41 41
contour named.cont
cutline -2 0 2 0 41 cut.2D
IN
splat in.txt 2>progress.txt || fail "splat failed"
[ -s named.cont ] || fail "contour statement ignored"
[ -s cut.2D ] || fail "cutline not written"
[ "$(wc -l <progress.txt)" -eq 4 ] || fail "expected 4 progress lines: $(cat progress.txt)"
grep -q "^splat: .*diffraction orders" progress.txt || fail "no order count line"
splat -q -o other.cont in.txt 2>quiet.txt || fail "splat -o failed"
[ ! -s quiet.txt ] || fail "-q still prints: $(cat quiet.txt)"
same named.cont other.cont
cp cut.2D cut1.2D
splat -q in.txt || fail "second run failed"
same named.cont other.cont
same cut.2D cut1.2D
grep -v contour in.txt >nocontour.txt
splat -q nocontour.txt || fail "splat without contour statement failed"
same splat.cont named.cont
# the 21st cutline point is (0, 0), the grid centre (index 20, row 20)
# (the '#' labels line at the head of each file is skipped: plot2d(5), contour(5))
c=$(grep -v '^#' cut.2D | awk 'NR == 24 { print $2 }')
g=$(grep -v '^#' named.cont | awk 'NR > 2 { for (i = 1; i <= NF; i++) v[n++] = $i } END { print v[20 * 41 + 20] }')
close "$c" "$g" 1e-12 "cutline vs grid at the centre"
# the header: window and grid
grep -v '^#' named.cont | head -2 | tr '\n' ' ' | grep -q "^-2 2 -2 2 41 41" ||
	fail "bad header: $(head -3 named.cont)"
# the labels line (contour(5), plot2d(5)) first, in micrometres
head -1 named.cont | grep -qx '# labels title "Aerial image" x "x (um)" y "y (um)" z "intensity (clear field = 1)"' ||
	fail "contour-file labels: $(head -1 named.cont)"
head -1 cut.2D | grep -qx '# labels title "Aerial image along a cutline" x "distance along the cut (um)" y "intensity (clear field = 1)"' ||
	fail "cutline labels: $(head -1 cut.2D)"
exit 0
