# Issue 18: standing waves shrink in the developed wall as the acid
# diffuses further.  180 nm spaces at KrF in the CA resist of
# examples/car-krf-lines on bare silicon (no anti-reflective layer, so
# the standing waves are strong), baked with Dh = 3e-6, 1e-5, 3e-5 um2/s
# (diffusion lengths sqrt(2 Dh t) = 19, 35, 60 nm against a standing-wave
# period of 70 nm), developed 40 s by fast marching (the ray-string gives
# 0.056, 0.034, 0.020 um: the same within 0.004).  The ripple is the
# peak-to-valley of the wall's x(z), z = -0.30 .. -0.10 um by 2.5 nm,
# about its straight-line fit (etch -cut y 0).  Measured: 0.060, 0.036,
# 0.020 um.  Checked: each ripple at most 0.8 of the one before, and the
# least diffused one over 0.04 um (the waves are there to be washed out:
# a bake that ignored Dh, or a wall that never reached the depth, fails).
. "$TOP/tests/lib/common.sh"
printf '%s\n' 'wavelength 0.248' 'na 0.68' 'sigma 0.75' 'background dark' \
	'window -0.18 0.18 -0.1 0.1' 'rect -0.09 -0.1 0.09 0.1' 'grid 19 3' 'contour image.cont' >mask.in
splat -q mask.in || fail "splat fails"
ripple() {   # ripple CUTFILE: peak-to-valley of the right wall about its fit
	for z in $(awk 'BEGIN { for (z = -0.30; z <= -0.0999; z += 0.0025) printf "%.4f ", z }'); do
		printf '%s ' "$z"
		awk -v C=0 -v Z0="$z" -v Z1="$z" -v DZ=1 -f "$TOP/tests/lib/halfwidth.awk" "$1"
	done | awk '{ z[NR] = $1; x[NR] = $2; sz += $1; sx += $2; szz += $1 * $1; szx += $1 * $2
		if ($2 < 0.05) short = 1 }
	END { n = NR; b = (n * szx - sz * sx) / (n * szz - sz * sz); a = (sx - b * sz) / n
		for (i = 1; i <= n; i++) { r = x[i] - a - b * z[i]
			if (i == 1 || r > hi) hi = r; if (i == 1 || r < lo) lo = r }
		if (short) print "open"; else printf "%.4f\n", hi - lo }'
}
prev=
for D in 3e-6 1e-5 3e-5; do
	printf '%s\n' 'wavelength 0.248' 'resist thickness 0.40 index 1.76 dill 0.0 0.45 0.040' \
		'substrate 1.57 3.57' 'dose 14' \
		'car quencher 0.15 amplification ARRHENIUS(1.33e10 0.80) order 1 loss 0.001 quenching 10' \
		"peb time 60 temperature 110 dacid $D dquencher 1e-6" \
		'develop enhanced 0.10 0.0002 0.004 5 13' 'grid nz 81' >resist.in
	bleach -q -o rate.bin image.cont resist.in || fail "bleach fails at Dh $D"
	etch -q -method fmm -et 40 -pt 40 -no2d -cut y 0 rate.bin || fail "etch fails at Dh $D"
	r=$(ripple curves.cut)
	echo "Dh $D um2/s: ripple $r um"
	case $r in open) fail "Dh $D: the space did not open down to z = -0.30 um" ;; esac
	if [ -z "$prev" ]; then
		awk -v r="$r" 'BEGIN { exit !(r > 0.04) }' || fail "Dh $D: ripple $r um, expected over 0.04"
	else
		awk -v r="$r" -v p="$prev" 'BEGIN { exit !(r <= 0.8 * p) }' ||
			fail "Dh $D: ripple $r um not below 0.8 x $prev um"
	fi
	prev=$r
done
exit 0
