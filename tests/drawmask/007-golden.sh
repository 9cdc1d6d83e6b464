# Golden files: drawmask's PostScript and SVG for a small input are compared
# as text with tests/drawmask/golden/ (output is deterministic, so any diff
# is a finding).  After an intended change, regenerate with
# REGEN=1 TESTS=drawmask/007 sh tests/run.sh BUILD and review the diff.
. "$TOP/tests/lib/common.sh"
printf 'window 0 2 0 2\nbackground dark\nrect 0.5 0.5 1.5 1.5 1 180\n' >small.in
drawmask -noplot -svg small.svg -lbl small.in </dev/null || fail "drawmask failed"
gs_check dataplot.ps
g=$TOP/tests/drawmask/golden
golden dataplot.ps "$g/small.ps"
golden small.svg "$g/small.svg"
exit 0
