# Thesis Figure 9.4 (examples/defect): a 0.5 um opaque square defect in a
# space of a 1.3 um line/space array, lambda 0.436, NA 0.28, sigma 0.5.
# Against the thesis text (9.2.2): far from the defect the 30% contour
# gives the 1.3 um space (within 0.1 um; measured 1.257); at the defect
# the intensity falls to the 40-60% contours (its minimum over the defect
# must lie in 0.4..0.6; measured 0.51) and the space narrows.
. "$TOP/tests/lib/common.sh"
cp "$TOP/examples/defect/mask.in" . || fail "no example defect"
splat -q mask.in || fail "splat failed on examples/defect"
[ -s image.cont ] || fail "no image.cont"
probe() { awk -v q="$1" -f "$TOP/tests/splat/probe.awk" image.cont; }
far=$(probe "xwidth -3.5 0 0.3")
close "$far" 1.3 0.1 "30% width of the space far from the defect"
m=$(probe "min -0.25 0.25 -0.25 0.25")
awk -v m="$m" 'BEGIN { exit !(m > 0.4 && m < 0.6) }' || fail "defect minimum $m not in 0.4..0.6"
near=$(probe "max -0.6 0.6 -0.1 0.1")
awk -v a="$near" -v b="$(probe 'max -0.6 0.6 -3.6 -3.4')" 'BEGIN { exit !(a < b) }' ||
	fail "the space is not dimmer beside the defect"
exit 0
