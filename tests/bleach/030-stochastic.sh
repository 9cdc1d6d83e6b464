# The stochastic statement (bleach(5)) through the program, on EUV lines
# (16 nm at 32 nm pitch, dipole illumination) in a 40 nm CA resist, a
# 33 x 21 x 11 grid:
#   - car's pag alone changes nothing: the rate file is byte-identical to
#     the one without it;
#   - the same seed writes the same bytes at -threads 1, 2, 3 and with
#     SAMPLE3D_THREADS=2; another seed writes other bytes; -seed S writes
#     the bytes of the statement's seed S, and is an error without the
#     statement or out of range;
#   - the ensemble mean: the window mean of M over 8 seeds is within 4
#     standard errors (of the 8 seeds' spread) of the deterministic run's,
#     without a quencher (the bake linear in the acid) and with quencher
#     0.3 on 21 planes (the linear-noise bake of bleach(1): measured +0.30
#     standard errors, where the nonlinear bake of the noisy fields gave
#     -6.4);
#   - a malformed stochastic statement or pag value: one line naming the
#     file and line, exit 1, no rate file.
. "$TOP/tests/lib/common.sh"
printf '%s\n' 'wavelength 0.0135' 'na 0.33' 'dipole 0.64 0.2 x' 'background dark' \
	'window -0.016 0.016 -0.01 0.01' 'rect -0.008 -0.01 0.008 0.01' 'grid 33 5' \
	'contour image.cont' >mask.in
splat -q mask.in || fail "splat fails"
resist() { # resist PAG-PAIR Q0 [STATEMENT]
	printf '%s\n' 'wavelength 0.0135' 'resist thickness 0.040 index 0.97 dill 0.0 4.5 0.03' \
		'substrate 0.999 0.0018' 'standingwaves off' 'dose 30' \
		"car quencher $2 amplification 0.4 order 1 loss 0.002 quenching 20 $1" \
		'peb time 60 dacid 3e-7 dquencher 1e-7' 'develop mack 0.1 0.0002 0.5 12' \
		"grid nx 33 ny 21 nz ${NZ:-11}" "${3:-}"
}
resist "" 0.3 >plain.in
resist "pag 0.3" 0.3 >pag.in
bleach -q -o plain.bin image.cont plain.in || fail "bleach fails without pag"
bleach -q -o pag.bin image.cont pag.in || fail "bleach fails with pag"
same plain.bin pag.bin

resist "pag 0.3" 0.3 "stochastic seed 7" >s7.in
resist "pag 0.3" 0.3 "stochastic seed 8" >s8.in
bleach -q -threads 1 -o t1.bin image.cont s7.in || fail "bleach fails on the stochastic input"
for t in 2 3; do
	bleach -q -threads $t -o t$t.bin image.cont s7.in || fail "bleach -threads $t fails"
	same t1.bin t$t.bin
done
SAMPLE3D_THREADS=2 bleach -q -o te.bin image.cont s7.in || fail "SAMPLE3D_THREADS=2 fails"
same t1.bin te.bin
bleach -q -o s8.bin image.cont s8.in || fail "bleach fails with seed 8"
! cmp -s t1.bin s8.bin || fail "seeds 7 and 8 write the same rate file"
! cmp -s t1.bin pag.bin || fail "the stochastic run equals the deterministic one"
# -seed S replaces the statement's seed, byte for byte; it needs the statement
bleach -q -seed 8 -o o8.bin image.cont s7.in || fail "bleach -seed 8 fails"
same o8.bin s8.bin
expect_error bleach -q -seed 8 -o x.bin image.cont pag.in
grep -q "no stochastic statement" err.txt || fail "-seed without stochastic: $(cat err.txt)"
for v in -1 1.5 x 9007199254740992; do
	bleach -q -seed $v -o x.bin image.cont s7.in 2>err.txt
	[ $? -eq 2 ] || fail "-seed $v: expected a usage error (status 2)"
	[ ! -e x.bin ] || fail "-seed $v left x.bin"
