# splat's gds statement on layouts written by gdspy and committed under
# tests/gds/data (so these checks never skip):
#  - boxes.gds (overlapping rectangles, decoy layer 2, a decoy datatype
#    1/1, a second top cell): the gds statement gives a byte-identical
#    image to the same shapes as polygon statements, and the rect version
#    agrees to 1e-12 (a different exact formula); statements in any order
#    and window auto give byte-identical files; T PHASE, datatypes, cell
#    selection, painting over earlier rects, relative file names;
#  - refs.gds (references rotated by 90, 180 and 30 degrees, reflected,
#    magnified 1.5, an array with rotation, overlaps) and paths.gds
#    (pathtypes 0, 2, 4 with bends): against gdspy's own flattening
#    (refs.in, paths.in, its get_polygons) to 1e-9;
#  - cycle.gds: a reference loop is one error naming the file and byte.
. "$TOP/tests/lib/common.sh"
D=$TOP/tests/gds/data
cp "$D"/*.gds "$D"/*.in . || fail "no test data"
optics='wavelength 0.365
na 0.5
sigma 0.5
grid 31 31'
win='window -3 3 -3 3'
run() {  # run NAME TEXT: splat on TEXT, image NAME.cont
	printf '%s\n' "$2" >"$1.in"
	splat -q -o "$1.cont" "$1.in" 2>err.txt || fail "$1: splat failed: $(cat err.txt)"
}

run g1 "$optics
$win
gds boxes.gds layer 1/0 cell TOP"
run p1 "$optics
$win
$(cat boxes.in)"
same g1.cont p1.cont
run r1 "$optics
$win
$(awk '{ print "rect", $2, $3, $6, $7 }' boxes.in)"
plotdiff -q -tol 1e-12 g1.cont r1.cont || fail "gds and rects differ by more than 1e-12"
# any order; window auto with the same window
run g2 "gds boxes.gds cell TOP layer 1/0
grid 31 31
window -3 3 -3 3
sigma 0.5
na 0.5
wavelength 0.365"
same g1.cont g2.cont
run g3 "$optics
window auto margin 0.5
gds boxes.gds layer 1/0 cell TOP"
run p3 "$optics
window -3 3 -2.5 2.5
$(cat boxes.in)"
same g3.cont p3.cont
# window auto default margin 2 lambda/NA = 1.46: from the contour header
run g4 "$optics
window auto
gds boxes.gds layer 1/0 cell TOP"
[ "$(grep -v '^#' g4.cont | head -n 1)" = "-3.96 3.96 -3.46 3.46" ] ||
	fail "window auto: $(grep -v '^#' g4.cont | head -n 1), expected the box -2.5 2.5 -2 2 grown by 1.46"
# T PHASE
run g5 "$optics
$win
gds boxes.gds layer 1/0 cell TOP 0.5 180"
run p5 "$optics
$win
$(sed 's/$/ t 0.5 180/' boxes.in)"
same g5.cont p5.cont
# datatype 1 is the decoy bar alone; layer 1 without datatype adds it
run g6 "$optics
$win
polygon 0 0 0.001 0 0 0.001 t 0 0
gds boxes.gds layer 1/1 cell TOP"
run r6 "$optics
$win
polygon 0 0 0.001 0 0 0.001 t 0 0
rect -0.2 -2.5 0.2 2.5"
plotdiff -q -tol 1e-12 g6.cont r6.cont || fail "datatype 1: not the decoy bar"
run g7 "$optics
$win
gds boxes.gds layer 1 cell TOP"
run p7 "$optics
$win
$(cat boxes.in)
polygon -0.2 -2.5 0.2 -2.5 0.2 2.5 -0.2 2.5"
plotdiff -q -tol 1e-12 g7.cont p7.cont || fail "layer 1, all datatypes"
# painted over what came before: a dark gds union over a clear rect
run g8 "$optics
$win
background clear
rect -3 -3 3 0
gds boxes.gds layer 1/0 cell TOP 0 0"
run p8 "$optics
$win
background clear
rect -3 -3 3 0
$(sed 's/$/ t 0 0/' boxes.in)"
same g8.cont p8.cont
# a relative file is relative to the input's folder
mkdir -p sub && cp boxes.gds sub/ && rm -f boxes.gds.moved
printf '%s\n' "$optics" "$win" "gds boxes.gds layer 1/0 cell TOP" >sub/m.in
mv boxes.gds boxes.gds.moved
splat -q -o g9.cont sub/m.in 2>err.txt || fail "relative file: $(cat err.txt)"
mv boxes.gds.moved boxes.gds
same g1.cont g9.cont

# gdspy's flattening of references, arrays and paths
for c in refs paths; do
	run g_$c "$optics
$win
gds $c.gds layer 1/0"
	run p_$c "$optics
$win
clip on
$(cat $c.in)"
	plotdiff -q -tol 1e-9 g_$c.cont p_$c.cont || fail "$c: our flattening and gdspy's differ"
done
# the decoys matter: layer 2 is a large square
run d2 "$optics
$win
gds refs.gds layer 2"
plotdiff -q -tol 1e-3 g_refs.cont d2.cont && fail "layer 2 images like layer 1"

# errors: one line, naming the statement, the file and the byte
n=0
bad() {  # bad TEXT PATTERN
	n=$((n + 1))
	printf '%s\n' "$optics" "$win" "$1" >bad$n.in
	expect_error splat -q -o bad$n.cont bad$n.in
	grep -q "^splat: bad$n.in:6: " err.txt || fail "case $n: no statement line: $(cat err.txt)"
	grep -q "$2" err.txt || fail "case $n: message lacks '$2': $(cat err.txt)"
	[ ! -e bad$n.cont ] || fail "case $n: output written"
}
bad "gds cycle.gds layer 1" 'cycle.gds: byte [0-9]*: reference loop'
bad "gds boxes.gds layer 1" '2 top cells.*"OTHER".*"TOP"'
bad "gds boxes.gds layer 1 cell NOPE" 'no cell named "NOPE"'
bad "gds boxes.in layer 1" 'boxes.in: byte 0: '
exit 0
