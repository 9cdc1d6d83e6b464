# calib -accuracy and fem -grid: the fit runs at one grid, chosen before
# it, and the fitted CDs carry an error estimate.  The 0.5 um contact at
# NA 0.6 of tests/calib/002-recovery.sh (here on an 11 x 11 image grid,
# nz 41), three points made by fem with Mack's Mth 0.5 (at 21 x 21 x 81
# for the first fit, at the inputs' grid for the second), fitted from 0.498
# (two iterations each):
#  - calib -accuracy 30 chooses the grid with fem -accuracy 30 at the
#    middle point (DIR/accuracy, its levels' tables there): 21 x 21 x 81,
#    finer than the inputs' (the estimate at 11 x 11 x 41 is over 30 %;
#    the test checks that the choice is not the inputs' grid, so that a
#    trial run at the inputs' grid cannot pass for one at the choice);
#    every trial's Makefile runs that grid (SPLATGRID, BLEACHNZ), the one
#    the choice wrote in accuracy.opts; the result is estimated by fem
#    -accuracy check (DIR/accuracy-result: every point's table has err),
#    and either every err is within 30 % of its cd or calib warns that it
#    is not (the inputs' grid was 21 x 21 and P 10, which chose 41 x 41 x
#    81: the same checks at 3 times the CPU);
#  - -accuracy check: the trials at the inputs' grids (no SPLATGRID), the
#    estimate on the result all the same;
#  - fem -grid "NX NY NZ" writes that grid into the Makefile (fem -n);
#    a malformed -grid, or -grid with -accuracy P, is a usage error (2);
#    calib -accuracy 0, and -accuracy 2 with -slurm, are usage errors (2).
. "$TOP/tests/lib/common.sh"
cat >m.in <<'IN'
wavelength 0.365
na 0.6
sigma 0.5
background dark
window -1.2 1.2 -1.2 1.2
rect -0.25 -0.25 0.25 0.25
grid 11 11
resist thickness 1 index 1.7 planes 11
IN
cat >truth.in <<'IN'
wavelength 0.365
resist thickness 1 index 1.7 dill 0.8 0.05 0.014
substrate 6.41 2.62
dose 80
bake diffusion 0.05
develop mack 0.1 0.0001 0.5 5
grid nz 41
IN
sed "s/mack 0.1 0.0001 0.5 5/mack 0.1 0.0001 0.498 5/" truth.in >start.in
M="-rel 5 -hole 0 0"

fem -q -n -if m.in -bf truth.in -et 60 -points 0:80 -measure "$M" -d fixed -grid "33 33 61" ||
	fail "fem -n -grid"
grep -qx 'SPLATGRID = -grid 33 33' fixed/Makefile && grep -qx 'BLEACHNZ = -nz 61' fixed/Makefile ||
	fail "fem -grid: $(grep -E 'GRID|NZ' fixed/Makefile)"
for g in "33 33" "33 33 x" "1 33 61" "33 33 61 5"; do
	st=0
	fem -q -n -if m.in -bf truth.in -et 60 -points 0:80 -measure "$M" -d bad -grid "$g" 2>/dev/null || st=$?
	[ $st -eq 2 ] || fail "fem -grid \"$g\": exit $st, expected 2"
done
st=0
fem -q -if m.in -bf truth.in -et 60 -points 0:80 -measure "$M" -d bad -grid "33 33 61" -accuracy 2 2>/dev/null || st=$?
[ $st -eq 2 ] || fail "fem -grid with -accuracy 2: exit $st, expected 2"

# the data at the grid each fit runs (-accuracy 30's choice, the inputs'
# for -accuracy check), so that both fits are short
fem -q -if m.in -bf truth.in -et 60 -points -0.2:75,0:80,0.2:85 -measure "$M" -d truth -j 2 \
	-grid "21 21 81" ||
	fail "fem on the truth"
fem -q -if m.in -bf truth.in -et 60 -points -0.2:75,0:80,0.2:85 -measure "$M" -d truth-in -j 2 ||
	fail "fem on the truth at the inputs' grid"
awk '!/^#/ { print $1, $2, $3 }' truth/fem.dat >meas.dat
awk '!/^#/ { print $1, $2, $3 }' truth-in/fem.dat >meas-in.dat
[ "$(wc -l <meas.dat)" -eq 3 ] && [ "$(wc -l <meas-in.dat)" -eq 3 ] ||
	fail "expected 3 points: $(cat meas.dat meas-in.dat)"

for a in 0 x; do
	st=0
	calib -q -if m.in -bf start.in -et 60 -data meas.dat -measure "$M" -free "develop 3 0.3:0.7" \
		-accuracy $a 2>/dev/null || st=$?
	[ $st -eq 2 ] || fail "calib -accuracy $a: exit $st, expected 2"
done
st=0
calib -q -if m.in -bf start.in -et 60 -data meas.dat -measure "$M" -free "develop 3 0.3:0.7" \
	-accuracy 2 -slurm 2>/dev/null || st=$?
[ $st -eq 2 ] || fail "calib -accuracy 2 -slurm: exit $st, expected 2"

# result DIR P: every point of DIR/accuracy-result has err; within P % or a warning in DIR.err
result() {
	n=0
	for t in "$1"/accuracy-result/f*/d*/measure.dat; do
		head -n 1 "$t" | grep -q ' err$' || fail "$t: no err column"
		n=$((n + 1))
	done
	[ $n -eq 3 ] || fail "$1/accuracy-result: $n points, expected 3"
	if cat "$1"/accuracy-result/f*/d*/measure.dat | awk -v p="$2" '!/^#/ && $NF > p / 100 * $2 { exit 1 }'; then
		grep -q 'warning' "$1.err" && fail "$1: a warning with every err within $2 %: $(cat "$1.err")"
	else
		grep -q "^calib: warning: the fitted CDs' estimated discretisation error is up to" "$1.err" ||
			fail "$1: an err over $2 % and no warning: $(cat "$1.err")"
	fi
}
calib -q -if m.in -bf start.in -et 60 -data meas.dat -measure "$M" -free "develop 3 0.3:0.7" \
	-accuracy 30 -d acc -j 2 2>acc.err || fail "calib -accuracy 30: $(cat acc.err)"
[ -n "$(ls acc/accuracy/accuracy/*.dat)" ] || fail "no levels in acc/accuracy/accuracy"
g=$(awk '{ print $3, $4, $5 }' acc/accuracy/accuracy.opts)
set -- $g
[ $# -eq 3 ] || fail "the grid chosen: \"$g\""
[ "$g" != "11 11 41" ] || fail "-accuracy 30 chose the inputs' grid: the test no longer tells them apart"
for mk in acc/runs/*/Makefile; do
	grep -qx "SPLATGRID = -grid $1 $2" "$mk" && grep -qx "BLEACHNZ = -nz $3" "$mk" ||
		fail "$mk: not the grid chosen ($g): $(grep -E 'GRID|NZ' "$mk")"
done
result acc 30
calib -q -if m.in -bf start.in -et 60 -data meas-in.dat -measure "$M" -free "develop 3 0.3:0.7" \
	-accuracy check -d chk -j 2 2>chk.err || fail "calib -accuracy check: $(cat chk.err)"
grep -l '^SPLATGRID =' chk/runs/*/Makefile && fail "-accuracy check: a trial not at the inputs' grids"
result chk 1
exit 0
