# Golden files: contour's PostScript and SVG for a small input are compared
# as text with tests/contour/golden/ (output is deterministic, so any diff
# is a finding).  After an intended change, regenerate with
# REGEN=1 TESTS=contour/007 sh tests/run.sh BUILD and review the diff.
. "$TOP/tests/lib/common.sh"
printf '0 2 0 2\n3 3\n0\n1\n2\n1\n2\n3\n2\n3\n4\n' >small.cont
contour -noplot -svg small.svg -cstep 0.5 small.cont </dev/null || fail "contour failed"
gs_check dataplot.ps
g=$TOP/tests/contour/golden
golden dataplot.ps "$g/small.ps"
golden small.svg "$g/small.svg"
exit 0
