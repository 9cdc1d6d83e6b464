# Malformed bleach input files and contour-files: each gives one line on
# stderr naming the file and line ("bleach: in.txt:N: ..."), exits 1,
# does not crash (under the sanitizers too) and leaves no rate file.
. "$TOP/tests/lib/common.sh"
printf '0 1 0 1\n2 2\n1 1 1 1\n' >clear.cont
good='wavelength 0.436
resist thickness 0.70 index 1.68 dill 0.64 0.040 0.010
substrate 4.73 0.14
dose 240
develop kim 0.062 0.0001 8.5
grid nz 60'
printf '%s\n' "$good" >in.txt
bleach -q clear.cont in.txt || fail "the good input fails"
rm -f rval.3D.binary
n=0
bad() { # bad 'what' 'sed script or replacement text'
	n=$((n + 1))
	printf '%s\n' "$2" >in.txt
	expect_file_error bleach in.txt -q clear.cont in.txt
	[ ! -e rval.3D.binary ] || fail "case $n ($1): left rval.3D.binary"
	ls | grep -q '\.tmp\|rval' && fail "case $n ($1): left a temporary: $(ls)"
	:
}
edit() { printf '%s\n' "$good" | sed "$1"; }
bad "empty file" ""
bad "unknown statement" "$(edit '1i\
colour blue')"
bad "no wavelength" "$(edit '/^wavelength/d')"
bad "no resist" "$(edit '/^resist/d')"
bad "no substrate" "$(edit '/^substrate/d')"
bad "no dose" "$(edit '/^dose/d')"
bad "no develop" "$(edit '/^develop/d')"
bad "wavelength twice" "$(edit '1p')"
bad "NaN wavelength" "$(edit 's/^wavelength .*/wavelength nan/')"
bad "negative wavelength" "$(edit 's/^wavelength .*/wavelength -0.4/')"
bad "huge wavelength" "$(edit 's/^wavelength .*/wavelength 1e300/')"
bad "garbage number" "$(edit 's/^dose .*/dose 24o/')"
bad "extra value" "$(edit 's/^dose .*/dose 240 250/')"
bad "missing thickness" "$(edit 's/thickness 0.70 //')"
bad "zero thickness" "$(edit 's/thickness 0.70/thickness 0/')"
bad "missing dill C" "$(edit 's/ 0.010$//')"
bad "unknown resist word" "$(edit 's/index 1.68/colour 1.68/')"
bad "layer count" "$(edit '2a\
layer 0.07 1.47')"
bad "negative layer k" "$(edit '2a\
layer 0.07 1.47 -1')"
bad "substrate one value" "$(edit 's/^substrate .*/substrate 4.73/')"
bad "unknown model" "$(edit 's/^develop .*/develop magic 1 2 3/')"
bad "kim 4 values" "$(edit 's/^develop .*/develop kim 0.062 0.0001 8.5 0.1/')"
bad "kim R1 zero" "$(edit 's/^develop .*/develop kim 0 0.0001 8.5/')"
bad "mack n = 1" "$(edit 's/^develop .*/develop mack 0.1 0.0001 0.5 1/')"
bad "mack Mth = 1" "$(edit 's/^develop .*/develop mack 0.1 0.0001 1 5/')"
bad "dill overflow" "$(edit 's/^develop .*/develop dill 500 0 0/')"
bad "canegative without crosslink" "$(edit 's/^develop .*/develop canegative 0.05 0.0003 2/')"
bad "crosslink without canegative" "$(edit '$a\
crosslink rate 1e11 energy 1 order 1 temperature 140 time 60')"
bad "crosslink missing time" "$(edit 's/^develop .*/develop canegative 0.05 0.0003 2\
crosslink rate 1e11 energy 1 order 1 temperature 140/')"
bad "bake without diffusion" "$(edit '$a\
bake 0.08')"
bad "bake negative" "$(edit '$a\
bake diffusion -0.08')"
bad "grid nz 1" "$(edit 's/^grid .*/grid nz 1/')"
bad "grid nx only" "$(edit 's/^grid .*/grid nx 10 nz 50/')"
bad "grid nz huge" "$(edit 's/^grid .*/grid nz 1e9/')"
bad "grid too many points" "$(edit 's/^grid .*/grid nx 10000 ny 10000 nz 1000/')"
bad "absurd exposure" "$(edit 's/0.010$/1000/; s/^dose .*/dose 1e6/')"
bad "standingwaves maybe" "$(edit '$a\
standingwaves maybe')"
bad "unterminated quote" "$(edit '$a\
"abc')"
# a missing input file and a bad contour-file
printf '%s\n' "$good" >in.txt
expect_error bleach -q clear.cont nonexistent.in
expect_error bleach -q nonexistent.cont in.txt
printf '0 1 0 1\n2 2\n1 1 1\n' >short.cont
expect_file_error bleach short.cont -q short.cont in.txt
printf '0 1 0 1\n2 2\n1 nan 1 1\n' >nan.cont
expect_file_error bleach nan.cont -q nan.cont in.txt
[ ! -e rval.3D.binary ] || fail "an error left rval.3D.binary"
echo "$n malformed inputs refused"
exit 0
