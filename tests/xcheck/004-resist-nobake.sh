# Cross-check of the two engines (etch -xcheck, limits as in
# 002-resist.sh) on the contact of examples/contact without bake at Table
# 9.1's dose (240 mJ/cm2), delooped (Figure 8.16's loops).  Measured: 95th
# percentile 1.24 x-y cells.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/xcheck.sh"
E=$TOP/examples/contact
splat -q "$E/mask.in" || fail "splat"
sed 's/^dose .*/dose 240/' "$E/resist-nobake.in" >nobake.in
bleach -q -o nobake.bin image.cont nobake.in || fail "bleach"
etch -et 30 -deloop -xcheck nobake.bin 2>nobake.log >/dev/null || fail "etch nobake"
xcheck_log nobake.log
# the loops of the unbaked contact are all removed at the default segment
# (joining the sheets once left 4 crossings here: deloop_run falls back)
grep -q 'deloop: .* 0 crossings left' nobake.log || fail "loops left: $(grep 'deloop:' nobake.log)"
exit 0
