# Thesis Figure 9.26 (examples/ca-lines): 0.4 um equal lines and spaces at
# lambda 0.248, NA 0.42, sigma 0.5 (0.68 lambda/NA).  The grating is well
# resolved - space centre above 0.9, line centre below 0.1 - and the 30%
# contour gives the 0.4 um space within 0.05 um (measured 0.398).
. "$TOP/tests/lib/common.sh"
cp "$TOP/examples/ca-lines/mask.in" . || fail "no example ca-lines"
splat -q mask.in || fail "splat failed on examples/ca-lines"
[ -s image.cont ] || fail "no image.cont"
probe() { awk -v q="$1" -f "$TOP/tests/splat/probe.awk" image.cont; }
s=$(probe "at 0 0"); l=$(probe "at 0.4 0")
awk -v s="$s" -v l="$l" 'BEGIN { exit !(s > 0.9 && l < 0.1) }' || fail "grating not resolved: $s $l"
close "$(probe 'xwidth 0 0 0.3')" 0.4 0.05 "30% width of the space"
exit 0
