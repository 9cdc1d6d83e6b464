# The fuzzing harness builds (tests/fuzz/targets/fuzz.sh, clang's libFuzzer) and
# each reader's target runs clean over its seed corpus and the regress
# files of its reader, once each: no crash, no sanitizer report.  Skipped
# without clang (CI installs it).
. "$TOP/tests/lib/common.sh"
need clang
sh "$TOP/tests/fuzz/targets/fuzz.sh" once fz >out.txt 2>&1
st=$?
[ $st -ne 77 ] || skip "$(tail -n 1 out.txt)"
[ $st -eq 0 ] || fail "fuzz targets: $(cat out.txt)"
n=$(grep -c '^fuzz: .*: [0-9][0-9]* executions, exit 0$' out.txt)
[ "$n" -eq 10 ] || fail "expected 10 readers (gds included) run clean: $(cat out.txt)"
exit 0
