# tests/golden/cases.sh - the small, fast cases whose outputs are kept as
# golden files in tests/golden/<case>/.  Sourced by the golden test
# (tests/sample3D/020-golden.sh) and by tests/regen.sh (make regen), so
# both run exactly the same commands.  Each case runs in the current
# directory and leaves curves.plot, curves.plot.2D and dataplot.ps.
GOLDEN_CASES="contact-small ridge"
GOLDEN_FILES="curves.plot curves.plot.2D dataplot.ps"

golden_case() {
	case $1 in
	contact-small)
		# the contact of examples/contact on a coarse 21x21x60 grid
		cat >mask.in <<'M'
wavelength 0.436
na 0.28
sigma 0.5
window -1.5 1.5 -1.5 1.5
grid 21 21
background dark
rect -0.625 -0.625 0.625 0.625
contour image.cont
M
		sed 's/^grid .*/grid nz 60/' "$TOP/examples/contact/resist.in" >resist.in
		sample3D -q -if mask.in -bf resist.in -et 40 -pt 20 -hidden -seg 0.3
		;;
	ridge)
		# thesis Figure 8.7's rate R = exp(-4 x^2)(1.05 - cos(2 pi z)), 1.5 s
		"$BUILD/tests/lib/mkrate" -o ridge.bin 21 5 41 -1 1 -0.2 0.2 -1 0 \
			'exp(-4*x^2)*(1.05-cos(2*pi*z))'
		etch -q -et 1.5 -pt 0.5 -seg 0.1 ridge.bin
		pdraw -noplot curves.plot
		;;
	*)
		echo "unknown golden case $1" >&2
		return 1
		;;
	esac
}
