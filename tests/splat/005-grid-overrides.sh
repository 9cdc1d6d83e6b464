# Command-line overrides of the resolution (the drivers' -accuracy):
# "splat -grid nx ny" gives byte for byte the output of the input file with
# its grid statement edited to those counts (an image and an image stack,
# cutlines included), and "bleach -nz N" the output of the resist file
# with its grid statement edited to nz N; a bad value is one line on
# stderr, status 2, and nothing written.
. "$TOP/tests/lib/common.sh"
cat >base.in <<'IN'
window -1.2 1.2 -1.2 1.2
rect -0.3 -0.3 0.3 0.3
na 0.5
sigma 0.5
grid 21 21
cutline -1.2 0 1.2 0 31 cut.2D
IN
for g in "9 13" "41 41" "2 2"; do
	sed "s/^grid .*/grid $g/" base.in >edit.in
	splat -q -o edit.cont edit.in || fail "splat edited grid $g"
	mv cut.2D edit.2D
	# shellcheck disable=SC2086 # g is two words on purpose
	splat -q -grid $g -o over.cont base.in || fail "splat -grid $g"
	same edit.cont over.cont
	same edit.2D cut.2D
done
# an image stack: the planes at the overridden grid
{ cat base.in; echo "resist thickness 0.5 index 1.7 planes 3"; } >stack.in
sed 's/^grid .*/grid 15 11/' stack.in >stack-edit.in
splat -q -o edit.stack stack-edit.in || fail "splat edited stack grid"
splat -q -grid 15 11 -o over.stack stack.in || fail "splat -grid on a stack"
same edit.stack over.stack
# the override really is used
splat -q -o a.cont base.in
splat -q -grid 31 31 -o b.cont base.in
cmp -s a.cont b.cont && fail "-grid 31 31 gave the file's 21 x 21 image"
for v in "x 21" "21 x" "1 21" "21 1" "10002 21" "21.5 21" "-3 21" "21"; do
	rm -f bad.cont
	st=0
	# shellcheck disable=SC2086 # v is words on purpose
	splat -q -o bad.cont -grid $v base.in 2>err.txt || st=$?
	[ $st -eq 2 ] || fail "-grid $v: exit $st, expected 2"
	[ "$(wc -l <err.txt)" -le 30 ] || fail "-grid $v: $(cat err.txt)"
	[ ! -e bad.cont ] || fail "-grid $v: output written"
done
expect_error splat -q -o bad.cont -grid 21 x base.in
[ ! -e bad.cont ] || fail "-grid 21 x: output written"
# a stack beyond the bound of planes * nx * ny
{ cat base.in; echo "resist thickness 0.5 index 1.7 planes 1001"; } >big.in
expect_error splat -q -o bad.cont -grid 5000 5000 big.in
[ ! -e bad.cont ] || fail "-grid 5000 5000 on 1001 planes: output written"

# bleach -nz
splat -q -o img.cont base.in
sed '/^grid/d' "$TOP/examples/resists/shipley1470.in" >r.in
for N in 60 121 2000; do
	{ cat r.in; echo "grid nz $N"; } >edit.in
	{ cat r.in; echo "grid nz 90"; } >other.in
	bleach -q -o edit.bin img.cont edit.in || fail "bleach edited nz $N"
	bleach -q -nz "$N" -o over.bin img.cont other.in || fail "bleach -nz $N"
	same edit.bin over.bin
	bleach -q -nz "$N" -o none.bin img.cont r.in || fail "bleach -nz $N, no grid statement"
	same edit.bin none.bin
done
bleach -q -o a.bin img.cont other.in
bleach -q -nz 60 -o b.bin img.cont other.in
cmp -s a.bin b.bin && fail "-nz 60 gave the file's nz 90"
# too coarse for the standing waves (shipley1470: 0.7 um, period 0.13 um),
# or not a count from 2 to 100000
for v in 3 x 1 100001 2.5 ""; do
	rm -f bad.bin
	st=0
	bleach -q -nz "$v" -o bad.bin img.cont other.in 2>err.txt || st=$?
	[ $st -eq 2 ] || fail "-nz '$v': exit $st, expected 2"
	[ ! -e bad.bin ] || fail "-nz '$v': output written"
done
expect_error bleach -q -nz 3 -o bad.bin img.cont other.in
exit 0
