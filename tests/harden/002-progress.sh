# The progress line of long work (src/lib/progress.h): "prog: what: N%
# done, about T left" on stderr, at most every SAMPLE3D_PROGRESS seconds
# (0 here: every call, so a run of a second shows it), percentages
# non-decreasing from 0 to 100, none with -q.  splat's pair loop and
# etch's time loop.
. "$TOP/tests/lib/common.sh"
cat >in.txt <<'IN'
window -1 1 -1 1
rect -0.3 -0.3 0.3 0.3
grid 5 5
IN
SAMPLE3D_PROGRESS=0 splat -o a.cont in.txt 2>err.txt || fail "splat: $(cat err.txt)"
grep -E '^splat: TCC pairs: [0-9]+% done, about [0-9.]+ (s|min|h) left$' err.txt >p.txt ||
	fail "no progress line from splat: $(cat err.txt)"
awk '{ v = $4 + 0; if (v < last) bad = 1; last = v } END { exit bad }' p.txt ||
	fail "splat percentages decrease: $(cat p.txt)"
SAMPLE3D_PROGRESS=0 splat -q -o b.cont in.txt 2>err.txt || fail "splat -q"
[ ! -s err.txt ] || fail "splat -q printed: $(cat err.txt)"
same a.cont b.cont

MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
$MKRATE -o r.bin 5 5 5 0 1 0 1 0 1 1 || fail "mkrate"
SAMPLE3D_PROGRESS=0 etch -et 0.2 -dt 0.05 -seg 0.25 r.bin 2>err.txt || fail "etch: $(cat err.txt)"
grep -E '^etch: time steps: [0-9]+% done, about [0-9.]+ (s|min|h) left$' err.txt >p.txt ||
	fail "no progress line from etch: $(cat err.txt)"
tail -n 1 p.txt | grep -q ' 100% done' || fail "etch's last progress line is not 100%: $(cat p.txt)"
SAMPLE3D_PROGRESS=0 etch -q -et 0.2 -dt 0.05 -seg 0.25 r.bin 2>err.txt || fail "etch -q"
[ ! -s err.txt ] || fail "etch -q printed: $(cat err.txt)"
exit 0
