# calib recovers known resist parameters from synthetic CDs: the 0.5 um
# contact at NA 0.6 of tests/fem/004-physics.sh (21 x 21 grid, fast
# marching, bottom CD at 5 % of the thickness), CDs made by fem with the
# Mack threshold Mth 0.5 and exponent n 5, plus fixed offsets of about 1 nm
# (sd 0.88 nm) standing for measurement noise; the fit starts from Mth
# 0.47, n 4.5.  Checked:
#  - each value within 5 % of the truth or 3 stderr, its stderr positive,
#    finite and under 10 % of the value;
#  - rms_nm between 0.3 and 1.5 nm (the noise's own rms is 0.88 nm);
#  - the reported rms equals, within 0.05 nm, an independent re-simulation
#    of resist.fit.in as written: a full fem matrix in another directory
#    (its own images, no -points), matched to the data by awk;
#  - resist.fit.in differs from the start file on the develop line only,
#    and holds the values calib.dat reports, as strings;
#  - the validation rms on three other points is under 1.5 nm;
#  - the pictures are written;
#  - the same command again is resumed: no simulation runs (no new run
#    directory) and calib.dat comes out byte for byte the same.
. "$TOP/tests/lib/common.sh"
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
cat >truth.in <<'IN'
# the process that made the data
wavelength 0.365
resist thickness 1 index 1.7 dill 0.8 0.05 0.014
substrate 6.41 2.62
dose 80
bake diffusion 0.05
develop mack 0.1 0.0001 0.5 5
grid nz 41
IN
sed 's/mack 0.1 0.0001 0.5 5/mack 0.1 0.0001 0.47 4.5/' truth.in >start.in
M="-rel 5 -hole 0 0"
FOCI=-0.6,-0.2,0.2 DOSES=70,80,90
fem -q -if m.in -bf truth.in -et 60 -method fmm -focus $FOCI -dose $DOSES -measure "$M" \
	-d truth -j 2 || fail "fem on the truth failed"
fem -q -if m.in -bf truth.in -et 60 -method fmm -points -0.4:75,0:85,0.2:75 -measure "$M" \
	-d vtruth -j 2 || fail "fem on the validation points failed"
# the offsets, nm, in row order
noise() { awk -v off="$1" 'BEGIN { n = split(off, o, " ") } !/^#/ { k++; printf "%s %s %.6f\n", $1, $2, $3 + o[k] / 1000 }' "$2"; }
noise "0.9 -1.2 0.4 1.3 -0.7 -0.8 1.1 -0.3 0.6" truth/fem.dat >meas.dat
noise "-0.5 1.0 0.7" vtruth/fem.dat >val.dat
[ "$(wc -l <meas.dat)" -eq 9 ] && [ "$(wc -l <val.dat)" -eq 3 ] || fail "expected 9 and 3 points"

run() {
	calib -q -if m.in -bf start.in -et 60 -data meas.dat -measure "$M" \
		-free "develop 3 0.3:0.7" -free "develop 4 2:12" -validate val.dat -j 2 2>calib.err
}
run || fail "calib failed: $(cat calib.err)"
cat calib/calib.dat
row() { awk -v k="$1" '$1 == "develop" && $2 == k { print $3, $4 }' calib/calib.dat; }
check() { # check K TRUTH
	set -- "$1" "$2" $(row "$1")
	[ $# -eq 4 ] || fail "no row develop $1 in calib.dat"
	awk -v t="$2" -v v="$3" -v s="$4" 'BEGIN { d = v - t; if (d < 0) d = -d
		exit !(s > 0 && s < 1e300 && s < 0.1 * v && (d <= 0.05 * t || d <= 3 * s)) }' ||
		fail "develop $1: $3 +- $4, truth $2"
	echo "develop $1: $3 +- $4 (truth $2)"
}
check 3 0.5
check 4 5
rms=$(awk '$1 == "#" && $2 == "rms_nm" { print $3 }' calib/calib.dat)
vrms=$(awk '$1 == "#" && $2 == "validate_rms_nm" { print $3 }' calib/calib.dat)
[ -n "$rms" ] && [ -n "$vrms" ] || fail "no rms_nm or validate_rms_nm line"
awk -v r="$rms" 'BEGIN { exit !(r >= 0.3 && r <= 1.5) }' || fail "rms $rms nm outside [0.3, 1.5]"
awk -v r="$vrms" 'BEGIN { exit !(r < 1.5) }' || fail "validation rms $vrms nm not under 1.5"

fem -q -if m.in -bf calib/resist.fit.in -et 60 -method fmm -focus $FOCI -dose $DOSES \
	-measure "$M" -d resim -j 2 || fail "re-simulation failed"
resim=$(awk 'NR == FNR { if (!/^#/) m[$1 " " $2] = $3; next }
	!/^#/ && ($1 " " $2) in m { d = $3 - m[$1 " " $2]; s += d * d; n++ }
	END { if (n != 9) exit 1; printf "%.6f", 1000 * sqrt(s / n) }' meas.dat resim/fem.dat) ||
	fail "the re-simulation does not cover the 9 points"
close "$rms" "$resim" 0.05 "calib's rms against the re-simulation of resist.fit.in"
echo "rms $rms nm, re-simulated $resim nm, validation $vrms nm"

diff start.in calib/resist.fit.in >d.txt && fail "resist.fit.in is the start file"
[ "$(grep -c '^[<>]' d.txt)" -eq 2 ] && grep -q '^> develop mack 0.1 0.0001 ' d.txt ||
	fail "resist.fit.in changed more than the develop line: $(cat d.txt)"
[ "$(awk '/^develop/ { print $5, $6 }' calib/resist.fit.in)" = "$(row 3 | cut -d' ' -f1) $(row 4 | cut -d' ' -f1)" ] ||
	fail "resist.fit.in does not hold calib.dat's values"
for f in bossung.ps bossung.svg residuals.ps residuals.svg; do
	[ -s "calib/$f" ] || fail "calib/$f missing"
done

cp calib/calib.dat first.dat
n1=$(ls calib/runs | wc -l)
run || fail "calib again failed: $(cat calib.err)"
[ "$(ls calib/runs | wc -l)" -eq "$n1" ] || fail "the rerun made new runs"
same calib/calib.dat first.dat
exit 0
