# Command-line overrides for sweeps (fem): "splat -defocus d" and
# "bleach -dose D" give byte for byte the output of the input file with
# its defocus or dose statement edited to that value (cutlines included),
# whether the file had the statement or not; a bad value (a dose of 0
# too: it exposes nothing) is one line on
# stderr, status 2, and nothing written.
. "$TOP/tests/lib/common.sh"
cat >base.in <<'IN'
window -1.5 1.5 -1.5 1.5
rect -0.4 -0.4 0.4 0.4
na 0.5
sigma 0.5
coma 0.05 field 1 0
grid 21 21
cutline -1.5 0 1.5 0 31 cut.2D
IN
for d in -0.35 0.5 0 1e-3; do
	{ cat base.in; echo "defocus $d"; } >edit.in
	splat -q -o edit.cont edit.in || fail "splat edited defocus $d"
	mv cut.2D edit.2D
	{ cat base.in; echo "defocus 0.2"; } >other.in
	splat -q -defocus "$d" -o over.cont other.in || fail "splat -defocus $d"
	same edit.cont over.cont
	same edit.2D cut.2D
	splat -q -o none.cont -defocus "$d" base.in || fail "splat -defocus $d, no statement"
	same edit.cont none.cont
done
# the override really is used: +0.5 differs from the file's 0.2
splat -q -defocus 0.5 -o a.cont other.in
splat -q -o b.cont other.in
cmp -s a.cont b.cont && fail "-defocus 0.5 gave the file's defocus 0.2 image"
for v in x nan inf -2000 500 "" 0.1.2; do
	rm -f bad.cont
	expect_error splat -q -defocus "$v" -o bad.cont base.in
	splat -q -defocus "$v" -o bad.cont base.in 2>/dev/null; st=$?
	[ $st -eq 2 ] || fail "-defocus '$v': exit $st, expected 2"
	[ ! -e bad.cont ] || fail "-defocus '$v': output written"
done
splat -q -defocus >/dev/null 2>&1; st=$?
[ $st -eq 2 ] || fail "-defocus without a value: exit $st"

# bleach -dose
splat -q -o img.cont base.in
sed '/^dose/d; s/^grid .*/grid nz 40/' "$TOP/examples/resists/shipley1470.in" >r.in
for D in 95 150.5; do
	{ cat r.in; echo "dose $D"; } >edit.in
	{ cat r.in; echo "dose 20"; } >other.in
	bleach -q -o edit.bin img.cont edit.in || fail "bleach edited dose $D"
	bleach -q -dose "$D" -o over.bin img.cont other.in || fail "bleach -dose $D"
	same edit.bin over.bin
done
bleach -q -o a.bin img.cont other.in
bleach -q -dose 95 -o b.bin img.cont other.in
cmp -s a.bin b.bin && fail "-dose 95 gave the file's dose 20"
for v in x nan inf -1 0 2e6 ""; do
	rm -f bad.bin
	expect_error bleach -q -dose "$v" -o bad.bin img.cont other.in
	bleach -q -dose "$v" -o bad.bin img.cont other.in 2>/dev/null; st=$?
	[ $st -eq 2 ] || fail "-dose '$v': exit $st, expected 2"
	[ ! -e bad.bin ] || fail "-dose '$v': output written"
done
exit 0
