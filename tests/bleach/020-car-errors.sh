# The car and peb statements of bleach(5): a good input runs and round-trips
# its ARRHENIUS values; each malformed one gives one line naming the file
# and line ("bleach: in.txt:N: ..."), exits 1 and leaves no rate file.
. "$TOP/tests/lib/common.sh"
printf '0 1 0 1\n2 2\n0.5 0.5 0.5 0.5\n' >clear.cont
good='wavelength 0.248
resist thickness 0.20 index 1.76 dill 0 0.45 0.04
substrate 1.57 3.57
dose 20
car quencher 0.1 amplification 0.5 order 1 loss 0.001 quenching 5
peb time 30 dacid 5e-6 dquencher 0 temperature 110
develop enhanced 0.1 0.0002 0.004 5 13
grid nz 41'
printf '%s\n' "$good" >in.txt
bleach -q clear.cont in.txt || fail "the good input fails"
# keyword pairs in any order, ARRHENIUS in either spacing
printf '%s\n' "$good" | sed 's/^car .*/car quenching 5 loss 0.001 order 1 amplification ARRHENIUS( 1e9 0.6 ) quencher 0.1/
s/^peb .*/peb temperature 110 dacid arrhenius(5e-6 0) time 30 dquencher 0/' >in2.txt
bleach -q -o r2 clear.cont in2.txt || fail "keywords in another order, ARRHENIUS, fail"
rm -f rval.3D.binary r2
n=0
bad() { # bad 'what' 'text'
	n=$((n + 1))
	printf '%s\n' "$2" >in.txt
	expect_file_error bleach in.txt -q clear.cont in.txt
	[ ! -e rval.3D.binary ] || fail "case $n ($1): left rval.3D.binary"
	:
}
edit() { printf '%s\n' "$good" | sed "$1"; }
bad "car without peb" "$(edit '/^peb/d')"
bad "peb without car" "$(edit '/^car/d')"
bad "car with bake" "$(edit '1a\
bake diffusion 0.05')"
bad "car with bake3d" "$(edit '1a\
bake3d diffusion 0.05')"
bad "car with crosslink" "$(edit '1a\
crosslink rate 1 energy 0 order 1 temperature 100 time 1')"
bad "car twice" "$(edit '/^car/p')"
bad "peb twice" "$(edit '/^peb/p')"
bad "missing quencher" "$(edit 's/quencher 0.1 //')"
bad "missing amplification" "$(edit 's/amplification 0.5 //')"
bad "missing order" "$(edit 's/order 1 //')"
bad "missing loss" "$(edit 's/loss 0.001 //')"
bad "missing quenching" "$(edit 's/ quenching 5//')"
bad "missing time" "$(edit 's/time 30 //')"
bad "missing dacid" "$(edit 's/dacid 5e-6 //')"
bad "missing dquencher" "$(edit 's/dquencher 0 //')"
bad "unknown car word" "$(edit 's/^car /car colour 3 /')"
bad "unknown peb word" "$(edit 's/^peb /peb colour 3 /')"
bad "value missing at the end" "$(edit 's/quenching 5/quenching/')"
bad "negative quencher" "$(edit 's/quencher 0.1/quencher -0.1/')"
bad "huge quencher" "$(edit 's/quencher 0.1/quencher 11/')"
bad "order zero" "$(edit 's/order 1/order 0/')"
bad "NaN amplification" "$(edit 's/amplification 0.5/amplification nan/')"
bad "negative loss" "$(edit 's/loss 0.001/loss -1/')"
bad "huge quenching" "$(edit 's/quenching 5/quenching 1e7/')"
bad "negative time" "$(edit 's/time 30/time -1/')"
bad "huge dacid" "$(edit 's/dacid 5e-6/dacid 2/')"
bad "diffusion length beyond ten thicknesses" "$(edit 's/dacid 5e-6/dacid 0.9/')"
bad "absolute zero" "$(edit 's/temperature 110/temperature -273.15/')"
bad "ARRHENIUS without temperature" "$(edit 's/ temperature 110//; s/amplification 0.5/amplification ARRHENIUS(1e9 0.6)/')"
bad "ARRHENIUS one number" "$(edit 's/amplification 0.5/amplification ARRHENIUS(1e9)/')"
bad "ARRHENIUS three numbers" "$(edit 's/amplification 0.5/amplification ARRHENIUS(1e9 0.6 2)/')"
bad "ARRHENIUS unclosed" "$(edit 's/amplification 0.5/amplification ARRHENIUS(1e9 0.6/')"
bad "ARRHENIUS negative energy" "$(edit 's/amplification 0.5/amplification ARRHENIUS(1e9 -0.6)/')"
bad "ARRHENIUS beyond the range" "$(edit 's/quenching 5/quenching ARRHENIUS(1e30 0.01)/')"
bad "ARRHENIUS on the order" "$(edit 's/order 1/order ARRHENIUS(1 0)/')"
bad "develop enhanced Rresin above Rmax" "$(edit 's/^develop .*/develop enhanced 0.1 0.0002 0.4 5 13/')"
bad "develop enhanced four values" "$(edit 's/^develop .*/develop enhanced 0.1 0.0002 0.004 5/')"
bad "develop notch Mth 1" "$(edit 's/^develop .*/develop notch 0.1 2.5e-5 1.5 1 13.5/')"
bad "develop notch n_notch 1" "$(edit 's/^develop .*/develop notch 0.1 2.5e-5 1.5 0.7 1/')"
bad "develop notch negative Rmax" "$(edit 's/^develop .*/develop notch -0.1 2.5e-5 1.5 0.7 13.5/')"
echo "$n malformed inputs refused"
exit 0
