# Golden files: drawplot's PostScript and SVG for a small input are compared
# as text with tests/drawplot/golden/ (output is deterministic, so any diff
# is a finding).  After an intended change, regenerate with
# REGEN=1 TESTS=drawplot/007 sh tests/run.sh BUILD and review the diff.
. "$TOP/tests/lib/common.sh"
printf '0 4 0 2\n2\n3\n0 0\n2 2\n4 0\n2\n0 1\n4 1\n' >small.2D
drawplot -noplot -svg small.svg -g small.2D </dev/null || fail "drawplot failed"
gs_check dataplot.ps
g=$TOP/tests/drawplot/golden
golden dataplot.ps "$g/small.ps"
golden small.svg "$g/small.svg"
exit 0
