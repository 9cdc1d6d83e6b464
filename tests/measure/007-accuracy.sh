# measure -accuracy P|check -coarse TABLE [-ratio r]: the err column is
# Richardson's estimate with the order 1 assumed, |cd - cd_coarse| / (r - 1),
# checked on two synthetic cylinders whose cds are known exactly (radius
# 0.30 and 0.31 um, tests/measure/synth.awk; a 256-sided polygon stands for
# the circle, so each cd is 1e-4 relative off and their difference 2e-4
# relative): expected err 0.02 um with r = 2, 0.01 um with r = 3, within
# 0.5 % of it.  With P the status is 3 when an err is over P % of its cd
# (3 % of 0.6 = 0.018 < 0.02), 0 when none is (5 %), and "check" never
# fails; without -accuracy there is no err column.  A coarse table of
# other heights, of another feature kind, or with a negative err is
# refused in one line with status 1; -accuracy and -coarse go together
# and bad values are usage errors (status 2).
. "$TOP/tests/lib/common.sh"
synth() { awk -f "$TOP/tests/measure/synth.awk" "$@"; }
synth -v kind=rev -v prof="0.30 -0.7 0.30 0 3 0" -v seed=1 >fine.plot
synth -v kind=rev -v prof="0.31 -0.7 0.31 0 3 0" -v seed=2 >coarse.plot
measure -rel 10,50,90 -hole 0 0 -o coarse.tab coarse.plot || fail "measure coarse"
measure -rel 10,50,90 -hole 0 0 -o plain.tab fine.plot || fail "measure fine"
head -n 1 plain.tab | grep -q err && fail "err column without -accuracy: $(head -n 1 plain.tab)"

# err column: header, value, and the other columns unchanged
errcol() { # errcol TABLE R: every row's err is 0.02 / (R - 1) within 0.5 %
	awk -v r="$2" 'NR == 1 { if ($0 != "# z cd area dx dy err") { print "header: " $0; bad = 1 }; next }
		/^#/ { next }
		{ n++; want = 0.02 / (r - 1); d = $6 - want; if (d < 0) d = -d
		  if (d > 0.005 * want) { print "err " $6 ", expected " want; bad = 1 } }
		END { if (n != 3) { print n " rows"; bad = 1 }; exit bad }' "$1" || fail "$1: $(cat "$1")"
}
measure -rel 10,50,90 -hole 0 0 -accuracy check -coarse coarse.tab -o check.tab fine.plot ||
	fail "-accuracy check exit $?"
errcol check.tab 2
# the rest of each row is the plain table's
cut -d' ' -f1-5 check.tab | sed 1d >a.txt
cut -d' ' -f1-5 plain.tab | sed 1d >b.txt
same a.txt b.txt
measure -rel 10,50,90 -hole 0 0 -accuracy check -coarse coarse.tab -ratio 3 -o r3.tab fine.plot ||
	fail "-ratio 3"
errcol r3.tab 3
measure -rel 10,50,90 -hole 0 0 -accuracy 5 -coarse coarse.tab -o p5.tab fine.plot ||
	fail "-accuracy 5: an err of 0.02 on a cd of 0.6 (3.3 %) is within 5 %"
errcol p5.tab 2
st=0
measure -rel 10,50,90 -hole 0 0 -accuracy 3 -coarse coarse.tab -o p3.tab fine.plot 2>err.txt || st=$?
[ $st -eq 3 ] || fail "-accuracy 3: exit $st, expected 3 (err 3.3 % of cd)"
errcol p3.tab 2
grep -q "over 3 %" err.txt || fail "-accuracy 3: no message: $(cat err.txt)"

# a coarse table of another measurement, or a bad one: one line naming it
refused() { # refused TABLE: measure -accuracy check -coarse TABLE fails naming TABLE
	expect_error measure -rel 10,50,90 -hole 0 0 -accuracy check -coarse "$1" fine.plot
	grep -q "^measure: $1:" err.txt || fail "the message does not name $1: $(cat err.txt)"
}
measure -rel 10,50 -hole 0 0 -o two.tab coarse.plot
refused two.tab
measure -rel 10,50,80 -hole 0 0 -o other.tab coarse.plot
refused other.tab
measure -rel 10,50,90 -space 0 0 x -o space.tab coarse.plot
refused space.tab
sed '2s/$/ -0.1/; 3s/$/ 0/; 4s/$/ 0/; 1s/$/ err/' coarse.tab >neg.tab
expect_file_error measure neg.tab -rel 10,50,90 -hole 0 0 -accuracy check -coarse neg.tab fine.plot
for args in "-accuracy 1" "-coarse coarse.tab" "-accuracy 0 -coarse coarse.tab" \
	"-accuracy 100 -coarse coarse.tab" "-accuracy x -coarse coarse.tab" \
	"-accuracy 1 -coarse coarse.tab -ratio 1" "-accuracy 1 -coarse coarse.tab -ratio x"; do
	st=0
	# shellcheck disable=SC2086 # args is a list of words on purpose
	measure -rel 10 -hole 0 0 $args fine.plot >/dev/null 2>&1 || st=$?
	[ $st -eq 2 ] || fail "measure $args: exit $st, expected 2"
done
exit 0
