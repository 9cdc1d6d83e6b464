# Thesis Figure 9.11 (examples/corner-defect): a 0.5 um opaque defect
# 0.2 um off the corner of a large opaque square.  Against the thesis
# text (9.2.3): the defect does not print at the 30% threshold of best
# dose nor at the 38% of 22% underexposure by the threshold model - the
# defect sits in the 'large area of 60% intensity' (its minimum must lie
# in 0.4..0.65; measured 0.53) - and the clear field far away is 1 within
# 0.01.
. "$TOP/tests/lib/common.sh"
cp "$TOP/examples/corner-defect/mask.in" . || fail "no example corner-defect"
splat -q mask.in || fail "splat failed on examples/corner-defect"
[ -s image.cont ] || fail "no image.cont"
probe() { awk -v q="$1" -f "$TOP/tests/splat/probe.awk" image.cont; }
m=$(probe "min -0.7 -0.2 0.2 0.7")
awk -v m="$m" 'BEGIN { exit !(m > 0.4 && m < 0.65) }' || fail "defect minimum $m not in 0.4..0.65"
close "$(probe 'at -2 2')" 1 0.01 "clear field 2 um off the corner"
# the square's corner itself: the 30% contour passes close to it
c=$(probe "at 0 0")
awk -v c="$c" 'BEGIN { exit !(c > 0.15 && c < 0.45) }' || fail "corner intensity $c not in 0.15..0.45"
exit 0
