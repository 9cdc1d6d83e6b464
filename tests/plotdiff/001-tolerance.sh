# plotdiff: identical files agree; a difference inside the tolerance
# agrees, outside it is reported with both line numbers and exit 1;
# -rtol is relative; layout does not matter; a missing or extra number is
# a difference; an unreadable file is exit 2; -q is silent.
. "$TOP/tests/lib/common.sh"
printf '0 1 0 1\n1\n2\n0 0\n1 1\n' >a
printf '0 1 0 1\n1\n2\n0 0\n1 1.0000005\n' >b
printf '0 1 0 1 1 2\n0 0 1 1\n' >c         # same numbers, other layout
printf '0 1 0 1\n1\n2\n0 0\n1 1\n7\n' >d   # one more number
plotdiff a a >out || fail "a file differs from itself"
grep -q '10 numbers agree' out || fail "count not reported: $(cat out)"
plotdiff a c >/dev/null || fail "layout should not matter"
plotdiff -tol 1e-6 a b >out || fail "5e-7 should be within -tol 1e-6"
plotdiff -tol 1e-7 a b >out; [ $? -eq 1 ] || fail "5e-7 should exceed -tol 1e-7"
grep -q '^plotdiff: a:5: 1 differs from b:5: 1.0000005' out || fail "bad report: $(cat out)"
plotdiff -rtol 1e-6 a b >/dev/null || fail "5e-7 should be within -rtol 1e-6 of 1"
plotdiff -rtol 1e-7 a b >/dev/null; [ $? -eq 1 ] || fail "5e-7 should exceed -rtol 1e-7"
plotdiff a d >out; [ $? -eq 1 ] || fail "an extra number should differ"
grep -q 'ends' out || fail "the shorter file is not named: $(cat out)"
[ -z "$(plotdiff -q a b)" ] || fail "-q printed something"
plotdiff a missing >/dev/null 2>err.txt; [ $? -eq 2 ] || fail "missing file: expected exit 2"
[ "$(wc -l <err.txt)" -eq 1 ] || fail "missing file: expected one line"
plotdiff -tol x a b >/dev/null 2>&1; [ $? -eq 2 ] || fail "bad option value: expected exit 2"
exit 0
