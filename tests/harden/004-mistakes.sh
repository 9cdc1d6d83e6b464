# The new user's mistakes each get one line naming the file, the line and
# what to do, and a non-zero exit, checked message by message:
#  - a file of the wrong kind is named by its kind (src/lib/formats/
#    fmt_kind.c, from its first bytes) and the kind the program reads:
#    pdraw and etch given a rate or plot file of the other kind, measure
#    a 2D profile, splat and bleach (sample3D -if and -bf swapped) each
#    other's input;
#  - measure refuses bleach -solid's surface of constant PAC;
#  - dose 0 is refused alike by bleach's dose statement, bleach -dose and
#    so sample3D (fem refuses it too: tests/fem/001-usage.sh);
#  - a bake diffusion length written in nanometres, and a rect written in
#    nanometres, say that lengths are micrometres;
#  - a GDS layer or cell that is not in the file lists those that are;
#  - sample3D reads the resist file first (bleach -check): "develop kimm"
#    is reported before splat writes anything.
. "$TOP/tests/lib/common.sh"
built splat bleach etch pdraw measure sample3D
E=$TOP/examples/contact
L=$TOP/examples/layout
# one PATTERN PROG ARGS...: one line on stderr, matching PATTERN (grep -E)
one() {
	_pat=$1
	shift
	expect_error "$@"
	grep -Eq -- "$_pat" err.txt || fail "$*: \"$(cat err.txt)\" does not match \"$_pat\""
}
# driver PATTERN ARGS...: sample3D ARGS fails with one line matching
# PATTERN (the message of the stage that found the mistake)
driver() {
	_pat=$1
	shift
	sample3D "$@" </dev/null >/dev/null 2>err.txt && fail "sample3D $* succeeded"
	[ "$(wc -l <err.txt)" -eq 1 ] || fail "sample3D $*: not one line: $(cat err.txt)"
	grep -Eq -- "$_pat" err.txt || fail "sample3D $*: \"$(cat err.txt)\" does not match \"$_pat\""
}
splat -q "$E/mask.in" || fail "splat on the contact"
bleach -q -solid image.cont "$E/resist.in" || fail "bleach on the contact"
etch -q -et 10 -cut y 0 rval.3D.binary || fail "etch on the contact"
one '^pdraw: rval.3D.binary:1: this is a rate file \(rval\(5\)\); pdraw reads plot3d\(5\)$' \
	pdraw -noplot rval.3D.binary
one '^etch: curves.plot:1: this is a 3D plot file \(plot3d\(5\)\); etch reads rval\(5\)$' \
	etch -et 10 curves.plot
one '^measure: curves.cut:1: this is a 2D plot file \(plot2d\(5\)\); measure reads plot3d\(5\)$' \
	measure -rel 50 -hole 0 0 curves.cut
one "^splat: $E/resist.in:1: this is a bleach input file \\(bleach\\(5\\)\\); splat reads splat\\(5\\)\$" \
	splat "$E/resist.in"
one "^bleach: $E/mask.in:1: this is a splat input file \\(splat\\(5\\)\\); bleach reads bleach\\(5\\)\$" \
	bleach image.cont "$E/mask.in"
one '^measure: mxyz.solid.3D:1: this is bleach -solid.s surface of constant PAC, not a developed surface' \
	measure -rel 50 -hole 0 0 mxyz.solid.3D
# dose 0
sed 's/^dose .*/dose 0/' "$E/resist.in" >d0.in
one '^bleach: d0.in:[0-9]+: dose 0: nothing is exposed' bleach image.cont d0.in
one '^bleach: option -dose: expected a number above 0' bleach -dose 0 image.cont "$E/resist.in"
mkdir s && cd s || fail "mkdir"
driver '^bleach: \.\./d0.in:[0-9]+: dose 0' -q -if "$E/mask.in" -bf ../d0.in -et 10
# reported before splat ran: nothing written
sed 's/^develop .*/develop kimm 1 2 3/' "$E/resist.in" >kimm.in
driver '^bleach: kimm.in:[0-9]+: develop: unknown model "kimm"' -q -if "$E/mask.in" -bf kimm.in -et 10
[ -z "$(ls | grep -v '^\(kimm.in\|err.txt\)$')" ] || fail "sample3D ran a stage before the resist's mistake: $(ls)"
bleach -check "$E/resist.in" || fail "bleach -check refuses the contact's resist"
cd .. || fail "cd"
# nanometres
sed 's/^bake .*/bake diffusion 80/' "$E/resist.in" >nm.in
one '^bleach: nm.in:[0-9]+: .*lengths are in micrometres: 80 nm is 0.08' bleach image.cont nm.in
sed 's/^rect .*/rect -625 -625 625 625/' "$E/mask.in" >nm-mask.in
one '^splat: nm-mask.in:[0-9]+: rect is outside the window .*micrometres, not nanometres' splat nm-mask.in
sed 's/^rect .*/rect 2 2 3 3/' "$E/mask.in" >out-mask.in
one '^splat: out-mask.in:[0-9]+: rect is outside the window of line [0-9]+$' splat out-mask.in
# GDS: what the file has
cp "$L/sram.gds" .
sed 's|layer 1/0 cell SRAM|layer 7/0 cell SRAM|' "$L/mask.in" >l7.in
one '^splat: l7.in:[0-9]+: gds: sram.gds has no shape on layer 7/0; its layers: 1/0, 1/1, 10/0, 2/0$' splat l7.in
sed 's|layer 1/0 cell SRAM|layer 1/0 cell SRAMX|' "$L/mask.in" >cx.in
one '^splat: cx.in:[0-9]+: sram.gds: .*no cell named "SRAMX"; its cells: BIT, SRAM$' splat cx.in
exit 0
