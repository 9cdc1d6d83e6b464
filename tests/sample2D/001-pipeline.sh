#!/bin/sh
# sample2D: the 2D pipeline along a cutline.  Checks: usage errors (a
# missing -cut, a bad number, an unknown method) exit 2 before any stage
# runs (no cut.2D); an unreadable input exits 1; a run on a 1 um clear
# space leaves cut.2D, rval.2D.binary (a 2D array etch2d reads and etch
# refuses), profile.plot with one set per print time and profile2D.ps; the
# space develops deeper at its centre than under the dark field (the
# profile's lowest point lies within the space, 1.5 to 2.5 um along the
# cut, and the resist 0.5 um along the cut is still at the top);
# bleach -cutline is deterministic.
. "$TOP/tests/lib/common.sh"
cat >mask.in <<'M'
wavelength 0.436
na 0.28
sigma 0.5
background dark
window -2 2 -2 2
rect -0.5 -2 0.5 2
grid 21 21
contour image.cont
M
cat >resist.in <<'R'
wavelength 0.436
resist thickness 0.5 index 1.68 dill 0.551 0.058 0.010
substrate 4.73 0.14
dose 150
develop kim 0.1143 0.0001683 4.667
grid nz 60
R
usage2() { "$@" >/dev/null 2>err.txt; st=$?; [ $st -eq 2 ] || fail "$*: exit $st, want 2"; }
usage2 sample2D -if mask.in -bf resist.in -et 10
usage2 sample2D -if mask.in -cut 0 x 1 1 -bf resist.in -et 10
usage2 sample2D -if mask.in -cut -2 0 2 0 -bf resist.in -et 10 -method nosuch
[ -e cut.2D ] && fail "a usage error ran a stage"
sample2D -if nosuch.in -cut -2 0 2 0 -bf resist.in -et 10 >/dev/null 2>err.txt &&
	fail "an unreadable mask did not fail"
sample2D -q -if mask.in -cut -2 0 2 0 -npts 41 -bf resist.in -et 20 -pt 10 ||
	fail "sample2D failed: $(cat err.txt)"
for f in cut.2D rval.2D.binary profile.plot profile2D.ps; do [ -s $f ] || fail "no $f"; done
n=$(grep -c '^0 4 -0.5 0$' profile.plot)
[ "$n" -eq 2 ] || fail "profile.plot has $n sets with the section's bounds, want 2"
etch -et 1 rval.2D.binary >/dev/null 2>&1 && fail "etch accepted the 2D array"
# the last set: its lowest point, and the height at 0.5 um
awk 'NF == 4 { set++ } set == 2 && NF == 2 { if (min == "" || $2 < min) { min = $2; xmin = $1 }
	if ($1 < 0.6 && $2 > top05) top05 = $2 }
	END { if (!(xmin >= 1.5 && xmin <= 2.5)) { print "lowest point at " xmin; exit 1 }
	      if (!(min < -0.05)) { print "the space did not develop: lowest z " min; exit 1 }
	      if (!(top05 > -0.05)) { print "the dark field developed: z " top05 " at 0.5 um"; exit 1 } }' \
	top05=-1 profile.plot || fail "the profile is not a developed space"
bleach -q -cutline -o again.bin cut.2D resist.in || fail "bleach -cutline"
same rval.2D.binary again.bin
exit 0
