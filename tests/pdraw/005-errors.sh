# pdraw: malformed plot files give one line "pdraw: file:line: ..." and
# exit 1 (empty, garbage, truncated, wrong count, NaN, huge count, a 2D
# file); -v with too few numbers or a zero vector is a usage error (exit
# 2); a degenerate polygon (all points on a line) and a flat box (zmin =
# zmax) with -h still draw.
. "$TOP/tests/lib/common.sh"
: >empty.3D
printf 'what\n' >garbage.3D
printf '0 1 0 1 0 1\n1\n3\n0 0 0\n1 1 1\n' >short.3D
printf '0 1 0 1 0 1\n1\n1999999999\n0 0 0\n' >huge.3D
printf '0 1 0 1 0 1\n1\n2\n0 0 nan\n1 1 1\n' >nan.3D
printf '0 1 0 1\n1\n2\n0 0\n1 1\n' >flat.2D
for f in empty garbage short huge nan; do
	expect_error pdraw -noplot $f.3D
	grep -q "^pdraw: $f.3D:" err.txt || fail "$f.3D: $(cat err.txt)"
done
expect_error pdraw -noplot flat.2D
printf '0 1 0 1 0 1\n1\n2\n0 0 0\n1 1 1\n' >ok.3D
pdraw -noplot -v 1 2 ok.3D </dev/null >out.txt 2>err.txt
[ $? -eq 2 ] || fail "-v with two numbers: expected exit 2"
pdraw -noplot -v 0 0 0 ok.3D </dev/null >out.txt 2>err.txt
[ $? -eq 2 ] || fail "-v 0 0 0: expected exit 2"
printf '0 1 0 1 0 0\n2\n4\n0 0 0\n1 1 0\n2 2 0\n0 0 0\n5\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 0\n' >degen.3D
pdraw -noplot -h degen.3D </dev/null || fail "pdraw -h on a degenerate polygon"
gs_check dataplot.ps
exit 0
