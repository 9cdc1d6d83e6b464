# fem's physics on the image inside the resist (splat's resist statement,
# an image stack): the isolated 0.5 um contact at NA 0.6, i-line, in 1 um of resist of
# tests/sample3D/030-bossung-stack.sh (11-plane image stack, fast-marching
# development 60 s), swept over foci -0.9:0.3:0.3 and doses 70, 90 mJ/cm2,
# with the bottom CD (5 % of the thickness above the substrate) from
# measure -hole.  Checked on fem.dat:
#  - the Bossung curves are not symmetric about focus 0: at each dose the CD
#    at focus -0.3 exceeds that at +0.3 by more than 0.05 um (measured:
#    0.186 and 0.095 um);
#  - the best focus (largest bottom CD) lies inside the resist, focus < 0
#    (measured: -0.6 um at both doses, about -depth/n for the bottom);
#  - CD grows with dose at every focus (measured: by 0.06-0.15 um);
#  - the process window for 0.53 um +- 10 % is centred inside the resist
#    (focus centre at 5 % EL < 0; measured -0.35 um).  The figures above
#    are those of the engines with the fast-marching bias removed (CDs
#    about 0.1 um larger than before, hence the target 0.53).
# 10 points on a 21 x 21 grid: about 2 s of CPU.
. "$TOP/tests/lib/common.sh"
built measure
cat >m.in <<'IN'
wavelength 0.365
na 0.6
sigma 0.5
background dark
window -1.2 1.2 -1.2 1.2
rect -0.25 -0.25 0.25 0.25
grid 21 21
resist thickness 1 index 1.7 planes 11
IN
splat -name m.in >/dev/null 2>err.txt || fail "splat refuses the image stack (resist statement): $(cat err.txt)"
cat >r.in <<'IN'
wavelength 0.365
resist thickness 1 index 1.7 dill 0.8 0.05 0.014
substrate 6.41 2.62
dose 80
bake diffusion 0.05
develop mack 0.1 0.0001 0.5 5
grid nz 61
IN
fem -q -if m.in -bf r.in -et 60 -method fmm -dose 70,90 -focus -0.9:0.3:0.3 \
	-measure "-rel 5,90 -hole 0 0" -target 0.53 -tol 10 -j 2 >window.txt || fail "fem failed"
cat fem/fem.dat window.txt
[ "$(grep -vc '^#' fem/fem.dat)" -eq 10 ] || fail "expected 10 points"
awk '!/^#/ && $5 != 1 { exit 1 }' fem/fem.dat || fail "every point should clear"
cd() { awk -v f="$1" -v d="$2" '!/^#/ && $1 == f && $2 == d { print $3 }' fem/fem.dat; }
for d in 70 90; do
	a=$(cd -0.3 $d) b=$(cd 0.3 $d)
	awk -v a="$a" -v b="$b" 'BEGIN { exit !(a - b > 0.05) }' ||
		fail "dose $d: cd at focus -0.3 ($a) is not 0.05 um above cd at +0.3 ($b)"
	best=$(awk -v d=$d '!/^#/ && $2 == d && $3 > m { m = $3; f = $1 } END { print f }' fem/fem.dat)
	echo "dose $d: best focus $best, cd(-0.3) - cd(+0.3) = $(awk -v a="$a" -v b="$b" 'BEGIN { print a - b }')"
	awk -v f="$best" 'BEGIN { exit !(f < 0) }' || fail "dose $d: the best focus $best is not inside the resist"
done
for f in -0.9 -0.6 -0.3 0 0.3; do
	awk -v a="$(cd $f 70)" -v b="$(cd $f 90)" 'BEGIN { exit !(b > a) }' ||
		fail "focus $f: cd does not grow with dose ($(cd $f 70) at 70, $(cd $f 90) at 90)"
done
fc=$(awk '$1 == 5 { print $3 }' fem/window.dat)
[ -n "$fc" ] || fail "no window at 5 % EL"
awk -v f="$fc" 'BEGIN { exit !(f < 0) }' || fail "the window's focus centre $fc is not inside the resist"
exit 0
