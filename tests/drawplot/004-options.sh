# drawplot's options-file: every keyword of the thesis' Appendix B list is
# accepted (each with a valid value, one per line), and takes effect where
# it shows in the PostScript (toplabel, scale); an out-of-range value, a
# bad on/off, an unknown keyword and a missing value are each rejected
# with one line naming the file and the line number.
. "$TOP/tests/lib/common.sh"
printf '0 1 0 1\n1\n2\n0 0\n1 1\n' >in
cat >opts <<'O'
xlabel "X" 
ylabel "Y"
toplabel "My Title"
noplot on
postscript on
printplot off
printer "lp0"
scale 0.5
xticks 5
yticks 3
autorange off
clip on
equalscale on
grid on
line on
linechange on
marker on
markerchange on
landscape off
xlog off
ylog off
sleeptime 5
templatefile ""
O
drawplot -noplot -o opts in </dev/null 2>err.txt || fail "drawplot -o opts: $(cat err.txt)"
grep -q '(My Title)' dataplot.ps || fail "toplabel from the options-file not drawn"
grep -q '0.5000 dup scale' dataplot.ps || fail "scale 0.5 from the options-file not applied"
printf 'toplabel "x"\n# comment\nxticks 30\n' >bad1
expect_file_error drawplot bad1 -noplot -o bad1 in
grep -q 'bad1:3:' err.txt || fail "wrong line in: $(cat err.txt)"
printf 'postscript maybe\n' >bad2
expect_file_error drawplot bad2 -noplot -o bad2 in
printf 'xlabel "a"\nnosuchkeyword on\n' >bad3
expect_file_error drawplot bad3 -noplot -o bad3 in
grep -q 'bad3:2:' err.txt || fail "wrong line in: $(cat err.txt)"
printf 'scale\n' >bad4
expect_file_error drawplot bad4 -noplot -o bad4 in
exit 0
