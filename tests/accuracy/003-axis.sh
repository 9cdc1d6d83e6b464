# measure -coarser-fine and -plus: the estimate of one group of axes from
# changes solved at different levels of the other, and the sum of the two
# groups' estimates (the drivers' refinement by axis, scripts/etchopts.sh
# accuracy_axes).  On synthetic cylinders whose cds are known exactly
# (tests/measure/synth.awk; the 256-sided polygon puts each cd 1e-4
# relative off the circle's, so the expected errs hold within 0.5 %):
#   - this solve r 0.31, -coarse 0.32 (e2 = -0.02 in cd), the earlier
#     change from -coarser 0.44 to -coarser-fine 0.44 - 0.02 2^0.5
#     (e1 = 2^1.5 e2: order 1.5 at r = q = 2): err = 1.25 * 0.02 /
#     (2^1.5 - 1) = 0.013673;
#     without -coarser-fine the earlier change would be -coarse's 0.32
#     against 0.44 (-0.24, order over 2, used as 1): err 0.025, which the
#     test tells apart;
#   - the same with -plus a table whose err is 0.025 (the order-1 estimate
#     of 0.31, 0.32, 0.34): err 0.038673, and with -accuracy 3 (3 % of a
#     0.62 cd is 0.0186) status 3, every row over, where the group alone
#     (0.013673) is status 0: the other group's err counts;
#   - changes too small to judge: radii 0.31, 0.3101, 0.310205 (cd
#     changes 2e-4 then 2.1e-4, order 0.07, not asymptotic), whose
#     order-0.5 estimate 2e-4 / (sqrt 2 - 1) = 4.8e-4 um is 0.078 % of the
#     cd: trusted (status 0, no note) at -accuracy 1, where it is under a
#     tenth of P, refused (status 3, the note) at -accuracy 0.5;
#   - an earlier change between two solves without the feature (cd 0 in
#     both: a hole not yet open there) says nothing of the order: this
#     solve 0.31, -coarse 0.32, -coarser and -coarser-fine 0: the
#     two-solve estimate |e2| / (2 - 1) = 0.02, trusted (status 0 at
#     -accuracy 5, no note), where three levels would see changes that
#     grow (0, then 0.02) and refuse it;
#   - -coarser-fine without -coarser, or without -accuracy, and -plus
#     without -accuracy, are usage errors (2); -plus with a table without
#     an err column is a one-line error (1).
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/cylinders.sh"
# tab R SEED NAME: the table of a cylinder of radius R
tab() {
	synth "$1" "$2" >s.plot
	# shellcheck disable=SC2086 # M is a list of words on purpose
	measure $M -o "$3" s.plot || fail "measure radius $1"
}
synth 0.31 1 >fine.plot
tab 0.32 2 c.tab
tab 0.44 3 cc.tab
tab "$(awk 'BEGIN { print 0.44 - 0.02 * sqrt(2) }')" 4 cf.tab
tab 0.34 5 o.tab

# shellcheck disable=SC2086 # M is a list of words on purpose
measure $M -accuracy 3 -coarse c.tab -coarser cc.tab -coarser-fine cf.tab -o g.tab fine.plot 2>err.txt ||
	fail "-coarser-fine: status $?: $(cat err.txt)"
errs g.tab "$(awk 'BEGIN { print 1.25 * 0.02 / (2 ^ 1.5 - 1) }')" "-coarser-fine, order 1.5"
# shellcheck disable=SC2086 # M is a list of words on purpose
measure $M -accuracy check -coarse c.tab -coarser cc.tab -o n.tab fine.plot 2>err.txt ||
	fail "without -coarser-fine: status $?"
errs n.tab 0.025 "without -coarser-fine, order over 2 used as 1"

# the other group's estimate: order 1 from 0.31, 0.32, 0.34
# shellcheck disable=SC2086 # M is a list of words on purpose
measure $M -accuracy check -coarse c.tab -coarser o.tab -o other.tab fine.plot || fail "the other group's table"
errs other.tab 0.025 "the other group's estimate"
st=0
# shellcheck disable=SC2086 # M is a list of words on purpose
measure $M -accuracy 3 -coarse c.tab -coarser cc.tab -coarser-fine cf.tab -plus other.tab \
	-o t.tab fine.plot 2>err.txt || st=$?
[ $st -eq 3 ] || fail "-plus: status $st, expected 3 (0.0387 over 3 % of 0.62): $(cat err.txt)"
grep -q 'the estimated error of 3 cds is over 3 %' err.txt || fail "-plus: no count of the rows over: $(cat err.txt)"
errs t.tab "$(awk 'BEGIN { print 1.25 * 0.02 / (2 ^ 1.5 - 1) + 0.025 }')" "-plus, the sum"

tab 0.3101 6 s1.tab
tab 0.310205 7 s2.tab
st=0
# shellcheck disable=SC2086 # M is a list of words on purpose
measure $M -accuracy 1 -coarse s1.tab -coarser s2.tab -o s.tab fine.plot 2>err.txt || st=$?
[ $st -eq 0 ] || fail "small changes at -accuracy 1: status $st: $(cat err.txt)"
[ ! -s err.txt ] || fail "small changes at -accuracy 1: a note: $(cat err.txt)"
errs s.tab "$(awk 'BEGIN { print 0.0002 / (sqrt(2) - 1) }')" "small changes"
st=0
# shellcheck disable=SC2086 # M is a list of words on purpose
measure $M -accuracy 0.5 -coarse s1.tab -coarser s2.tab -o s.tab fine.plot 2>err.txt || st=$?
[ $st -eq 3 ] || fail "small changes at -accuracy 0.5: status $st, expected 3"
grep -q 'not in the asymptotic range' err.txt || fail "small changes at -accuracy 0.5: no note: $(cat err.txt)"

# a table of the same heights without the feature
awk '/^#/ { print; next } { print $1, 0, 0, 0, 0 }' c.tab >zero.tab
st=0
# shellcheck disable=SC2086 # M is a list of words on purpose
measure $M -accuracy 5 -coarse c.tab -coarser zero.tab -coarser-fine zero.tab -o z.tab fine.plot \
	2>err.txt || st=$?
[ $st -eq 0 ] || fail "an earlier change without the feature: status $st: $(cat err.txt)"
[ ! -s err.txt ] || fail "an earlier change without the feature: a note: $(cat err.txt)"
errs z.tab 0.02 "an earlier change without the feature"

for args in "-accuracy 3 -coarse c.tab -coarser-fine cf.tab" "-coarser-fine cf.tab" "-plus other.tab"; do
	st=0
	# shellcheck disable=SC2086 # the words on purpose
	measure $M $args fine.plot >/dev/null 2>&1 || st=$?
	[ $st -eq 2 ] || fail "measure $args: exit $st, expected 2"
done
# shellcheck disable=SC2086 # M is a list of words on purpose
expect_error measure $M -accuracy 3 -coarse c.tab -plus c.tab fine.plot
grep -q 'no err column' err.txt || fail "-plus without err: $(cat err.txt)"
exit 0
