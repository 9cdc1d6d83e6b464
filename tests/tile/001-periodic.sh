# sample3D -tile on a periodic array: a 6 x 6 um window of 0.5 um
# contacts on a 1 um pitch (i-line NA 0.6, a 0.1 um grid, 40 planes),
# contacts centred on whole micrometres so that the seams at x = 0 and
# y = 0 run through contacts and four tiles meet in the middle of one.
# Tiled 2 x 2 (cores of 3 um, a halo of 0.5 um: every tile is a 4 um
# window, whole periods, its edges midway between contacts; a halo of 1.5
# um, 6 um tiles, gave the same CDs to the 6 digits measure prints at
# twice the CPU, and a halo of 0.3 um, not whole periods, fails the image
# check) against the untiled run:
#  - the stitched image equals the untiled one within 1e-6 (intensity);
#  - the CDs at 10, 50 and 90 % of the height of four contacts (the one
#    under the corner, one on a seam, two inside cores) within 0.5 nm;
#  - the stitched surface has no open border: stitch warns of no open
#    seam, and measure (which names any open border) prints nothing on
#    stderr for sections through the four contacts; sample3D -measure
#    prints its table of the stitched surface.
# Against the untiled run of the same inputs, tolerances as stated.
. "$TOP/tests/lib/common.sh"
built sample3D splat bleach etch stitch measure
# 1e-6: the requirement; the two images differ by FFT rounding (1e-14)
ITOL=1e-6
# 0.5 nm: the requirement
CDTOL=0.0005
awk 'BEGIN { print "wavelength 0.365\nna 0.6\nsigma 0.5\nbackground dark\nwindow -3 3 -3 3\nclip on"
	for (j = -3; j <= 3; j++) for (i = -3; i <= 3; i++)
		printf "polygon %g %g %g %g %g %g %g %g\n", i - 0.25, j - 0.25, i + 0.25, j - 0.25,
			i + 0.25, j + 0.25, i - 0.25, j + 0.25
	print "grid 61 61\ncontour image.cont" }' >mask.in
sed 's/nz 300/nz 40/' "$TOP/examples/array40/resist.in" >resist.in
grep -q "nz 40" resist.in || fail "the resist file has no nz 300 line to change"
# the untiled run by hand, imaged by Abbe's method as the tiles are
# (sample3D(1), TILES)
{ splat -q -method abbe mask.in && bleach -q -o rval.3D.binary image.cont resist.in &&
	etch -q -method fmm -et 60 -last -no2d rval.3D.binary; } 2>err.txt ||
	fail "untiled run: $(cat err.txt)"
mkdir tl
(cd tl && sample3D -q -if ../mask.in -bf ../resist.in -et 60 -last -tile 3 -halo 0.5 -j 2 \
	-measure "-rel 50 -hole 0 0") >table.txt 2>err.txt || fail "tiled run: $(cat err.txt)"
[ ! -s err.txt ] || fail "tiled run: $(cat err.txt)"
grep -q '^# cleared yes$' table.txt || fail "sample3D -tile -measure printed no table: $(cat table.txt)"
[ "$(ls tl/tiles/in | wc -l)" -eq 4 ] || fail "expected 4 tiles, got $(ls tl/tiles/in)"
d=$(awk 'FNR == 1 { h = 0 } /^#/ { next } h < 2 { h++; next }
	NR == FNR { a[++n] = $1; next }
	{ d = $1 - a[++k]; if (d < 0) d = -d; if (d > m) m = d }
	END { if (k != n || k != 61 * 61) print "count"; else printf "%.3g\n", m }' image.cont tl/image.cont)
[ "$d" != count ] || fail "the stitched image has not the untiled grid"
close "$d" 0 "$ITOL" "largest intensity difference"
for h in "0 0" "0 1" "1 1" "-2 -1"; do
	# shellcheck disable=SC2086
	measure -rel 10,50,90 -hole $h curves.plot >a.txt 2>err.txt || fail "measure untiled: $(cat err.txt)"
	# shellcheck disable=SC2086
	measure -rel 10,50,90 -hole $h tl/curves.plot >b.txt 2>err.txt || fail "measure tiled: $(cat err.txt)"
	[ ! -s err.txt ] || fail "measure of the stitched surface at $h: $(cat err.txt)"
	paste a.txt b.txt | awk '/^#/ { next } { print $2, $7 }' >cd.txt
	[ "$(wc -l <cd.txt)" -eq 3 ] || fail "hole $h: expected 3 CDs: $(cat a.txt b.txt)"
	while read -r a b; do close "$a" "$b" "$CDTOL" "cd of the hole at $h"; done <cd.txt
done
exit 0
