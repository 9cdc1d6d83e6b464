#!/bin/sh
# The delooped unbaked contact of examples/contact with several print
# times has no gap for measure to refuse, and measures like fast marching:
# its run.sh (sample3D -et 60 -pt 20 -hidden), here with -deloop.  The
# set of each print time is a delooped copy of the advancing mesh; while
# that mesh was delooped in place at 20 and 40 s its seams stayed open,
# and the last set kept 8.3 um of open border in the wall (measure refused
# it at 40 to 70 % of the height).  Measure's refusal itself is checked on
# synthetic gaps (tests/measure/007-gaps.sh).  Checked:
#   - sample3D -measure "-rel 50,70,90 -hole 0 0" succeeds with nothing
#     on stderr from measure (no gap, no open border; -accuracy off: the
#     grid study's notes on the coarser levels are not this test's), and etch's summary
#     in sample3D's log reports 0 um of border left open;
#   - etch -method fmm on the same run's rate file (rval.3D.binary),
#     measured at the same heights: every cd of the ray-string surface
#     within TOL = 3 % of fast marching's (measured fmm 0.6626 1.1335
#     1.1983, ray-string 0.6806 1.1329 1.2024 um: 2.7, 0.05, 0.3 %).  At
#     50 % the section passes the hole's narrowing tip, where the cd
#     changes 3.7 um per um of height: fast marching, with the rate
#     between nodes reconstructed with its curvature, is 0.5 % from the
#     cd the same run converges to as nz grows (0.6596 at nz 600, 0.6594
#     at 1200); the ray-string, whose rate is linear between nodes, and
#     fast marching with a linear rate (0.6796) lie 3 % from it.
. "$TOP/tests/lib/common.sh"
TOL=0.03
E=$TOP/examples/contact
sample3D -if "$E/mask.in" -bf "$E/resist-nobake.in" -et 60 -pt 20 -hidden -deloop \
	-accuracy off -measure "-rel 50,70,90 -hole 0 0" >s3d.txt 2>err.txt || fail "sample3D -measure: $(grep measure: err.txt)"
! grep -q "^measure:" err.txt || fail "measure warned: $(grep measure: err.txt)"
line=$(grep 'etch: deloop:' err.txt) || fail "no deloop summary from etch"
echo "$line"
echo "$line" | grep -q ' 0 um of border left open' || fail "border left open: $line"
[ -s rval.3D.binary ] || fail "sample3D left no rate file"
etch -q -et 60 -pt 20 -method fmm -o fmm.plot rval.3D.binary || fail "etch -method fmm"
measure -rel 50,70,90 -hole 0 0 fmm.plot >fmm.txt 2>err.txt || fail "fast-marching surface refused: $(cat err.txt)"
f=$(awk '!/^#/ { printf "%s ", $2 }' fmm.txt) r=$(awk '!/^#/ && NF == 5 { printf "%s ", $2 }' s3d.txt)
echo "cds at 50 70 90 %: fast marching $f, ray-string $r"
echo "$f $r" | awk -v t=$TOL '{ if (NF != 6) exit 1; for (i = 1; i <= 3; i++) { a = $i; b = $(i + 3)
	if (!(a > 0.5)) exit 1; d = (a - b) / a; if (d < 0) d = -d; if (d > t) exit 1 } }' ||
	fail "the ray-string's cds differ from fast marching's by more than $TOL"
exit 0
