# End to end (thesis Figure 8.18 against 8.16): post-exposure bake smooths
# the standing-wave ripples of the contact wall.  At Table 9.1's best dose
# for Olin Hunt 6512 (240 mJ/cm2) both contacts open in 30 s; along the cut
# y = 0 the right-hand wall between z = -0.6 and -0.1 um is measured by its
# excess total variation in x (sum |dx| - |net dx|; 0 for a monotone wall,
# tests/lib/ripple.awk).  Without bake it exceeds 0.05 um (measured 0.22);
# with bake it is below a third of that (measured 0).
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact
splat -q "$E/mask.in" || fail "splat failed"
for r in resist resist-nobake; do
	sed 's/^dose .*/dose 240/' "$E/$r.in" >$r.in
	bleach -q -o $r.bin image.cont $r.in || fail "bleach $r failed"
	etch -q -et 30 -cut y 0 -o $r.plot $r.bin || fail "etch $r failed"
done
bake=$(awk -v zlo=-0.6 -v zhi=-0.1 -f "$TOP/tests/lib/ripple.awk" resist.cut | cut -d' ' -f1)
nobake=$(awk -v zlo=-0.6 -v zhi=-0.1 -f "$TOP/tests/lib/ripple.awk" resist-nobake.cut | cut -d' ' -f1)
echo "wall ripple (excess variation, um): bake $bake, no bake $nobake"
awk -v n="$nobake" 'BEGIN { exit !(n > 0.05) }' || fail "no ripples without bake ($nobake)"
awk -v b="$bake" -v n="$nobake" 'BEGIN { exit !(b < n / 3) }' || fail "bake did not smooth the wall ($bake vs $nobake)"
exit 0
