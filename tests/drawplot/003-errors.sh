# Malformed inputs give one line "drawplot: file:line: ..." and exit 1,
# never a crash (also under the sanitizers): empty, garbage, truncated,
# wrong counts, NaN, a huge count; and template-files with an unknown
# word, a line type out of range (11), a marker out of range (18), a
# missing value and no entries.
. "$TOP/tests/lib/common.sh"
printf '0 1 0 1\n1\n2\n0 0\n1 1\n' >ok.2D
: >empty.2D
printf 'hello world\n' >garbage.2D
printf '0 1 0 1\n1\n3\n0 0\n1 1\n' >short.2D
printf '0 1 0 1\n2\n2\n0 0\n1 1\n' >count.2D
printf '0 1 0 1\n1\n2\n0 nan\n1 1\n' >nan.2D
printf '0 1 0 1\n1\n1999999999\n0 0\n' >huge.2D
for f in empty garbage short count nan huge; do
	expect_error drawplot -noplot $f.2D
	grep -q "^drawplot: $f.2D:" err.txt || fail "$f.2D: message does not name the file: $(cat err.txt)"
done
expect_error drawplot -noplot missing.2D
printf 'ln_type = 1 mkr_type = 0\nfoo = 3\n' >t1
printf 'ln_type = 11\n' >t2
printf 'mkr_type = 18\n' >t3
printf 'label\n' >t4
printf '# nothing\n' >t5
for t in t1 t2 t3 t4 t5; do
	expect_file_error drawplot $t -noplot -t $t ok.2D
done
grep -q '^drawplot: t5:1:' err.txt || fail "empty template: $(cat err.txt)"
exit 0
