# measure's bad input: a usage error exits 2 with the first problem and a
# line naming --help (the usage itself when there is no argument); a run-time
# error (no set of that number, a height outside the resist, a point
# outside the box, a malformed surface) prints one line "measure: ..."
# and exits 1, leaving no output file behind.
. "$TOP/tests/lib/common.sh"
awk -f "$TOP/tests/measure/synth.awk" -v kind=rev -v prof="0 -0.7 0.3 -0.7 0.6 0 3 0" -v N=16 >s.plot

measure --help >help.txt || fail "--help exits non-zero"
grep -q '^usage: measure' help.txt || fail "--help prints no usage"
measure -h >help2.txt || fail "-h exits non-zero"
same help.txt help2.txt

# usage errors: exit 2, the first problem reported, then the pointer to --help
for args in "" "-hole 0 0 s.plot" "-at -0.3 s.plot" "-at -0.3 -rel 50 -hole 0 0 s.plot" \
	"-at a,b -hole 0 0 s.plot" "-at -0.3, -hole 0 0 s.plot" "-rel 120 -hole 0 0 s.plot" \
	"-at -0.3 -hole 0 s.plot" "-at -0.3 -space 0 0 z s.plot" "-at -0.3 -hole 0 0 -line 0 0 x s.plot" \
	"-s 0 -at -0.3 -hole 0 0 s.plot" "-at -0.3 -hole 0 0 -bogus s.plot" "-at -0.3 -hole 0 0 s.plot t.plot"; do
	# shellcheck disable=SC2086 # word splitting on purpose
	measure $args >out.txt 2>err.txt </dev/null
	st=$?
	[ $st -eq 2 ] || fail "measure $args: exit $st, expected 2: $(cat err.txt)"
	if [ -z "$args" ]; then
		grep -q '^usage: measure' err.txt || fail "measure alone: no usage on stderr"
		continue
	fi
	[ "$(wc -l <err.txt)" -eq 2 ] || fail "measure $args: not two lines: $(cat err.txt)"
	grep -qx 'measure: measure --help prints the usage' err.txt || fail "measure $args: no pointer to the usage"
	grep -q '^measure: ' err.txt || fail "measure $args: no message on stderr"
done

# run-time errors: one line, exit 1
expect_error measure -s 2 -at -0.3 -hole 0 0 s.plot
grep -q "no set 2" err.txt || fail "no set: $(cat err.txt)"
expect_error measure -at -0.8 -hole 0 0 s.plot
grep -q "outside the resist" err.txt || fail "height: $(cat err.txt)"
expect_error measure -at 0.1 -hole 0 0 s.plot
expect_error measure -at -0.3 -hole 3 0 s.plot
grep -q "outside the box" err.txt || fail "point: $(cat err.txt)"
expect_error measure -at -0.3 -line 0 -2.6 y s.plot
expect_error measure -at -0.3 -hole 0 0 nosuch.plot
# malformed surfaces: the plot reader's errors name the line
printf '0 1 0 1 -1 0\n1\n4\n0 0 0\n1 0 0\n0 1 0\n' >short.plot
expect_file_error measure short.plot -at -0.5 -hole 0.1 0.1 short.plot
printf '0 1 0 1 -1 0\n1\n4\n0 0 0\n1 0 nan\n0 1 0\n0 0 0\n' >nan.plot
expect_file_error measure nan.plot -at -0.5 -hole 0.1 0.1 nan.plot
: >empty.plot
expect_file_error measure empty.plot -at -0.5 -hole 0.1 0.1 empty.plot
printf 'garbage\n' >garbage.plot
expect_file_error measure garbage.plot -at -0.5 -hole 0.1 0.1 garbage.plot
# ... and measure's own: not triangles, not closed, not a box
printf '0 1 0 1 -1 0\n1\n3\n0 0 0\n1 0 0\n0 1 0\n' >open.plot
expect_error measure -at -0.5 -hole 0.1 0.1 open.plot
grep -q "curve 1: 3 points" err.txt || fail "not a triangle: $(cat err.txt)"
printf '0 1 0 1 -1 0\n1\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 -1\n' >unclosed.plot
expect_error measure -at -0.5 -hole 0.1 0.1 unclosed.plot
grep -q "not closed" err.txt || fail "not closed: $(cat err.txt)"
printf '0 1 0 1 0 0\n0\n' >flat.plot
expect_error measure -at 0 -hole 0.1 0.1 flat.plot
grep -q "not a box" err.txt || fail "flat box: $(cat err.txt)"

# a failed run leaves no output file, and does not clobber an old one
echo old >keep.txt
expect_error measure -at -0.8 -hole 0 0 -o keep.txt -plot keep.plot s.plot
[ "$(cat keep.txt)" = old ] || fail "a failed run clobbered the output"
[ ! -e keep.plot ] || fail "a failed run left a plot file"
[ -z "$(ls | grep -v '\.\(plot\|txt\)$')" ] || fail "temporaries left: $(ls)"
exit 0
