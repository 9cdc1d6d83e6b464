# sample3D -measure "ARGS": after etch, the table of measure ARGS on the
# last set of curves.plot is printed on standard output, the same bytes as
# measure run by hand; -measure without -et is a usage error, and so is a
# bad measure option, found before any stage runs; a measure that fails
# on the result stops the driver with measure's message.
. "$TOP/tests/lib/common.sh"
"$BUILD/tests/lib/mkrate" -o flat.bin 11 11 8 -1 1 -1 1 -0.7 0 0.1 || fail "mkrate"
sample3D -q -rb flat.bin -et 2 -pt 1 -measure "-at -0.15,-0.25 -line 0 0 x" >out.txt 2>err.txt ||
	fail "sample3D -measure failed: $(cat err.txt)"
measure -at -0.15,-0.25 -line 0 0 x curves.plot >direct.txt 2>/dev/null || fail "measure"
same out.txt direct.txt
grep -q '^-0.25 2 ' out.txt || fail "not the last set (the front at -0.2): $(cat out.txt)"
sample3D -q -rb flat.bin -measure "-rel 50 -hole 0 0" >/dev/null 2>err.txt
[ $? -eq 2 ] || fail "-measure without -et: not a usage error"
grep -q "needs -et" err.txt || fail "-measure without -et: $(head -1 err.txt)"
rm -f curves.plot
sample3D -q -rb flat.bin -et 1 -measure "-rel 50 -hole 0" >/dev/null 2>err.txt
[ $? -eq 2 ] || fail "a bad -measure argument: not a usage error"
grep -q "^measure: option -hole needs two numbers" err.txt || fail "bad -measure argument: $(cat err.txt)"
[ ! -e curves.plot ] || fail "etch ran although the -measure arguments were bad"
sample3D -q -rb flat.bin -et 1 -measure "-rel 50 -hole 5 0" >/dev/null 2>err.txt &&
	fail "a point outside the box did not stop sample3D"
grep -q "^measure: .*outside the box" err.txt || fail "measure's message lost: $(cat err.txt)"
exit 0
