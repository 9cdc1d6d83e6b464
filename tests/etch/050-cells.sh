#!/bin/sh
# etch -method cell and huygens: the thesis' cell methods in 3D (3.6,
# 4.5.1, Figure 4.3).  Checks, on a uniform 1 um/s rate in 1 x 1 x 0.5 um:
#   - huygens from a seed at 10 cells a step (cells 0.01 um, dt 0.1):
#     every face centre of the etched region at 0.3 s lies within 3 % of
#     the radius plus one cell of the hemisphere about the seed (thesis
#     4.5.1: faceted, but close);
#   - Dill's cells from a seed overshoot the sphere somewhere by more than
#     4 % (the facets of 3.6, as the octagons of 3.4.1) and undershoot by
#     no more than one cell plus 3 %;
#   - two seeds (Figure 4.3) give one region: the two hemispheres merge
#     and no face lies inside either ball (cells cannot loop);
#   - from the resist top, huygens gives the flat front at z = -R t;
#   - -cut, -deloop and -xcheck are refused with the cell methods.
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
$MKRATE -o u.bin 3 3 3 -0.5 0.5 -0.5 0.5 -0.5 0 1 || fail "mkrate"
# face centres of the last set: "x y z" per face
centres() {
	awk 'NF == 6 { set++; next } NF == 1 { n = $1; k = 0; next }
		NF == 3 { k++; if (k <= 4) { sx += $1; sy += $2; sz += $3 }
			if (k == 5) { if (set == last) print sx / 4, sy / 4, sz / 4; sx = sy = sz = 0 } }' \
		last="$2" "$1"
}
etch -q -method huygens -seed 0 0 0 -seg 0.01 -dt 0.1 -et 0.3 -o h.plot u.bin || fail "huygens"
centres h.plot 1 | awk '{ r = sqrt($1 * $1 + $2 * $2 + $3 * $3); e = r - 0.3; if (e < 0) e = -e
	if (e > w) w = e; n++ } END { print n " faces, worst " w
	if (n < 1000 || w > 0.03 * 0.3 + 0.01) exit 1 }' || fail "huygens hemisphere off"
etch -q -method cell -seed 0 0 0 -seg 0.01 -et 0.3 -o c.plot u.bin || fail "cell"
centres c.plot 1 | awk '{ r = sqrt($1 * $1 + $2 * $2 + $3 * $3) / 0.3 - 1
	if (r > over) over = r; if (-r > under) under = -r } END { print "over " over ", under " under
	if (!(over > 0.04) || under > 0.03 + 0.01 / 0.3) exit 1 }' || fail "cell facets not as the thesis'"
etch -q -method huygens -seed -0.2 0 0 -seed 0.2 0 0 -seg 0.01 -dt 0.1 -et 0.3 -o two.plot u.bin ||
	fail "two seeds"
centres two.plot 1 | awk '{ a = sqrt(($1 + 0.2) ^ 2 + $2 * $2 + $3 * $3); b = sqrt(($1 - 0.2) ^ 2 + $2 * $2 + $3 * $3)
	if (a < 0.3 * 0.97 - 0.01 && b < 0.3 * 0.97 - 0.01) bad++ } END { if (bad) { print bad " faces inside both balls"; exit 1 } }' ||
	fail "two seeds: faces inside the merged region"
etch -q -method huygens -seg 0.02 -dt 0.1 -et 0.2 -o top.plot u.bin || fail "huygens from the top"
centres top.plot 1 | awk '{ if ($3 < lo || n == 0) lo = $3; if ($3 > hi || n == 0) hi = $3; n++ }
	END { print "z " lo " .. " hi; if (lo < -0.2 - 0.02 || hi > -0.2 + 0.02) exit 1 }' ||
	fail "huygens from the top is not flat at -0.2"
for o in "-cut x 0" "-deloop" "-xcheck"; do
	# shellcheck disable=SC2086
	etch -q -method cell $o -et 0.1 u.bin >/dev/null 2>&1
	[ $? -eq 2 ] || fail "-method cell $o not refused as a usage error"
done
exit 0
