# Golden files: pdraw's PostScript and SVG for a small input are compared
# as text with tests/pdraw/golden/ (output is deterministic, so any diff
# is a finding).  After an intended change, regenerate with
# REGEN=1 TESTS=pdraw/007 sh tests/run.sh BUILD and review the diff.
. "$TOP/tests/lib/common.sh"
printf '0 1 0 1 0 1\n2\n4\n0 0 0\n1 0 0\n0 1 1\n0 0 0\n4\n0 0 1\n1 1 0\n1 0 1\n0 0 1\n' >small.3D
pdraw -noplot -svg small.svg -h small.3D </dev/null || fail "pdraw failed"
gs_check dataplot.ps
g=$TOP/tests/pdraw/golden
golden dataplot.ps "$g/small.ps"
golden small.svg "$g/small.svg"
exit 0
