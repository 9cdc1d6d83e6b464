# Thesis Figure 9.27 (examples/coma-contact): a 0.8 lambda/NA contact with
# coma 0.4 lambda at field (1,0), sigma 0.3.  Against the thesis text
# (9.3.3): the intensity builds up towards -x, the centre of the field -
# the image centroid moves to -x by more than 0.1 um (measured -0.35) and
# the intensity 0.7 um left of centre exceeds that 0.7 um right of it -
# while the y mirror symmetry stays (1e-9).
. "$TOP/tests/lib/common.sh"
cp "$TOP/examples/coma-contact/mask.in" . || fail "no example coma-contact"
splat -q mask.in || fail "splat failed on examples/coma-contact"
[ -s image.cont ] || fail "no image.cont"
probe() { awk -v q="$1" -f "$TOP/tests/splat/probe.awk" image.cont; }
cx=$(probe "xcentroid")
awk -v c="$cx" 'BEGIN { exit !(c < -0.1) }' || fail "centroid x $cx does not move towards -x"
l=$(probe "at -0.7 0"); r=$(probe "at 0.7 0")
awk -v l="$l" -v r="$r" 'BEGIN { exit !(l > r + 0.1) }' || fail "no build-up at -x: $l vs $r"
close "$(probe 'at -0.5 0.8')" "$(probe 'at -0.5 -0.8')" 1e-9 "y mirror"
exit 0
