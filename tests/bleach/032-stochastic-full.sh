# The stochastic statement's bake full (bleach(5)): the ordinary,
# nonlinear bake of the noisy acid and quencher, on 030-stochastic.sh's
# EUV lines (16 nm at 32 nm pitch, 40 nm CA resist, 33 x 21 x 21 grid,
# G0 3 per nm^3, quencher 0.3):
#   - bake full writes the same bytes at -threads 1 and 2, and other bytes
#     than bake linear (and the default, which is bake linear byte for
#     byte);
#   - the ensemble mean of M over seeds 1 to 8 against the deterministic
#     run's (standard error from the 8 seeds' spread): bake full lies
#     below it by more than 2 standard errors (the neutralisation shift of
#     bleach(1), measured -6.4), bake linear within 4 (measured +0.3);
#   - a bad bake word, a missing or repeated one: one line naming the file
#     and line, exit 1, no rate file.
. "$TOP/tests/lib/common.sh"
printf '%s\n' 'wavelength 0.0135' 'na 0.33' 'dipole 0.64 0.2 x' 'background dark' \
	'window -0.016 0.016 -0.01 0.01' 'rect -0.008 -0.01 0.008 0.01' 'grid 33 5' \
	'contour image.cont' >mask.in
splat -q mask.in || fail "splat fails"
resist() { # resist [STATEMENT]
	printf '%s\n' 'wavelength 0.0135' 'resist thickness 0.040 index 0.97 dill 0.0 4.5 0.03' \
		'substrate 0.999 0.0018' 'standingwaves off' 'dose 30' \
		'car quencher 0.3 amplification 0.4 order 1 loss 0.002 quenching 20 pag 3' \
		'peb time 60 dacid 3e-7 dquencher 1e-7' 'develop mack 0.1 0.0002 0.5 12' \
		'grid nx 33 ny 21 nz 21' "${1:-}"
}
resist "stochastic seed 7 bake full" >full.in
resist "stochastic seed 7 bake linear" >lin.in
resist "stochastic seed 7" >def.in
bleach -q -threads 1 -o f1.bin image.cont full.in || fail "bleach fails on bake full"
bleach -q -threads 2 -o f2.bin image.cont full.in || fail "bleach -threads 2 fails on bake full"
same f1.bin f2.bin
bleach -q -o lin.bin image.cont lin.in || fail "bleach fails on bake linear"
bleach -q -o def.bin image.cont def.in || fail "bleach fails without a bake word"
same lin.bin def.bin
! cmp -s f1.bin lin.bin || fail "bake full and bake linear write the same rate file"

# the window mean of M in an ASCII rate file
mmean() {
	awk '/^[A-Za-z]/ { m = ($1 == "M"); next } NR > 3 && m { for (i = 1; i <= NF; i++) { s += $i; n++ } }
	     END { if (n != 33 * 21 * 21) exit 1; printf "%.12g\n", s / n }' "$1"
}
resist >det.in
bleach -q -ascii -o det.txt image.cont det.in || fail "bleach fails (deterministic)"
det=$(mmean det.txt) || fail "det.txt: not 33 x 21 x 21 values of M"
shift_se() { # shift_se BAKE: (mean over 8 seeds - deterministic) in standard errors
	for s in 1 2 3 4 5 6 7 8; do
		resist "stochastic seed $s bake $1" >e.in
		bleach -q -ascii -o e.txt image.cont e.in || fail "bleach fails at seed $s, bake $1"
		mmean e.txt || fail "e.txt: not 33 x 21 x 21 values of M"
	done >means.txt
	awk -v d="$det" '{ s += $1; s2 += $1 * $1; n++ }
		END { m = s / n; se = sqrt((s2 - n * m * m) / (n - 1) / n)
		      if (!(se > 0)) exit 1; printf "%.3f %.5f %.5f\n", (m - d) / se, m - d, se }' means.txt ||
		fail "bake $1: no spread over the 8 seeds"
}
full=$(shift_se full) || exit 1
lin=$(shift_se linear) || exit 1
echo "deterministic mean M $det; bake full: shift, in standard errors, mean - det, standard error: $full"
echo "bake linear: $lin"
awk -v f="${full%% *}" -v l="${lin%% *}" 'BEGIN { exit !(f < -2) }' ||
	fail "bake full: the ensemble mean of M is not below the deterministic M ($full)"
awk -v l="${lin%% *}" 'BEGIN { exit !(l <= 4 && l >= -4) }' ||
	fail "bake linear: the ensemble mean of M is not within 4 standard errors ($lin)"

rm -f rval.3D.binary
n=0
bad() { # bad 'what' 'statement'
	n=$((n + 1))
	resist "$2" >in.txt
	expect_file_error bleach in.txt -q image.cont in.txt
	[ ! -e rval.3D.binary ] || fail "case $n ($1): left rval.3D.binary"
	grep -q "in.txt:10:" err.txt || fail "case $n ($1): not on line 10: $(cat err.txt)"
	[ "$(wc -l <err.txt)" -eq 1 ] || fail "case $n ($1): not one line: $(cat err.txt)"
}
bad "bake nonlinear" "stochastic seed 1 bake nonlinear"
bad "bake without word" "stochastic seed 1 bake"
bad "bake twice" "stochastic seed 1 bake full bake linear"
grep -q "bake given twice" err.txt || fail "bake twice: $(cat err.txt)"
exit 0
