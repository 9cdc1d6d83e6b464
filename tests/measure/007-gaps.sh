# measure never prints a cd whose section passes through a gap of the
# surface (open border, as delooping can leave): synthetic surfaces of
# tests/measure/synth.awk with a window left out of a wall, whose sections
# are known exactly.
#   - a truncated-cone hole (radius 0.3 at z = -0.7, 0.6 at 0), walls in
#     pieces of at most 0.02 um: closed, it measures at -0.65, -0.35 and
#     -0.2 with no warning at all;
#   - the same hole without the wall between z = -0.4 and -0.3 over 45
#     degrees (sectors 0-31 of 256): at z = -0.35 refused, exit 1, one line
#     naming the hole, the height and the gap, whose ends lie on the wall
#     (r = 0.45 within 1e-3) at the window's sides, 2 r sin(22.5 deg) =
#     0.3444 um apart (within 1e-3), and no table written; with a second
#     height that is clear, still refused; at z = -0.2 (the window below
#     the plane, where the ray test does not look) measured with only the
#     open-border warning, the same table as the closed hole; -force
#     measures at -0.35 with the refusal as a warning;
#   - the window all round (a crack through the wall, no open edge crossing
#     the plane): refused at -0.35, and -force shows why: its cd is more
#     than 2 % off the true 0.9 um (measured 0.9428);
#   - two trapezoidal lines along y (x = -1 and 1, 0.65 wide at z = -0.35),
#     walls and the 50 steps along y in pieces of at most 0.1 um, the left
#     wall of the right line left out for y from -0.5 to 0.5: the right
#     line and the space between them measured through the window are
#     refused, naming the line or space and a gap 1 um wide (within 1e-6) at
#     x = 0.675; the left line at that height (the gap 1.35 um away,
#     beyond the 3-edge tolerance of 0.3 um) and the right line at
#     y = 1.5 (1 um from the window) are measured, 0.65 within 1e-6, with
#     the open-border warning only.
. "$TOP/tests/lib/common.sh"
synth() { awk -f "$TOP/tests/measure/synth.awk" "$@"; }
cd_at() { awk -v z="$2" '!/^#/ && $1 == z { print $2 }' "$1"; }
# gap_ends: the two points "x y" of the gap named in err.txt, one a line
gap_ends() {
	sed -n 's/.* from (\([^,]*\), \([^)]*\)) to (\([^,]*\), \([^)]*\)).*/\1 \2\n\3 \4/p' err.txt
}

P="0 -0.7 0.3 -0.7 0.428571428571429 -0.4 0.471428571428571 -0.3 0.6 0 3 0"
synth -v kind=rev -v prof="$P" -v step=0.02 -v seed=1 >closed.plot
synth -v kind=rev -v prof="$P" -v step=0.02 -v gap="0 31 3 3" -v seed=1 >window.plot
synth -v kind=rev -v prof="$P" -v step=0.02 -v gap="0 255 3 3" -v seed=1 >crack.plot

measure -at -0.65,-0.35,-0.2 -hole 0 0 closed.plot >closed.txt 2>err.txt || fail "closed hole: $(cat err.txt)"
[ ! -s err.txt ] || fail "closed hole: a warning: $(cat err.txt)"
close "$(cd_at closed.txt -0.35)" 0.9 0.005 "closed hole cd at -0.35"

expect_error measure -at -0.35 -hole 0 0 -o w.txt window.plot
grep -q "^measure: window.plot: set 1: the section of the hole at z = -0.35 passes through a gap " err.txt ||
	fail "window: the message does not name the hole, the height and the gap: $(cat err.txt)"
