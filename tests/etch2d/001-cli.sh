#!/bin/sh
# etch2d: the command line and the file it writes.  Checks: bad options,
# a missing -et (status 2), a 3D rate array, a seed outside the box or (for a surface
# method) off the top, and too many cells each give one line "etch2d: ..."
# and no output file, as do runs of more than the allowed steps or nodes;
# etch refuses a 2D array and points at etch2d; every
# method writes one set per print time (4 with -et 1 -pt 0.25) whose
# bounds are the box, that drawplot draws; the output is byte-identical
# between two runs; -stats prints its line; a 2D array round-trips through
# the ASCII and binary forms of rval(5); -start refuses a profile that is
# not one polyline from wall to wall or crosses itself, and reads one
# written right to left as the same.
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
$MKRATE -o r2.bin 11 1 11 -1 1 0 0 -1 0 '0.5+0.2*x' || fail "mkrate 2D"
$MKRATE -ascii -o r2.txt 11 1 11 -1 1 0 0 -1 0 '0.5+0.2*x' || fail "mkrate 2D ascii"
$MKRATE -o r3.bin 5 5 5 -1 1 -1 1 -1 0 1 || fail "mkrate 3D"
"$BUILD/tests/lib/fmtcat" rate r2.txt back.bin || fail "2D ASCII rate file does not read back"
cmp -s back.bin r2.bin || fail "2D rate: ASCII -> binary differs from the binary written directly"

# usage errors: status 2, the first line "etch2d: ..."
usage_error() {
	"$@" </dev/null >/dev/null 2>err.txt
	st=$?
	[ $st -eq 2 ] || fail "$*: exit $st, want 2"
	head -1 err.txt | grep -q "^etch2d: " || fail "$*: $(head -1 err.txt)"
}
usage_error etch2d -et 1 -bogus r2.bin
usage_error etch2d r2.bin
usage_error etch2d -et 1 -method nosuch r2.bin
usage_error etch2d -et 1 -seed 0 r2.bin
expect_error etch2d -et 1 -o out.plot r3.bin
grep -q "use etch" err.txt || fail "3D array refused without pointing at etch: $(cat err.txt)"
expect_error etch2d -et 1 -seed 5 0 -o out.plot r2.bin
expect_error etch2d -et 1 -seed 0 -0.5 -o out.plot r2.bin
expect_error etch2d -et 1 -method cell -cells 10000 10000 -o out.plot r2.bin
# runs that would take hours or eat memory are refused up front
expect_error etch2d -et 100 -dt 1e-9 -method huygens -o out.plot r2.bin
expect_error etch2d -et 1e12 -o out.plot r2.bin
expect_error etch2d -et 1 -seg 1e-12 -o out.plot r2.bin
# -start: one polyline wall to wall, not crossing itself, not with -seed
printf -- '-1 1 -1 0\n1\n4\n-1 0\n-0.2 0\n0 -0.3\n1 0\n' >groove.plot
printf -- '-1 1 -1 0\n1\n3\n-1 0\n0 -0.3\n0.5 0\n' >short.plot
printf -- '-1 1 -1 0\n1\n5\n-1 0\n0.5 -0.5\n0.5 -0.2\n-0.5 -0.5\n1 0\n' >cross.plot
printf -- '-1 1 -1 0\n2\n2\n-1 0\n1 0\n2\n-1 -0.5\n1 -0.5\n' >two.plot
# a curve of no points: refused, not taken for the flat top
printf -- '-1 1 -1 0\n1\n0\n' >empty.plot
usage_error etch2d -et 1 -start groove.plot -seed 0 0 r2.bin
for f in short cross two empty; do
	expect_error etch2d -et 1 -start $f.plot -o out.plot r2.bin
	grep -q "^etch2d: $f.plot:1: " err.txt || fail "-start $f.plot: $(cat err.txt)"
done
[ -e out.plot ] && fail "a refused run left out.plot"
# a profile written right to left is the same profile
awk 'NR <= 3 { print; next } { l[NR] = $0 } END { for (i = NR; i > 3; i--) print l[i] }' \
	groove.plot >reversed.plot
for m in raystring cell fmm; do
	etch2d -et 0.3 -method $m -start groove.plot -o g1.plot r2.bin || fail "-start $m failed"
	etch2d -et 0.3 -method $m -start reversed.plot -o g2.plot r2.bin || fail "-start $m reversed"
	same g1.plot g2.plot
done
expect_error etch -et 1 r2.bin
grep -q "etch2d" err.txt || fail "etch does not point at etch2d: $(cat err.txt)"

for m in raystring string ray cell huygens fmm; do
	etch2d -et 1 -pt 0.25 -method $m -o $m.plot r2.bin || fail "$m failed"
	n=$(grep -c '^-1 1 -1 0$' $m.plot)
	[ "$n" -eq 4 ] || fail "$m: $n sets with the box's bounds, want 4"
	drawplot -noplot -e -svg $m.svg $m.plot </dev/null >/dev/null 2>&1 || fail "drawplot cannot draw $m.plot"
	[ -s $m.svg ] || fail "drawplot wrote no picture of $m.plot"
	etch2d -et 1 -pt 0.25 -method $m -o again.plot r2.bin || fail "$m failed twice"
	same $m.plot again.plot
done
etch2d -et 1 -seed 0 0 -method cell -cells 20 10 -stats -o s.plot r2.bin 2>stats.txt ||
	fail "-stats run failed"
grep -q "method cell: cpu .* boundary cells .* of 200 cells, steps" stats.txt ||
	fail "-stats line: $(cat stats.txt)"
exit 0
