# Cross-check of the two engines on the thesis' resists (etch -xcheck):
# for the baked contact of examples/contact at Table 9.1's dose (240
# mJ/cm2) the nodes of the ray-string surface lie near the fast-marching
# surface T = t: median under half a grid cell and 95th percentile under
# two, a cell measured by the rate grid's x-y spacing (0.1 um; its z
# spacing, 0.0023 um, is finer than the ray-string segments by a factor of
# 70).  Measured: 95th percentile 0.39 x-y cells.  The same contact without
# bake is 004-resist-nobake.sh, the opaque defect 005-resist-defect.sh
# (one test each, so that the runner spreads them over the cores).
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/xcheck.sh"
E=$TOP/examples/contact
splat -q "$E/mask.in" || fail "splat"
sed 's/^dose .*/dose 240/' "$E/resist.in" >bake.in
bleach -q -o bake.bin image.cont bake.in || fail "bleach"
etch -et 30 -pt 15 -xcheck bake.bin 2>bake.log >/dev/null || fail "etch bake"
xcheck_log bake.log
exit 0
