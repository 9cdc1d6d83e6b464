# drawmask: bad mask-files give one line "drawmask: file:line: ..." and
# exit 1 (an unknown statement, a rect outside the window, no window, an
# empty file); a missing file and a second file name are errors too.
. "$TOP/tests/lib/common.sh"
printf 'window 0 4 0 4\nfrobnicate 3\n' >m1
printf 'window 0 4 0 4\nrect 1 1 5 5\n' >m2
printf 'rect 1 1 2 2\n' >m3
: >m4
for m in m1 m2 m3 m4; do
	expect_file_error drawmask $m -noplot $m
done
expect_error drawmask -noplot nosuchfile
drawmask -noplot m1 m2 </dev/null >/dev/null 2>err.txt
[ $? -eq 2 ] || fail "two mask-files: expected exit 2"
exit 0
