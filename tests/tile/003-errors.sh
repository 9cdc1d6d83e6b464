# stitch's errors: usage mistakes exit 2 (one line and the --help hint),
# bad inputs exit 1 with one line "stitch: ..."; nothing is written on
# an error.  sample3D -tile refuses what it cannot tile with exit 2.
# Checked against the exit status and the first word of the message.
. "$TOP/tests/lib/common.sh"
built stitch sample3D
usage2() { # usage2 ARGS: exit 2 and a message starting "stitch: "
	stitch "$@" >/dev/null 2>err.txt </dev/null
	st=$?
	[ $st -eq 2 ] || fail "stitch $*: exit $st, expected 2"
	grep -q "^stitch: " err.txt || fail "stitch $*: $(cat err.txt)"
}
usage2 -cut 0 mask.in
usage2 -cut 2
usage2 -cut 2 -o x mask.in
usage2 -t a.plot 0 0 1 0 0 1
usage2 -t a.plot 0 0
usage2 -halo 1 -t a.plot 0 0 0 1 0 1
usage2 -image
cat >mask.in <<'M'
wavelength 0.365
na 0.6
window -1 1 -1 1
rect -0.25 -0.25 0.25 0.25
grid 21 21
M
printf '0 1 0 1 -1 0\n1\n4\n0 0 -1\n1 0 -1\n0 1 0\n0 0 -1\n' >one.plot
printf '0 1 0 1 -1 0\n1\n3\n0 0 -1\n1 0 -1\n0 1 0\n' >notri.plot
expect_error stitch -o out.plot -t missing.plot 0 0 0 1 0 1
[ ! -e out.plot ] || fail "an output was left after an error"
expect_error stitch -o out.plot -t notri.plot 0 0 0 1 0 1
[ ! -e out.plot ] || fail "an output was left after an error"
expect_error stitch -image -o out.cont -t one.plot 0 0 0 1 0 1
expect_error stitch -cut 0.5 -d sub nosuch.in
# a good one-tile join writes the triangle back
stitch -o out.plot -t one.plot 0 0 0 1 0 1 2>err.txt || fail "one tile: $(cat err.txt)"
[ "$(grep -vc '^#' out.plot)" -ge 6 ] || fail "one tile: $(cat out.plot)"
stitch -cut 1 -halo 0.2 -d sub mask.in >list.txt || fail "stitch -cut failed"
[ "$(wc -l <list.txt)" -eq 4 ] || fail "expected 4 tiles: $(cat list.txt)"
# sample3D: -tile needs -if, -bf and -et; -halo alone is refused
sample3D -tile 1 -rb x -et 1 >/dev/null 2>err.txt; st=$?
[ $st -eq 2 ] || fail "sample3D -tile without -if: exit $st: $(cat err.txt)"
sample3D -halo 1 -if mask.in >/dev/null 2>err.txt; st=$?
[ $st -eq 2 ] || fail "sample3D -halo without -tile: exit $st: $(cat err.txt)"
exit 0
