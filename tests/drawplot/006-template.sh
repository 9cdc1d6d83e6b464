# The template-file: curve i takes entry i modulo the number of entries
# (checked on the dash patterns and markers of the PostScript: entry 1 is
# solid with no marker, entry 2 dashed "[6 3]" with circles), labels make
# a legend (the label texts appear), bare numbers "3 17" are a line type
# and a marker, and "=" may be glued or left out.
. "$TOP/tests/lib/common.sh"
printf '0 3 0 3\n3\n2\n0 0\n3 3\n2\n0 1\n3 1\n2\n0 2\n3 2\n' >c.2D
cat >tpl <<'T'
ln_type = 1   mkr_type = 0   label = "First line"
ln_type=2 mkr_type=14 label "Second"
T
drawplot -noplot -t tpl c.2D </dev/null || fail "drawplot -t"
gs_check dataplot.ps
grep -q '^(First line) ' dataplot.ps || fail "legend label 1 missing"
grep -q '^(Second) ' dataplot.ps || fail "legend label 2 missing"
grep -q '^\[6 3\] 0 setdash' dataplot.ps || fail "entry 2's dashed line missing"
printf '3 17\n' >tpl2
drawplot -noplot -t tpl2 c.2D </dev/null || fail "drawplot -t bare numbers"
grep -q '^\[1 3\] 0 setdash' dataplot.ps || fail "line type 3 (dotted) missing"
printf 'templatefile "tpl"\n' >opts
drawplot -noplot -o opts c.2D </dev/null || fail "templatefile keyword"
grep -q '^(Second) ' dataplot.ps || fail "templatefile from the options-file not used"
exit 0
