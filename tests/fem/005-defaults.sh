# fem without an engine option measures every point: a 3 x 3 matrix
# (focus -0.3, 0, 0.3 um; dose 80, 100, 120 mJ/cm2) of
# examples/contact-highna shrunk to a 1.6 um cell, a 17 x 17 image grid,
# 5 image planes and nz 41 (the engine left to fem's default: fast
# marching, written to etch.opts) gives a cd for all nine points, each
# open (cleared).  With -accuracy check every point's table gains err, and
# the cds are byte for byte those of the plain sweep (the same grid);
# with -accuracy 8 on two points fem chooses the grid at the nominal point
# (its levels' tables in DIR/accuracy) and every point's err is within 8 %
# of its cd.  femwin -resolution prints the inputs' grids (17 17 41) and
# refuses a resist whose grid statement resamples the image; -accuracy P
# with -n is a usage error (choosing the grid runs the nominal point).
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact-highna
sed 's/^window .*/window -0.8 0.8 -0.8 0.8/; s/^grid .*/grid 17 17/; s/planes 11/planes 5/' \
	"$E/mask.in" >mask.in
sed 's/^grid nz .*/grid nz 41/' "$E/resist.in" >resist.in
M="-rel 10,50,90 -hole 0 0"

[ "$(femwin -resolution mask.in resist.in)" = "17 17 41" ] ||
	fail "femwin -resolution: $(femwin -resolution mask.in resist.in)"
sed 's/^grid nz .*/grid nx 20 ny 20 nz 41/' resist.in >resampled.in
expect_file_error femwin resampled.in -resolution mask.in resampled.in

fem -q -if mask.in -bf resist.in -et 60 -dose 80,100,120 -focus -0.3,0,0.3 -measure "$M" \
	-d plain -j 2 || fail "fem without an engine option: some point failed"
grep -q -- "'-method' 'fmm'" plain/etch.opts || fail "the default engine is not fast marching: $(cat plain/etch.opts)"
awk '!/^#/ { n++; if (!($3 > 0) || $5 != 1) { print "point " $1 " " $2 ": " $0; bad = 1 } }
	END { exit bad || n != 9 }' plain/fem.dat || fail "not nine open points: $(cat plain/fem.dat)"

fem -q -if mask.in -bf resist.in -et 60 -dose 80,100,120 -focus -0.3,0,0.3 -measure "$M" \
	-d check -j 2 -accuracy check || fail "fem -accuracy check"
same plain/fem.dat check/fem.dat
for t in check/f*/d*/measure.dat; do
	head -n 1 "$t" | grep -q ' err$' || fail "$t: no err column"
done

fem -q -if mask.in -bf resist.in -et 60 -dose 90,110 -focus 0 -measure "$M" \
	-d acc -j 2 -accuracy 8 || fail "fem -accuracy 8"
[ "$(ls acc/accuracy/*.dat | wc -l)" -ge 2 ] || fail "no levels in acc/accuracy: $(ls acc/accuracy)"
for t in acc/f0/d90/measure.dat acc/f0/d110/measure.dat; do
	awk '!/^#/ { n++; if (!($6 <= 0.08 * $2)) { print "err " $6 " of cd " $2; bad = 1 } }
		END { exit bad || n != 3 }' "$t" || fail "$t: $(cat "$t")"
done

st=0
fem -q -if mask.in -bf resist.in -et 60 -dose 90 -focus 0 -measure "$M" -d n -n -accuracy 2 \
	2>err.txt || st=$?
[ $st -eq 2 ] || fail "-accuracy 2 with -n: exit $st, expected 2"
grep -q "not with -n" err.txt || fail "-accuracy 2 with -n: $(cat err.txt)"
exit 0
