# drawplot -fill: a set of a closed square (last point the first) and an
# open line; the square alone is filled light grey (one polygon filled
# with 0.85, FILL_GRAY, in the PostScript) under the lines, and without
# -fill nothing is filled.  Ghostscript renders it.
. "$TOP/tests/lib/common.sh"
cat >r.2D <<'P'
0 3 0 3
2
5
1 1
2 1
2 2
1 2
1 1
2
0 0.5
3 2.5
P
drawplot -noplot -fill -tl region -psfile fill.ps r.2D </dev/null || fail "drawplot -fill"
[ "$(grep -c ' 0.85 F' fill.ps)" -eq 1 ] || fail "-fill: expected one polygon filled 0.85, found $(grep -c ' 0.85 F' fill.ps)"
drawplot -noplot -tl region -psfile plain.ps r.2D </dev/null || fail "drawplot"
! grep -q ' 0.85 F' plain.ps || fail "a fill without -fill"
if command -v gs >/dev/null 2>&1; then gs_check fill.ps; fi
exit 0
