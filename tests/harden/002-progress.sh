# The progress line of long work (src/lib/progress.h): "prog: what: N%
# done, about T left" on stderr (T "? s" before any work is done), at most
# every SAMPLE3D_PROGRESS seconds: with 0, every call, so a run of a second
# shows them; with 3600 (and with the default 5 s, on these sub-second
# runs) none.  Checked on splat's pair loop and etch's time loop: every
# progress line has that form, the percentages of each loop never
# decrease and stay within 0-100, splat's pair loop starts at 0 % (it
# reports before each pair) and etch's time loop ends at 100 % (it reports
# after each step); -q prints nothing on stderr, and the outputs are the
# same with and without the lines.
. "$TOP/tests/lib/common.sh"
LINE='^[a-z]+: [a-zA-Z ]+: [0-9]+% done, about (\? s|[0-9.]+ (s|min|h)) left$'
# check FILE PROG WHAT: FILE's progress lines of PROG all have the form,
# and those of WHAT exist, within 0-100, non-decreasing; prints them
check() {
	grep '% done' "$1" >all.txt
	grep -Ev "$LINE" all.txt >odd.txt && fail "$2: progress lines of another form: $(cat odd.txt)"
	grep "^$2: $3: " all.txt >p.txt || fail "no progress line \"$2: $3:\": $(cat "$1")"
	awk -F': ' '{ v = $3 + 0; if (v < last || v > 100) bad = 1; last = v } END { exit bad }' p.txt ||
		fail "$2 $3: percentages decrease or pass 100: $(cat p.txt)"
}
cat >in.txt <<'IN'
window -1 1 -1 1
rect -0.3 -0.3 0.3 0.3
grid 5 5
IN
SAMPLE3D_PROGRESS=0 splat -o a.cont in.txt 2>err.txt || fail "splat: $(cat err.txt)"
check err.txt splat "TCC pairs"
head -n 1 p.txt | grep -q ': 0% done, about ? s left$' || fail "splat's pair loop does not start at 0 %: $(cat p.txt)"
SAMPLE3D_PROGRESS=0 splat -q -o b.cont in.txt 2>err.txt || fail "splat -q"
[ ! -s err.txt ] || fail "splat -q printed: $(cat err.txt)"
same a.cont b.cont
for every in 3600 ""; do
	SAMPLE3D_PROGRESS=$every splat -o c.cont in.txt 2>err.txt || fail "splat: $(cat err.txt)"
	! grep -q '% done' err.txt || fail "SAMPLE3D_PROGRESS=$every: progress lines in a short run: $(cat err.txt)"
	same a.cont c.cont
done

MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
$MKRATE -o r.bin 5 5 5 0 1 0 1 0 1 1 || fail "mkrate"
SAMPLE3D_PROGRESS=0 etch -o a.plot -et 0.2 -dt 0.05 -seg 0.25 r.bin 2>err.txt || fail "etch: $(cat err.txt)"
check err.txt etch "time steps"
tail -n 1 p.txt | grep -q ': 100% done' || fail "etch's last progress line is not 100%: $(cat p.txt)"
SAMPLE3D_PROGRESS=0 etch -q -o b.plot -et 0.2 -dt 0.05 -seg 0.25 r.bin 2>err.txt || fail "etch -q"
[ ! -s err.txt ] || fail "etch -q printed: $(cat err.txt)"
same a.plot b.plot
for every in 3600 ""; do
	SAMPLE3D_PROGRESS=$every etch -o c.plot -et 0.2 -dt 0.05 -seg 0.25 r.bin 2>err.txt || fail "etch: $(cat err.txt)"
	! grep -q '% done' err.txt || fail "SAMPLE3D_PROGRESS=$every: progress lines in a short run: $(cat err.txt)"
	same a.plot c.plot
done
exit 0
