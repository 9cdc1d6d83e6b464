# fem on a long sweep: progress and interruption.
#  - without -q, "fem: K/N points" lines on stderr, K never decreasing,
#    the last one N/N, and the summary names every file collect wrote
#    (region.ps included, with -target);
#  - killed mid-sweep (SIGTERM to its process group, as ^C sends SIGINT to
#    the terminal's; both are trapped alike), fem says in one line how
#    many points are done and that the same command resumes, and exits
#    130; the points finished before the signal stay (one caught between
#    its measure and its clean-up may be deleted by make), no temporary
#    is left once the process group has ended, and the same command then
#    finishes the sweep (fem.dat has every point).
. "$TOP/tests/lib/common.sh"
built fem
need setsid
E=$TOP/examples/contact
# the example's resist at nz 100 (not 300): a point still takes a few
# tenths of a second at -j 1, time enough for the signal to find the sweep
# midway, at a third of the cost
sed 's/^grid nz 300$/grid nz 100/' "$E/resist.in" >resist.in
grep -qx 'grid nz 100' resist.in || fail "examples/contact/resist.in has no line grid nz 300 to change"
set -- -if "$E/mask.in" -bf "$PWD/resist.in" -et 10 -dose 70:90:10 -focus -1:1:1 \
	-measure "-rel 10 -hole 0 0" -j 2
# one point at a time in the interrupted run (-j 1, the last -j wins):
# under -j 2 make runs every bleach before any etch, so points finish
# together at the end and a signal finds none or all of them
setsid "$BUILD/bin/fem" "$@" -j 1 >/dev/null 2>err1.txt &
pid=$!
n=0
# a point is finished once its recipe has ended: measure.dat written, then
# its intermediates removed (make deletes the target of a recipe still
# running when the signal comes, so a point caught between the two is
# lost, as the header allows); the first such point must survive
first=""
until [ -n "$first" ]; do
	sleep 0.2
	for m in fem/f*/d*/measure.dat; do
		[ -f "$m" ] && [ ! -e "${m%/measure.dat}/rate" ] && { first=$m; break; }
	done
	n=$((n + 1))
	[ $n -lt 600 ] || { kill -TERM -"$pid"; fail "no point finished in 120 s"; }
done
sleep 0.3
kill -TERM -"$pid" || fail "cannot signal fem"
wait "$pid"
st=$?
[ $st -eq 130 ] || fail "interrupted fem: exit $st, expected 130: $(cat err1.txt)"
grep -Eq '^fem: interrupted after [0-8]/9 points; run the same command again to resume$' err1.txt ||
	fail "no resume line: $(cat err1.txt)"
[ -f "$first" ] || fail "$first, finished before the signal, was deleted"
done1=$(ls fem/f*/d*/measure.dat | wc -l)
[ "$done1" -ge 1 ] && [ "$done1" -lt 9 ] || fail "$done1 points done after the interruption"
# a program the signal reached may still be writing what it finished
# (etch keeps its finished print times) after make and fem are gone: the
# temporaries are checked once the whole process group has ended
n=0
while kill -0 -"$pid" 2>/dev/null; do
	sleep 0.2
	n=$((n + 1))
	[ $n -lt 150 ] || fail "the sweep's programs still run 30 s after fem ended"
done
[ -z "$(find fem -name '*.tmp*')" ] || fail "temporaries left: $(find fem -name '*.tmp*')"
# the same command resumes and finishes
fem "$@" -target 0.85 -tol 10 >/dev/null 2>err2.txt || fail "the resumed fem failed: $(tail -n 3 err2.txt)"
grep -E '^fem: [0-9]+/9 points$' err2.txt | sed 's/^fem: \([0-9]*\)\/.*/\1/' >counts.txt
[ -s counts.txt ] || fail "no progress lines: $(cat err2.txt)"
awk 'NR > 1 && $1 < last { exit 1 } { last = $1 }' counts.txt || fail "progress decreased: $(cat counts.txt)"
[ "$(tail -n 1 counts.txt)" = 9 ] || fail "progress did not end at 9/9: $(cat err2.txt)"
[ "$(head -n 1 counts.txt)" -ge "$done1" ] || fail "the resumed run started below the finished points"
grep -q "region.ps" err2.txt || fail "the summary omits region.ps: $(tail -n 1 err2.txt)"
[ "$(awk '!/^#/ && NF' fem/fem.dat | wc -l)" -eq 9 ] || fail "fem.dat: not 9 points"
exit 0