done

# the window mean of M in an ASCII rate file
mmean() {
	awk '/^[A-Za-z]/ { m = ($1 == "M"); next } NR > 3 && m { for (i = 1; i <= NF; i++) { s += $i; n++ } }
	     END { if (n != 33 * 21 * nz) exit 1; printf "%.12g\n", s / n }' nz="${NZ:-11}" "$1"
}
ensemble() { # ensemble Q0: the mean of M over seeds 1 to 8 against the deterministic run
	resist "pag 3" "$1" >det.in
	bleach -q -ascii -o det.txt image.cont det.in || fail "bleach fails (deterministic, pag 3, quencher $1)"
	det=$(mmean det.txt) || fail "det.txt: not 33 x 21 x ${NZ:-11} values of M"
	for s in 1 2 3 4 5 6 7 8; do
		resist "pag 3" "$1" "stochastic seed $s" >e.in
		bleach -q -ascii -o e.txt image.cont e.in || fail "bleach fails at seed $s, quencher $1"
		mmean e.txt || fail "e.txt: not 33 x 21 x ${NZ:-11} values of M"
	done >means.txt
	awk -v d="$det" -v q="$1" '{ s += $1; s2 += $1 * $1; n++ }
		END { m = s / n; se = sqrt((s2 - n * m * m) / (n - 1) / n)
		      printf "quencher %s: deterministic mean M %.5f, 8 seeds %.5f, standard error %.5f (%.2f of them)\n",
			     q, d, m, se, (m - d) / se
		      exit !(se > 0 && (m - d) <= 4 * se && (d - m) <= 4 * se) }' means.txt ||
		fail "quencher $1: the ensemble mean of M is not within 4 standard errors of the deterministic M"
}
ensemble 0
# on 21 planes: the nonlinear bake's shift was -6.4 standard errors there
NZ=21
ensemble 0.3
unset NZ

rm -f rval.3D.binary
n=0
bad() { # bad 'what' 'text'
	n=$((n + 1))
	printf '%s\n' "$2" >in.txt
	expect_file_error bleach in.txt -q image.cont in.txt
	[ ! -e rval.3D.binary ] || fail "case $n ($1): left rval.3D.binary"
	grep -q "in.txt:$3:" err.txt || fail "case $n ($1): not on line $3: $(cat err.txt)"
}
bad "stochastic without pag" "$(resist "" 0.3 "stochastic seed 1")" 10
bad "stochastic without car" "$(resist "" 0.3 "stochastic seed 1" | sed '/^car/d; /^peb/d')" 8
bad "no seed" "$(resist "pag 0.3" 0.3 "stochastic photons on")" 10
bad "negative seed" "$(resist "pag 0.3" 0.3 "stochastic seed -1")" 10
bad "fractional seed" "$(resist "pag 0.3" 0.3 "stochastic seed 1.5")" 10
bad "seed above 2^53" "$(resist "pag 0.3" 0.3 "stochastic seed 9007199254740992")" 10
bad "seed twice" "$(resist "pag 0.3" 0.3 "stochastic seed 1 seed 2")" 10
bad "photons maybe" "$(resist "pag 0.3" 0.3 "stochastic seed 1 photons maybe")" 10
bad "acid without value" "$(resist "pag 0.3" 0.3 "stochastic seed 1 acid")" 10
bad "both off" "$(resist "pag 0.3" 0.3 "stochastic seed 1 photons off acid off")" 10
bad "unknown word" "$(resist "pag 0.3" 0.3 "stochastic seed 1 electrons on")" 10
bad "stochastic twice" "$(resist "pag 0.3" 0.3 "stochastic seed 1"; echo "stochastic seed 2")" 11
bad "pag 0" "$(resist "pag 0" 0.3)" 6
bad "pag nan" "$(resist "pag nan" 0.3)" 6
bad "pag missing" "$(resist "pag" 0.3)" 6
bad "pag twice" "$(resist "pag 0.3 pag 0.4" 0.3)" 6
exit 0
