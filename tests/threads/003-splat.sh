# splat's output does not depend on the thread count: a 5 um
# window at i-line NA 0.6 sigma 0.5 (481 orders: the pair loop's rows
# split at 64 pairs, the Abbe FFT's 25 columns and 50 rows at 8, the
# image's rows in blocks of 16 per thread), with a cutline and, in a
# second input (2.5 um, 121 orders: its pair rows too short to split, its
# FFTs and image rows split), a two-plane image stack with defocus and
# coma; both methods with 1, 2 and 3 threads (-threads, and SAMPLE3D_THREADS once),
# every output compared byte for byte.  The two methods differ (the
# Abbe source cells), so they are also checked not to be byte-identical
# to each other (the method option is really used).
. "$TOP/tests/lib/common.sh"
cat >a.in <<'IN'
wavelength 0.365
na 0.6
sigma 0.5
background dark
window 0 5 0 5
rect 0.25 0.25 0.75 0.75
rect 1.25 0.25 1.75 0.75
rect 2.25 1.25 2.75 1.75
rect 3.1 3.1 4.4 4.2
grid 41 41
cutline 0 2.5 5 2.5 51 cut.2D
IN
cat >b.in <<'IN'
wavelength 0.365
na 0.6
sigma 0.5
window 0 2.5 0 2.5
rect 0.25 0.25 0.75 0.75
rect 1.1 1.1 2.2 1.9
grid 41 41
defocus 0.4
coma 0.1 field 1 0
resist thickness 0.8 index 1.7 planes 2
IN
for m in hopkins abbe; do
	for t in 1 2 3; do
		splat -q -method $m -threads $t -o a-$m-$t.cont a.in || fail "splat -method $m -threads $t failed"
		mv cut.2D cut-$m-$t.2D
		splat -q -method $m -threads $t -o b-$m-$t.stack b.in || fail "splat -method $m -threads $t (stack) failed"
	done
	SAMPLE3D_THREADS=2 splat -q -method $m -o a-$m-env.cont a.in || fail "SAMPLE3D_THREADS=2 splat failed"
	for t in 2 3 env; do same a-$m-1.cont a-$m-$t.cont; done
	for t in 2 3; do
		same cut-$m-1.2D cut-$m-$t.2D
		same b-$m-1.stack b-$m-$t.stack
	done
done
cmp -s a-hopkins-1.cont a-abbe-1.cont && fail "-method abbe gave the hopkins image byte for byte"
splat -q -method fast a.in 2>err.txt && fail "-method fast accepted"
grep -q 'method' err.txt || fail "bad -method: $(cat err.txt)"
splat -q -threads 0 a.in 2>err.txt && fail "-threads 0 accepted"
exit 0
