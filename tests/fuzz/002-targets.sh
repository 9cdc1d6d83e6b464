# The fuzzing harness builds (tests/fuzz/targets/fuzz.sh, clang's libFuzzer) and
# each reader's target runs clean over its seed corpus and the regress
# files of its reader, once each: no crash, no sanitizer report.  Skipped
# without clang (CI installs it).  The harness is built (at -O0: compiling
# is most of this test's time, and the sanitizers check the same accesses)
# in BUILD/fuzz-check
# and kept there: the next make check rebuilds only what changed since
# (fuzz.sh compares each object with its sources, headers and fuzz.sh).
. "$TOP/tests/lib/common.sh"
need clang
fz=$BUILD/fuzz-check
sh "$TOP/tests/fuzz/targets/fuzz.sh" once "$fz" >out.txt 2>&1
st=$?
[ $st -ne 77 ] || skip "$(tail -n 1 out.txt)"
[ $st -eq 0 ] || fail "fuzz targets: $(cat out.txt)"
n=$(grep -c '^fuzz: .*: [0-9][0-9]* executions, exit 0$' out.txt)
[ "$n" -eq 13 ] || fail "expected 11 readers (gds included) and the command lines of measure and fem run clean: $(cat out.txt)"
# In process, a reader's die() returns to the harness: a stream the rate
# reader had open once leaked a descriptor per bad file, until fopen
# failed (the campaign of stop 10 aborted after 310 000 runs).  With 32
# descriptors, 3000 mutated runs must pass (before the fix: 121).
# (new units go to the scratch corpus fdc/, named first, never to the tree)
mkdir -p fdc
(ulimit -n 32 && ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1 \
	"$fz/fuzz_rate_binary" -runs=3000 -seed=1 -close_fd_mask=2 -detect_leaks=0 \
	fdc "$TOP/tests/fuzz/corpus/rate_binary" >fdleak.txt 2>&1) ||
	fail "the rate reader leaks descriptors in process: $(grep -m 3 'ERROR\|SUMMARY' fdleak.txt)"
exit 0
