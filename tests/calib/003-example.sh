# examples/calibrate runs end to end through its README's command as
# printed, "sh calibrate.sh" (tests/lib/examples.sh, example_readme: fem
# makes the "measured" CDs, 3 foci x 2 doses, from the hidden process,
# hidden.in, adding fixed offsets of about 1 nm (rms 0.86 nm) for
# measurement noise; calib fits Mth and n of the start file resist.in to
# the 6 points and validates on 4 others), and calib recovers the hidden
# values.  Checked:
#  - the README's "Calibrate to measured CDs" table is the example's
#    output: the table rows and the rms line of README.md equal table.txt,
#    character for character (the simulations are deterministic, so any
#    difference is a change to explain);
#  - each fitted value within 5 % of the hidden one, its stderr positive,
#    finite and under 10 % of the value;
#  - rms_nm between 0.3 and 1.5 nm (the noise's own rms is 0.86 nm) and
#    the validation rms under 1.5 nm;
#  - the reported rms equals, within 0.05 nm, an independent
#    re-simulation of resist.fit.in as written (the README: "the rms is
#    that of fem run on it as written"): a full fem matrix of the measured
#    foci and doses in another directory (its own images, no -points),
#    matched to the data by awk;
#  - resist.fit.in differs from the start file on the develop line only,
#    and holds the values calib.dat reports, as strings;
#  - the pictures are written;
#  - the same command again is resumed: no simulation runs (no new run
#    directory) and calib.dat comes out byte for byte the same.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/examples.sh"
example_readme calibrate
ex=tree/examples/calibrate/out
cat $ex/table.txt
grep '^|\|^rms ' $ex/table.txt >got.txt
awk '/^## Calibrate to measured CDs/ { f = 1; next } /^## / { f = 0 }
	f && (/^\|/ || /^rms /)' "$TOP/README.md" >readme.txt
[ -s readme.txt ] || fail "README.md has no table under \"## Calibrate to measured CDs\""
same got.txt readme.txt
awk -F'|' 'NR > 2 && NF > 5 { h = $3 + 0; v = $5 + 0; d = v - h; if (d < 0) d = -d
	if (!(d <= 0.05 * h)) { print "far: " $0; bad = 1 } } END { exit bad }' $ex/table.txt ||
	fail "a fitted value is not within 5 % of the hidden one"

dat=$ex/calib/calib.dat
row() { awk -v k="$1" '$1 == "develop" && $2 == k { print $3, $4 }' "$dat"; }
for k in 3 4; do
	set -- $(row $k)
	[ $# -eq 2 ] || fail "no row develop $k in calib.dat"
	awk -v v="$1" -v s="$2" 'BEGIN { exit !(s > 0 && s < 1e300 && s < 0.1 * v) }' ||
		fail "develop $k: $1 +- $2: stderr not positive or over 10 %"
done
rms=$(awk '$1 == "#" && $2 == "rms_nm" { print $3 }' "$dat")
vrms=$(awk '$1 == "#" && $2 == "validate_rms_nm" { print $3 }' "$dat")
[ -n "$rms" ] && [ -n "$vrms" ] || fail "no rms_nm or validate_rms_nm line"
awk -v r="$rms" 'BEGIN { exit !(r >= 0.3 && r <= 1.5) }' || fail "rms $rms nm outside [0.3, 1.5]"
awk -v r="$vrms" 'BEGIN { exit !(r < 1.5) }' || fail "validation rms $vrms nm not under 1.5"

# the re-simulation: the measured points' foci and doses as a full matrix
E=tree/examples/calibrate
list() { awk -v c="$1" '!/^#/ && !($c in s) { s[$c]; l = l (l == "" ? "" : ",") $c } END { print l }' \
	$ex/measured.dat; }
fem -q -if $E/mask.in -bf $ex/calib/resist.fit.in -et 60 -method fmm -focus "$(list 1)" \
	-dose "$(list 2)" -measure "-rel 5 -hole 0 0" -d resim -j 2 || fail "re-simulation failed"
npts=$(grep -vc '^#' $ex/measured.dat)
resim=$(awk -v n="$npts" 'NR == FNR { if (!/^#/) m[$1 " " $2] = $3; next }
	!/^#/ && ($1 " " $2) in m { d = $3 - m[$1 " " $2]; s += d * d; k++ }
	END { if (k != n) exit 1; printf "%.6f", 1000 * sqrt(s / k) }' $ex/measured.dat resim/fem.dat) ||
	fail "the re-simulation does not cover the $npts points"
close "$rms" "$resim" 0.05 "calib's rms against the re-simulation of resist.fit.in"
echo "rms $rms nm, re-simulated $resim nm, validation $vrms nm"

diff $E/resist.in $ex/calib/resist.fit.in >d.txt && fail "resist.fit.in is the start file"
[ "$(grep -c '^[<>]' d.txt)" -eq 2 ] && grep -q '^> develop mack ' d.txt ||
	fail "resist.fit.in changed more than the develop line: $(cat d.txt)"
[ "$(awk '/^develop/ { print $5, $6 }' $ex/calib/resist.fit.in)" = "$(row 3 | cut -d' ' -f1) $(row 4 | cut -d' ' -f1)" ] ||
	fail "resist.fit.in does not hold calib.dat's values"
for f in bossung.ps bossung.svg residuals.ps residuals.svg; do
	[ -s "$ex/calib/$f" ] || fail "calib/$f missing"
done

cp "$dat" first.dat
n1=$(ls $ex/calib/runs | wc -l)
example_readme calibrate
[ "$(ls $ex/calib/runs | wc -l)" -eq "$n1" ] || fail "the rerun made new runs"
same "$dat" first.dat
exit 0
