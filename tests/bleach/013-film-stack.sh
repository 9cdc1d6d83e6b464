# bleach on an image stack through the film (splat -bf with imaging
# vector, the header word film): such a stack already holds the film's
# standing waves, so bleach divides them out by the unexposed film's 1D
# factor and counts them once.  Against the 1D bleach at normal
# incidence: a clear mask, coherent light (every plane wave normal), gives
# the same M as bleach on a plain clear image of 1:
#  - for a bleaching resist (A > 0) both runs use the same dose table at
#    the same dose, the ratio of the stack to the 1D factor being 1 to
#    rounding: M within 1e-12;
#  - for A = 0 the stack's M is the closed form exp(-C D I) and the plain
#    run's the dose table's Hermite interpolation (expose.c: ~1e-8): M
#    within 1e-7;
#  - without the film word (a plain stack of the same numbers) the film
#    would count twice: M differs by more than 1e-3 (the check can fail);
#  - a resist file with standingwaves off is refused for a film stack, in
#    one line naming the stack.
. "$TOP/tests/lib/common.sh"
cat >mask.in <<'IN'
wavelength 0.193
immersion 1.44
na 1.35
sigma 0
imaging vector
resist thickness 0.1 index 1.7 planes 21
window 0 0.2 0 0.2
background clear
grid 5 5
contour clear.stack
IN
resist() { # A
	cat <<IN
wavelength 0.193
ambient 1.44
resist thickness 0.1 index 1.7 dill $1 0.9 0.05
layer 0.08 1.82 0.34
substrate 0.88 2.78
dose 30
develop mack 0.1 0.0001 0.5 5
grid nz 41
IN
}
{ echo "0 0.2 0 0.2"; echo "5 5"; i=0; while [ $i -lt 25 ]; do echo 1; i=$((i + 1)); done; } >one.cont
values() { awk 'NR > 4 { for (i = 1; i <= NF; i++) print $i }' "$1"; }
maxdiff() { paste -d' ' "$1" "$2" | awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.3g\n", m + 0 }'; }
for A in 0.6 0; do
	resist $A >r$A.in
	splat -q -bf r$A.in mask.in || fail "splat -bf (A = $A)"
	sed -n 1p clear.stack | grep -q ' film$' || fail "no film word: $(sed -n 1p clear.stack)"
	bleach -q -ascii -o s.3D clear.stack r$A.in || fail "bleach on the film stack (A = $A)"
	bleach -q -ascii -o p.3D one.cont r$A.in || fail "bleach on a clear image (A = $A)"
	values s.3D >s.txt
	values p.3D >p.txt
	d=$(maxdiff s.txt p.txt)
	tol=1e-12
	[ "$A" = 0 ] && tol=1e-7
	echo "A = $A: film stack against the 1D bleach: M and rate within $d (tolerance $tol)"
	awk -v d="$d" -v t="$tol" 'BEGIN { exit !(d <= t) }' || fail "A = $A: $d beyond $tol"
done
# the same numbers as a plain stack: the film counted twice
sed '1s/ film$//' clear.stack >plain.stack
bleach -q -ascii -o d.3D plain.stack r0.in || fail "bleach on the plain stack"
values d.3D >d.txt
d=$(maxdiff d.txt p.txt)
awk -v d="$d" 'BEGIN { exit !(d > 1e-3) }' || fail "the film word changes nothing ($d)"
{ resist 0; echo "standingwaves off"; } >off.in
expect_error bleach -q -o x.3D clear.stack off.in
grep -q 'clear.stack:1: the image stack holds the film' err.txt || fail "$(cat err.txt)"
exit 0
