# sample3D follows the SAMPLE3D(L) guide's branching: -if/-bf/-et runs all
# three stages; -cf/-bf runs bleach only; -rb/-ra with -et runs etch only;
# -ascii, -solid, -pt, -hidden reach the right stages (-hidden: the
# profile's faces are filled with paper white, the thesis' hidden-line
# mesh, where the default shades them in many greys); -h and --help print
# the usage and exit 0; etch options pass through;
# a broken resist file is reported before any stage runs; a failing stage
# stops the run with its own message and a non-zero exit and leaves the
# earlier outputs; usage errors exit 2.  Checked against
# the files each stage must (and must not) leave in the directory.
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact
cat >mask.in <<'M'
wavelength 0.436
na 0.28
sigma 0.5
window -1.5 1.5 -1.5 1.5
grid 21 21
background dark
rect -0.6 -0.6 0.6 0.6
contour img.cont
M
sed 's/^grid .*/grid nz 60/' "$E/resist.in" >resist.in

sample3D -q -if mask.in -bf resist.in -et 20 -pt 10 -solid || fail "full run failed"
for f in img.cont rval.3D.binary mxyz.solid.3D curves.plot curves.plot.2D dataplot.ps; do
	[ -s $f ] || fail "full run: $f missing"
done
[ ! -e rval.3D ] || fail "rval.3D written without -ascii"
[ "$(grep -c '^$' curves.plot)" -eq 1 ] || fail "-pt 10 -et 20: expected two sets in curves.plot"
grep -q '^%%Pages: 2' dataplot.ps || fail "dataplot.ps should have a page per print time"
grep -q '(developed resist, .*, t = 20 s)' profile.ps || fail "profile.ps: no page titled t = 20 s"

mkdir b && cd b
sample3D -q -cf ../img.cont -bf ../resist.in -ascii || fail "bleach-only run failed"
[ -s rval.3D ] || fail "-ascii: rval.3D missing"
[ ! -e curves.plot ] || fail "etch ran without -et"
sample3D -q -ra rval.3D -et 10 -linear -dt 0.5 || fail "etch-only run (-ra) failed"
[ -s curves.plot ] || fail "-ra -et: curves.plot missing"
# the same rates through the binary file give the same profile
cp curves.plot ascii.plot
sample3D -q -rb ../rval.3D.binary -et 10 -linear -dt 0.5 || fail "etch-only run (-rb) failed"
same curves.plot ascii.plot
cd ..

# progress: one line per stage (splat, bleach, etch, and the three
# pictures: pdraw, drawplot, contour) from the driver
sample3D -if mask.in -bf resist.in -et 5 2>log >/dev/null || fail "run with progress failed"
[ "$(grep -c '^sample3D: ' log)" -eq 6 ] || fail "expected 6 progress lines: $(grep '^sample3D' log)"
# the pictures, named after their content; the print time in each page's
# title; dataplot.ps is the profile
for f in profile.ps cut.ps image.ps dataplot.ps curves.cut; do
	[ -s $f ] || fail "$f missing"
done
same profile.ps dataplot.ps
grep -q '(developed resist, .*, t = 5 s)' profile.ps || fail "profile.ps does not title its page with the print time"
grep -q '(t = 5 s)' cut.ps || fail "cut.ps has no legend of print times"

# a broken bleach input is found before any stage runs (bleach -check)
mkdir c && cd c
printf 'wavelength 0.436\nbogus\n' >bad.in
sample3D -q -if ../mask.in -bf bad.in -et 10 >/dev/null 2>err.txt
st=$?
[ $st -ne 0 ] || fail "a broken bleach input should stop the run"
grep -q '^bleach: bad.in:2: ' err.txt || fail "bleach's own message not shown: $(cat err.txt)"
[ ! -e img.cont ] || fail "splat ran before the bleach input was checked"
# a failing stage (bleach's work beyond the limits) stops before etch,
# keeps splat's image
{ grep -v '^grid' "$E/resist.in"; echo 'grid nx 3000 ny 3000 nz 3000'; } >big.in
sample3D -q -if ../mask.in -bf big.in -et 10 >/dev/null 2>err.txt
st=$?
[ $st -ne 0 ] || fail "a failing bleach should stop the run"
grep -q '^bleach: big.in:[0-9]*: .*beyond the limits' err.txt || fail "bleach's own message not shown: $(cat err.txt)"
[ -s img.cont ] || fail "splat's output should stay"
[ ! -e curves.plot ] || fail "etch ran after bleach failed"
cd ..

# -hidden: the hidden-line mesh (white faces) instead of the shaded solid
# (pdraw -walls against -walls -shade; the side walls are 0.82 grey in both)
cd b
sample3D -q -rb ../rval.3D.binary -et 5 || fail "shaded run failed"
shades=$(grep -o '[0-9][0-9.]* F\b' profile.ps | sort -u | wc -l)
[ "$shades" -gt 5 ] || fail "default profile: $shades grey levels, expected a shaded solid"
sample3D -q -rb ../rval.3D.binary -et 5 -hidden || fail "-hidden run failed"
grep -o '[0-9][0-9.]* F\b' profile.ps | sort -u >greys.txt
printf '%s\n' '0.82 F' '1 F' >want.txt
same greys.txt want.txt
cd ..

# usage
sample3D --help | grep -q '^usage: sample3D' || fail "--help"
sample3D -h | grep -q '^usage: sample3D' || fail "-h does not print the usage"
sample3D -zz >/dev/null 2>&1; [ $? -eq 2 ] || fail "bad option: expected exit 2"
sample3D >/dev/null 2>&1; [ $? -eq 2 ] || fail "nothing to do: expected exit 2"
sample3D -bf resist.in >/dev/null 2>&1; [ $? -eq 2 ] || fail "-bf without an image: expected exit 2"
sample3D -rb x -if mask.in -et 1 >/dev/null 2>&1; [ $? -eq 2 ] || fail "-rb with -if: expected exit 2"
exit 0