grep -q -- "-method fmm" err.txt && grep -q -- "-force" err.txt || fail "window: no cure named: $(cat err.txt)"
[ ! -e w.txt ] || fail "window: a table was written although measure refused"
[ "$(gap_ends | wc -l)" -eq 2 ] || fail "window: no gap ends in the message: $(cat err.txt)"
gap_ends | awk '{ r = sqrt($1 * $1 + $2 * $2); d = r - 0.45; if (d < 0) d = -d; if (d > 1e-3) exit 1
	if ($2 < -1e-9 || $2 > $1 + 1e-9) exit 1 }' || fail "window: the gap's ends are not on the wall in the window: $(cat err.txt)"
gap_ends | awk 'NR == 1 { x = $1; y = $2 } NR == 2 { d = sqrt(($1 - x) ^ 2 + ($2 - y) ^ 2) - 0.9 * sin(3.14159265358979 / 8)
	if (d < 0) d = -d; exit d > 1e-3 }' || fail "window: the gap's ends are not the window's sides: $(cat err.txt)"
expect_error measure -at -0.2,-0.35 -hole 0 0 window.plot
grep -q "hole at z = -0.35 passes through a gap" err.txt || fail "window, two heights: $(cat err.txt)"

measure -at -0.2 -hole 0 0 window.plot >below.txt 2>err.txt || fail "window below the plane refused: $(cat err.txt)"
[ "$(wc -l <err.txt)" -eq 1 ] && grep -q "0.924 um of open border .* none through the sections measured" err.txt ||
	fail "window below the plane: expected the open-border warning only: $(cat err.txt)"
measure -at -0.2 -hole 0 0 closed.plot >closed2.txt 2>/dev/null || fail "closed hole at -0.2"
same below.txt closed2.txt

measure -force -at -0.35 -hole 0 0 window.plot >forced.txt 2>err.txt || fail "window -force: $(cat err.txt)"
[ "$(wc -l <err.txt)" -eq 1 ] && grep -q "hole at z = -0.35 passes through a gap.*(measured anyway: -force)" err.txt ||
	fail "window -force: expected the refusal as one warning: $(cat err.txt)"
[ -n "$(cd_at forced.txt -0.35)" ] || fail "window -force: no cd: $(cat forced.txt)"

expect_error measure -at -0.35 -hole 0 0 crack.plot
grep -q "hole at z = -0.35 passes through a gap" err.txt || fail "crack: $(cat err.txt)"
measure -force -at -0.35 -hole 0 0 crack.plot >crack.txt 2>/dev/null || fail "crack -force"
awk '!/^#/ { exit !($2 > 0.9 * 1.02) }' crack.txt ||
	fail "crack: the cd through the crack is not wrong, the surface does not model the error: $(cat crack.txt)"

L="-2.5 -0.7 -1.4 -0.7 -1.25 0 -0.75 0 -0.6 -0.7 0.6 -0.7 0.75 0 1.25 0 1.4 -0.7 2.5 -0.7"
synth -v kind=ext -v prof="$L" -v M=50 -v step=0.1 -v gap="20 29 6 6" -v seed=3 >lines.plot
for f in "line 1 0" "space 0 0"; do
	set -- $f
	expect_error measure -at -0.35 -$1 $2 $3 x lines.plot
	grep -q "the section of the $1 at z = -0.35 passes through a gap of the surface 1 um wide" err.txt ||
		fail "$1 through the window: $(cat err.txt)"
	gap_ends | awk '{ d = $1 - 0.675; if (d < 0) d = -d; if (d > 1e-6) exit 1 }' ||
		fail "$1 through the window: the gap is not at x = 0.675: $(cat err.txt)"
done
for p in "-1 0" "1 1.5"; do
	measure -at -0.35 -line $p x lines.plot >l.txt 2>err.txt || fail "line at ($p) refused: $(cat err.txt)"
	[ "$(wc -l <err.txt)" -eq 1 ] && grep -q "none through the sections measured" err.txt ||
		fail "line at ($p): expected the open-border warning only: $(cat err.txt)"
	close "$(cd_at l.txt -0.35)" 0.65 1e-6 "line at ($p)"
done
exit 0
