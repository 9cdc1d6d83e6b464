# splat rejects bad command lines (status 2, usage) and every malformed
# input with one line "splat: file:line: ..." and status 1, without a
# crash or sanitizer report, and leaves no output behind.  Checked against
# the rules of man/man5/splat.5.
. "$TOP/tests/lib/common.sh"

# command line
splat >/dev/null 2>err.txt; st=$?
[ $st -eq 2 ] || fail "no input file: exit $st, expected 2"
grep -q usage err.txt || fail "no input file: no usage printed"
splat -x in >/dev/null 2>err.txt; st=$?
[ $st -eq 2 ] || fail "unknown option: exit $st, expected 2"
splat -o >/dev/null 2>err.txt; st=$?
[ $st -eq 2 ] || fail "-o without a value: exit $st, expected 2"
splat a b >/dev/null 2>err.txt; st=$?
[ $st -eq 2 ] || fail "two inputs: exit $st, expected 2"
splat --help >help.txt 2>&1 || fail "--help exits non-zero"
grep -q "usage: splat" help.txt || fail "--help prints no usage"
expect_error splat -q missing.in

good='window -2 2 -2 2
rect -0.5 -0.5 0.5 0.5'
n=0
bad() {   # bad LINE-NUMBER TEXT: the input must fail naming that line
	n=$((n + 1))
	printf '%s\n' "$2" >bad$n.in
	expect_file_error splat bad$n.in -q -o out$n.cont bad$n.in
	grep -q "^splat: bad$n.in:$1: " err.txt || fail "case $n: wrong line: $(cat err.txt)"
	[ ! -e out$n.cont ] || fail "case $n: output written despite the error"
	ls | grep -q 'out.*tmp' && fail "case $n: temporary left behind"
	return 0
}
bad 3 "$good
frobnicate 1"
bad 1 "na 1
$good"
bad 1 "na 1.5
$good"
bad 1 "na 0
$good"
bad 1 "sigma -0.1
$good"
bad 3 "$good
grid 1 1"
bad 3 "$good
grid 51 1"
bad 1 "window 0 0 -1 1"
bad 1 "window 0 1 2 2"
bad 1 "window 1 0 0 1"
bad 2 "window -1 1 -1 1
rect -2 0 0 0.5"
bad 2 "window -1 1 -1 1
rect 0 0 0.5 1.5"
bad 1 "rect 0 0 3 3
window -1 1 -1 1"
bad 1 "rect 0 0 1 1"
bad 3 "$good
rect 0 0 0 1"
bad 3 "$good
rect 0 0 1"
bad 3 "$good
rect 0 0 1 1 2 0"
bad 3 "$good
rect 0 0 1 1 0.5"
bad 3 "$good
wavelength nan"
bad 3 "$good
wavelength -0.4"
bad 3 "$good
na inf"
bad 3 "$good
na 0.5 0.6"
bad 3 "$good
coma 0.4"
bad 3 "$good
coma 0.4 field 2 0"
bad 3 "$good
coma 0.4 at 1 0"
bad 3 "$good
zernike 38 0.1"
bad 3 "$good
zernike 0 0.1"
bad 3 "$good
annular 0.5 0.3"
bad 3 "$good
quadrupole 0.2 0.3"
bad 3 "$good
dipole 0.7 0.2 z"
bad 3 "$good
background grey"
bad 3 "$good
background 1.5 0"
bad 3 "$good
cutline 0 0 1 1 1 c.2D"
bad 3 "$good
cutline 0 0 1 1 10"
bad 3 "$good
contour"
bad 3 "$good
\"window\" 0 1 0 1"
bad 3 "$good
grid 100000000 3"
# empty and garbage files: no window, reported at the end of the input
printf '' >empty.in
expect_error splat -q empty.in
printf '\001\002\377garbage\n' >garbage.in
expect_file_error splat garbage.in -q garbage.in
# all the light outside the pupil
printf '%s\nannular 1.1 1.5\n' "$good" >dark.in
expect_error splat -q -o dark.cont dark.in
[ ! -e dark.cont ] || fail "output written for a source outside the pupil"
exit 0
