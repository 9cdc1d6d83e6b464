# Standing waves shrink in the developed wall as the acid
# diffuses further.  180 nm spaces at KrF in the CA resist of
# examples/car-krf-lines on bare silicon (no anti-reflective layer, so
# the standing waves are strong), baked with Dh = 3e-6, 1e-5, 3e-5 um2/s
# (diffusion lengths sqrt(2 Dh t) = 19, 35, 60 nm against a standing-wave
# period of 70 nm), developed 40 s by fast marching (the ray-string gives
# peak-to-valley wall ripples of 0.056, 0.034, 0.020 um against fast
# marching's 0.060, 0.036, 0.020).  The ripple measured is ripple.awk's
# excess total variation of the right wall's x between z = -0.30 and
# -0.10 um (etch -cut y 0), about twice the peak-to-valley a period:
# 0.355, 0.215, 0.111 um.  Checked: each at most 0.8 of the one before,
# and the least diffused one over 0.2 um (the waves are there to be
# washed out: a bake that ignored Dh, or a wall that never reached the
# depth, fails).
. "$TOP/tests/lib/common.sh"
printf '%s\n' 'wavelength 0.248' 'na 0.68' 'sigma 0.75' 'background dark' \
	'window -0.18 0.18 -0.1 0.1' 'rect -0.09 -0.1 0.09 0.1' 'grid 19 3' 'contour image.cont' >mask.in
splat -q mask.in || fail "splat fails"
prev=
for D in 3e-6 1e-5 3e-5; do
	printf '%s\n' 'wavelength 0.248' 'resist thickness 0.40 index 1.76 dill 0.0 0.45 0.040' \
		'substrate 1.57 3.57' 'dose 14' \
		'car quencher 0.15 amplification ARRHENIUS(1.33e10 0.80) order 1 loss 0.001 quenching 10' \
		"peb time 60 temperature 110 dacid $D dquencher 1e-6" \
		'develop enhanced 0.10 0.0002 0.004 5 13' 'grid nz 81' >resist.in
	bleach -q -o rate.bin image.cont resist.in || fail "bleach fails at Dh $D"
	etch -q -method fmm -et 40 -pt 40 -no2d -cut y 0 rate.bin || fail "etch fails at Dh $D"
	set -- $(awk -v zlo=-0.30 -v zhi=-0.10 -f "$TOP/tests/lib/ripple.awk" curves.cut)
	r=${1:-0}
	echo "Dh $D um2/s: ripple $r um over ${2:-0} wall points"
	[ "${2:-0}" -ge 100 ] || fail "Dh $D: the wall has ${2:-0} points between z = -0.30 and -0.10 um"
	if [ -z "$prev" ]; then
		awk -v r="$r" 'BEGIN { exit !(r > 0.2) }' || fail "Dh $D: ripple $r um, expected over 0.2"
	else
		awk -v r="$r" -v p="$prev" 'BEGIN { exit !(r <= 0.8 * p) }' ||
			fail "Dh $D: ripple $r um not below 0.8 x $prev um"
	fi
	prev=$r
done
exit 0
