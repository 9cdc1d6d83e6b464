# sample3D -tile on a layout that is not periodic over the tiles (a line
# with a bend, a contact, two squares and a bar, i-line NA 0.6, sigma 0.5,
# a 0.1 um grid, 40 planes), cut 2 x 2 into 3 um cores with a seam through
# the features, against the untiled 6 um run (imaged by Abbe's method, as
# the tiles are):
#  - at the default halo (3 lambda/NA, 1.9 um on this grid) the stitched
#    image is within 0.005 of the untiled one (measured 0.0023: the
#    partially coherent image settles slowly) and the CDs at 50 % of the
#    height of the contact and the square beside it within 1 nm (measured
#    0.34 and 0.40 nm);
#  - a halo of 0.7 um (1.15 lambda/NA) is worse than 0.005 (measured
#    0.022, and CDs 2.5 to 3.7 nm off): the halo is what the accuracy
#    rests on.
# Tolerances: twice the measured differences (stitch(1), ACCURACY).
. "$TOP/tests/lib/common.sh"
built sample3D splat bleach etch stitch measure
ITOL=0.005
CDTOL=0.001
cat >mask.in <<'M'
wavelength 0.365
na 0.6
sigma 0.5
background dark
window -3 3 -3 3
rect -0.25 -0.25 0.25 0.25
rect 0.6 -0.3 1.2 0.3
rect -2 -1.3 1.5 -0.8
rect -2 -1.3 -1.5 2
rect 1.7 0.9 2.3 1.5
rect -0.9 1.2 -0.3 1.8
grid 61 61
contour image.cont
M
sed 's/nz 300/nz 40/' "$TOP/examples/array40/resist.in" >resist.in
grep -q "nz 40" resist.in || fail "the resist file has no nz 300 line to change"
{ splat -q -method abbe mask.in && bleach -q -o rval.3D.binary image.cont resist.in &&
	etch -q -method fmm -et 60 -last -no2d rval.3D.binary; } 2>err.txt ||
	fail "untiled run: $(cat err.txt)"
imgdiff() { # imgdiff A B: the largest difference of two images on one grid
	awk 'FNR == 1 { h = 0 } /^#/ { next } h < 2 { h++; next } NR == FNR { a[++n] = $1; next }
		{ d = $1 - a[++k]; if (d < 0) d = -d; if (d > m) m = d }
		END { if (k != n) print "count"; else printf "%.3g\n", m }' "$1" "$2"
}
mkdir def small
(cd def && sample3D -q -if ../mask.in -bf ../resist.in -et 60 -last -tile 3 -j 2) 2>err.txt ||
	fail "tiled run: $(cat err.txt)"
(cd small && sample3D -q -if ../mask.in -bf ../resist.in -et 60 -last -tile 3 -halo 0.7 -j 2) \
	2>err.txt || fail "tiled run, halo 0.7: $(cat err.txt)"
d=$(imgdiff image.cont def/image.cont)
[ "$d" != count ] || fail "the stitched image has not the untiled grid"
close "$d" 0 "$ITOL" "largest intensity difference at the default halo"
d=$(imgdiff image.cont small/image.cont)
awk -v d="$d" -v t="$ITOL" 'BEGIN { exit !(d > t) }' ||
	fail "a halo of 0.7 um gives $d, expected worse than $ITOL"
for h in "0 0" "0.9 0"; do
	# shellcheck disable=SC2086
	a=$(measure -rel 50 -hole $h curves.plot 2>/dev/null | awk '!/^#/ { print $2 }')
	# shellcheck disable=SC2086
	b=$(measure -rel 50 -hole $h def/curves.plot 2>/dev/null | awk '!/^#/ { print $2 }')
	[ -n "$a" ] && [ -n "$b" ] || fail "hole $h: no cd ($a, $b)"
	close "$a" "$b" "$CDTOL" "cd at 50 % of the hole at $h"
done
exit 0
