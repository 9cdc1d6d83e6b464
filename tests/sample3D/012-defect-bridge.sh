# End to end (thesis Figures 9.8-9.9): the 0.5 um opaque defect in the
# 1.3 um line/space array (examples/defect) after 30 s.  Kodak 820 at 80%
# of its best dose (88 mJ/cm2, Figure 9.9a) bridges: resist remains at the
# defect centre, more than 0.2 um above the substrate (z = -1.2 um;
# measured -0.81).  Olin Hunt 6512 at its best dose (240 mJ/cm2, Figure
# 9.8) does not: the defect centre clears to the substrate (z = -0.7, to
# 1e-6).  Heights from the cut y = 0 at |x| < 0.05 um.
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/defect
splat -q "$E/mask.in" || fail "splat failed"
centre() { awk 'NF == 0 { m = -9 } NF == 2 && $1 > -0.05 && $1 < 0.05 && $2 > m { m = $2 } END { print m }' m=-9 "$1"; }
for r in kodak820-88 olinhunt6512-240; do
	bleach -q -o $r.bin image.cont "$E/resist-$r.in" || fail "bleach $r failed"
	etch -q -et 30 -cut y 0 -o $r.plot $r.bin || fail "etch $r failed"
done
k=$(centre kodak820-88.cut)
o=$(centre olinhunt6512-240.cut)
echo "height at the defect centre: Kodak 820 88 mJ/cm2 $k, Olin Hunt 6512 240 mJ/cm2 $o"
awk -v k="$k" 'BEGIN { exit !(k > -1.0) }' || fail "Kodak 820 at 80% dose should bridge (z $k)"
close "$o" -0.7 1e-6 "Olin Hunt 6512 at best dose, defect centre"
exit 0
