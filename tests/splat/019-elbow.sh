# Thesis Figure 9.2 (examples/elbow): a 1.25 um isolated transparent elbow.
# Against the thesis text (9.2.1): the intensity stays high along the
# elbow - at the corner and along both arms above 0.8 - and the 30%
# contour gives the 1.25 um arm width within 0.1 um; the elbow is
# symmetric about its diagonal (1e-6, the quadrature's level).
. "$TOP/tests/lib/common.sh"
cp "$TOP/examples/elbow/mask.in" . || fail "no example elbow"
splat -q mask.in || fail "splat failed on examples/elbow"
[ -s image.cont ] || fail "no image.cont"
probe() { awk -v q="$1" -f "$TOP/tests/splat/probe.awk" image.cont; }
for p in "0.625 0.625" "3 0.625" "0.625 3"; do
	v=$(probe "at $p")
	awk -v v="$v" 'BEGIN { exit !(v > 0.8) }' || fail "intensity $v at $p below 0.8"
done
close "$(probe 'ywidth 3 0.625 0.3')" 1.25 0.1 "30% width of the horizontal arm"
close "$(probe 'at 2 0.3')" "$(probe 'at 0.3 2')" 1e-6 "diagonal symmetry"
exit 0
