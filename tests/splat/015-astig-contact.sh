# Thesis Figure 9.28 (examples/astig-contact): a 0.8 lambda/NA contact with
# astigmatism 0.4 lambda at field (1,0), sigma 0.3.  Against the thesis
# text (9.3.3): a 'football' stretched along the radial x direction - the
# 30% contour is more than 0.2 um longer along x than along y (measured
# 1.49 vs 1.15) - with no movement (centroid at 0 within 1e-6).
. "$TOP/tests/lib/common.sh"
cp "$TOP/examples/astig-contact/mask.in" . || fail "no example astig-contact"
splat -q mask.in || fail "splat failed on examples/astig-contact"
[ -s image.cont ] || fail "no image.cont"
probe() { awk -v q="$1" -f "$TOP/tests/splat/probe.awk" image.cont; }
wx=$(probe "xwidth 0 0 0.3"); wy=$(probe "ywidth 0 0 0.3")
awk -v a="$wx" -v b="$wy" 'BEGIN { exit !(a > b + 0.2) }' || fail "not stretched along x: $wx vs $wy"
close "$(probe xcentroid)" 0 1e-6 "centroid x"
exit 0
