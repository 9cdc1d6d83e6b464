#!/bin/sh
# tests/run.sh itself (so that make check runs tests side by side and
# reports as it goes, not one at a time and nothing until the end), on a small tree of its own:
#  - with TEST_JOBS=2 two tests run at the same time: a/001 waits (up to
#    60 s) for a file b/001 writes, so it passes only if both run at once;
#  - every area is reported as a block: its tests in name order, then
#    "== area: N passed, N failed[, N skipped] (T s)"; a failing test's
#    output is shown, a skip's reason given;
#  - the closing line counts everything and the exit status is non-zero
#    when a test failed, zero when none did.
. "$TOP/tests/lib/common.sh"
mkdir -p fake/tests/a fake/tests/b fake/tests/c fake/build/tests sync
cp "$TOP/tests/run.sh" fake/tests/run.sh
cat >fake/tests/a/001-wait.sh <<'T'
i=0
while [ ! -f "$SYNC/b-started" ]; do
	i=$((i + 1)); [ $i -lt 600 ] || { echo "b never started beside a"; exit 1; }
	sleep 0.1
done
exit 0
T
cat >fake/tests/b/001-start.sh <<'T'
touch "$SYNC/b-started"
exit 0
T
printf 'echo "the reason it failed"\nexit 3\n' >fake/tests/c/001-fail.sh
printf 'echo "skipped: no tool"\nexit 77\n' >fake/tests/c/002-skip.sh
SYNC=$PWD/sync TESTS= TEST_JOBS=2 sh fake/tests/run.sh "$PWD/fake/build" >out.txt 2>&1
st=$?
[ $st -ne 0 ] || fail "a failing test left exit 0: $(cat out.txt)"
grep -q '^PASS a/001-wait.sh$' out.txt || fail "a/001 did not pass (not run beside b?): $(cat out.txt)"
grep -q '^== a: 1 passed, 0 failed (' out.txt || fail "no line for area a: $(cat out.txt)"
grep -q '^== b: 1 passed, 0 failed (' out.txt || fail "no line for area b"
grep -q '^FAIL c/001-fail.sh (exit 3)$' out.txt || fail "c/001 not reported as failed"
grep -q '^    the reason it failed$' out.txt || fail "the failing test's output is not shown"
grep -q '^SKIP c/002-skip.sh: skipped: no tool$' out.txt || fail "the skip's reason is not shown"
grep -q '^== c: 0 passed, 1 failed, 1 skipped (' out.txt || fail "no line for area c: $(cat out.txt)"
# area c's block: its tests in name order, then its line
awk '/^(PASS|FAIL|SKIP) c\// || /^== c:/ { print }' out.txt >c.txt
printf '%s\n' 'FAIL c/001-fail.sh (exit 3)' 'SKIP c/002-skip.sh: skipped: no tool' >want.txt
head -n 2 c.txt | cmp -s - want.txt || fail "area c out of order: $(cat c.txt)"
[ "$(tail -n 1 out.txt)" = "2 passed, 1 failed, 1 skipped" ] || fail "closing line: $(tail -n 1 out.txt)"
# without the failing test: exit 0
rm fake/tests/c/001-fail.sh
rm -f sync/b-started
SYNC=$PWD/sync TESTS= TEST_JOBS=2 sh fake/tests/run.sh "$PWD/fake/build" >out2.txt 2>&1 ||
	fail "no failing test, yet exit non-zero: $(cat out2.txt)"
[ "$(tail -n 1 out2.txt)" = "2 passed, 0 failed, 1 skipped" ] || fail "closing line: $(tail -n 1 out2.txt)"
exit 0
