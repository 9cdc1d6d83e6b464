# splat's vector imaging, as a program (the physics is tests/splat/vector.c):
#  - the statements imaging, immersion, polarization and reduction read,
#    and their bad forms are one-line errors naming the line: an unknown
#    word, an immersion index below 1, na at or beyond the immersion index
#    (na 1.2 in air keeps today's message), a reduction below 1, a source
#    beyond the immersion's horizon;
#  - splat -bf takes the film from bleach's resist file: the stack's
#    header ends in "film" and carries the resist file's thickness and
#    index; a resist file whose ambient is not the immersion index, or of
#    another wavelength, or a vector run with -bf but no resist statement,
#    is refused in one line; -method hopkins with imaging vector is a
#    usage error (exit 2);
#  - -bf with scalar imaging changes nothing: the same bytes as without;
#  - the vector stack is byte-identical with 1, 2 and 3 threads (a contact
#    whose source points take the FFT path);
#  - a file with the default statements written out gives the same
#    bytes as one without them (imaging scalar, immersion 1,
#    polarization unpolarized, reduction 4 are the defaults).
. "$TOP/tests/lib/common.sh"
cat >resist.in <<'IN'
wavelength 0.193
ambient 1.44
resist thickness 0.1 index 1.7 dill 0 1.2 0.05
layer 0.08 1.82 0.34
substrate 0.88 2.78
dose 30
develop mack 0.1 0.0001 0.5 5
grid nz 41
IN
lines() { cat <<'IN'
wavelength 0.193
na 1.35
immersion 1.44
annular 0.7 0.9
window 0 0.09 0 0.09
background clear
rect 0 0 0.045 0.09 0 0
grid 19 3
resist thickness 0.1 index 1.7 planes 5
IN
}
{ lines; echo "imaging vector"; echo "polarization te"; } >v.in
splat -q -bf resist.in -o v.stack v.in || fail "splat -bf"
sed -n 1p v.stack | grep -qx 'stack planes 5 thickness 0.1 index 1.7 wavelength 0.193 film' ||
	fail "header: $(sed -n 1p v.stack)"
splat -q -o nv.stack v.in || fail "splat vector without -bf"
sed -n 1p nv.stack | grep -q 'film' && fail "a stack without -bf says film"
cmp -s v.stack nv.stack && fail "the film changes nothing"
# threads: a contact whose source points take the FFT path (many orders)
cat >il.in <<'IN'
wavelength 0.365
na 0.6
sigma 0.5
imaging vector
resist thickness 1 index 1.7 planes 3
window -1.2 1.2 -1.2 1.2
background dark
rect -0.25 -0.25 0.25 0.25
grid 21 21
IN
for t in 1 2 3; do
	splat -q -threads $t -o v$t.stack il.in || fail "-threads $t"
done
same v1.stack v2.stack
same v1.stack v3.stack
# scalar: -bf is not used; the defaults spelled out change nothing
lines >s.in
{ lines; printf 'imaging scalar\npolarization unpolarized\nreduction 4\n'; } >s2.in
splat -q -o s.stack s.in || fail "scalar"
splat -q -bf resist.in -o s1.stack s.in || fail "scalar -bf"
splat -q -o s2.stack s2.in || fail "scalar, defaults spelled out"
same s.stack s1.stack
same s.stack s2.stack
# errors, one line naming the file and line
bad() { # TEXT PATTERN
	printf '%b' "$1" >bad.in
	expect_error splat -q -o bad.out bad.in
	grep -q "$2" err.txt || fail "expected '$2': $(cat err.txt)"
	[ ! -e bad.out ] || fail "an output was left for: $1"
}
W='window 0 1 0 1\n'
bad "${W}imaging vectorial\n" 'bad.in:2: imaging: expected'
bad "${W}immersion 0.9\n" 'bad.in:2: immersion: the index must be in'
bad "${W}polarization z\n" 'bad.in:2: polarization: expected x, y, te, tm or unpolarized'
bad "${W}reduction 0.5\n" 'bad.in:2: reduction: expected a ratio'
bad "${W}reduction\n" 'bad.in:2: reduction: expected'
bad "${W}na 1.2\n" 'bad.in:2: na must be in (0, 1), found 1.2'
bad "${W}na 1.5\nimmersion 1.44\n" 'bad.in:2: na 1.5 must be below the immersion index 1.44'
bad "${W}immersion 1.44\nna 1.35\nsigma 1.1\n" 'bad.in:4: the source reaches'
printf 'immersion 1.44\nna 1.35\nreduction inf\n' >ok.in
printf "$W" >>ok.in
splat -q -o ok.cont ok.in || fail "na 1.35 in water, reduction inf"
# -bf mismatches
sed 's/^ambient 1.44/ambient 1/' resist.in >air.in
expect_error splat -q -bf air.in -o x.stack v.in
grep -q 'air.in: ambient 1 must equal the immersion index 1.44' err.txt || fail "$(cat err.txt)"
sed 's/^wavelength 0.193/wavelength 0.248/' resist.in >krf.in
expect_error splat -q -bf krf.in -o x.stack v.in
grep -q 'krf.in: wavelength 0.248 um, but v.in has wavelength 0.193' err.txt || fail "$(cat err.txt)"
grep -v '^resist' v.in >np.in
expect_error splat -q -bf resist.in -o x.stack np.in
grep -q 'np.in: -bf with imaging vector' err.txt || fail "$(cat err.txt)"
splat -q -method hopkins -o x.stack v.in 2>err.txt
[ $? -eq 2 ] || fail "-method hopkins with imaging vector: not a usage error"
grep -q 'imaging vector' err.txt || fail "$(cat err.txt)"
[ ! -e x.stack ] || fail "an output was left"
# the thickness and index come from the resist file
sed 's/^resist thickness 0.1 index 1.7/resist thickness 0.2 index 1.6/' v.in >thick.in
splat -q -bf resist.in -o t.stack thick.in 2>err.txt || fail "thickness from -bf"
grep -q 'taking resist.in' err.txt || fail "no warning: $(cat err.txt)"
sed -n 1p t.stack | grep -q 'thickness 0.1 index 1.7 ' || fail "header: $(sed -n 1p t.stack)"
exit 0
