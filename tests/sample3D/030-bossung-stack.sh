# The Bossung asymmetry that the image inside the resist brings
# (splat's resist statement): an isolated 0.5 um contact at NA 0.6, i-line, sigma 0.5, in 1 um of
# resist (index 1.7, Dill 0.8 0.05 0.014 on silicon, 0.05 um bake, Mack
# development), exposed at 80 mJ/cm2 and developed 60 s (fast marching);
# the bottom CD is measured 5% of the thickness above the substrate with
# measure -hole.  Without a resist statement the images at defocus -0.3
# and +0.3 agree to rounding, 1e-12 (the old symmetric Bossung curve); with the
# 11-plane stack the developed bottom CD must differ between them by more
# than 0.05 um, the larger at d = -0.3, and of the foci -0.9, -0.6, -0.3,
# 0, +0.3 the one with the largest bottom CD must lie inside the resist
# (d < 0).  Measured when written (41 x 41 image over 2.4 um, nz 61):
# bottom CD 0.480, 0.496, 0.494, 0.474, 0.395 um at d = -0.9, -0.6, -0.3,
# 0, +0.3; the margin at +-0.3 is 0.099 um, the best focus -0.6 um (about
# -depth/n for the resist's bottom at 1 um, n 1.7).  The grid is coarse
# for speed (2.4 s): at 0.03 um spacing the CDs are ~0.04 um larger, the
# margin the same (examples/contact-highna).
. "$TOP/tests/lib/common.sh"
built measure
cat >m.in <<'IN'
wavelength 0.365
na 0.6
sigma 0.5
background dark
window -1.2 1.2 -1.2 1.2
rect -0.25 -0.25 0.25 0.25
grid 41 41
contour img.cont
IN
cat >r.in <<'IN'
wavelength 0.365
resist thickness 1 index 1.7 dill 0.8 0.05 0.014
substrate 6.41 2.62
dose 80
bake diffusion 0.05
develop mack 0.1 0.0001 0.5 5
grid nz 61
IN
# the single image: defocus sign does not matter
splat -q -defocus -0.3 -o minus.cont m.in || fail "splat -defocus -0.3"
splat -q -defocus 0.3 -o plus.cont m.in || fail "splat -defocus 0.3"
paste minus.cont plus.cont | awk 'NR > 2 { d = $1 - $2; if (d < 0) d = -d; if (d > w) w = d }
	END { printf "single image: defocus -0.3 and +0.3 differ by %.3g\n", w; exit !(w <= 1e-12) }' ||
	fail "the single images at defocus -0.3 and +0.3 differ"
# the stack
echo "resist thickness 1 index 1.7 planes 11" >>m.in
best= bestcd=0
for d in -0.9 -0.6 -0.3 0 0.3; do
	splat -q -defocus $d m.in || fail "splat -defocus $d"
	bleach -q img.cont r.in || fail "bleach at defocus $d"
	etch -q -method fmm -et 60 rval.3D.binary || fail "etch at defocus $d"
	measure -rel 5 -hole 0 0 curves.plot >cd.txt || fail "measure at defocus $d: $(cat cd.txt)"
	grep -q '^# cleared yes' cd.txt || fail "defocus $d: the contact does not clear"
	cd=$(awk '!/^#/ { print $2; exit }' cd.txt)
	echo "defocus $d: bottom CD $cd um"
	eval "cd_$(echo $d | tr -- '-.' 'm_')=$cd"
	if awk -v a="$cd" -v b="$bestcd" 'BEGIN { exit !(a > b) }'; then best=$d bestcd=$cd; fi
done
echo "best focus $best (bottom CD $bestcd um); d = -0.3: $cd_m0_3, d = +0.3: $cd_0_3"
awk -v a="$cd_m0_3" -v b="$cd_0_3" 'BEGIN { exit !(a - b > 0.05) }' ||
	fail "bottom CD at d = -0.3 ($cd_m0_3) is not 0.05 um above d = +0.3 ($cd_0_3)"
awk -v d="$best" 'BEGIN { exit !(d < 0) }' || fail "the best focus $best is not inside the resist"
exit 0
