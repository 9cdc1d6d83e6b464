# End to end, physical meaning (thesis Figures 8.14-8.18): the 1.25 um
# contact of examples/contact (Olin Hunt 6512, 80 mJ/cm2 as Figure 8.17
# states, 0.08 um bake) opens to the substrate within the example's 60 s of
# development: the deepest point of the final profile is the substrate,
# z = -0.7 um (to 1e-9: nodes stop there).  At 60% of the dose (48 mJ/cm2)
# it does not: the deepest point stays above -0.6 um (measured -0.33).
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact
mindepth() { awk 'NF == 0 { m = 0 } NF == 3 && $3 < m { m = $3 } END { print m }' m=0 "$1"; }
splat -q "$E/mask.in" || fail "splat failed"
bleach -q -o full.bin image.cont "$E/resist.in" || fail "bleach failed"
etch -q -et 60 -o full.plot full.bin || fail "etch failed"
close "$(mindepth full.plot)" -0.7 1e-9 "deepest point at 80 mJ/cm2"
sed 's/^dose .*/dose 48/' "$E/resist.in" >low.in
bleach -q -o low.bin image.cont low.in || fail "bleach (48 mJ/cm2) failed"
etch -q -et 60 -o low.plot low.bin || fail "etch (48 mJ/cm2) failed"
d=$(mindepth low.plot)
awk -v d="$d" 'BEGIN { exit !(d > -0.6) }' || fail "at 48 mJ/cm2 the contact should not open (deepest point $d)"
echo "deepest point: 80 mJ/cm2 $(mindepth full.plot), 48 mJ/cm2 $d"
exit 0
