# Decimated fast-marching surfaces (src/lib/geometry/tri_decimate.c):
# etch -method fmm (default -tol: 0.02 of the x-y spacing, here 0.002 um)
# against -dense, on the contact of examples/contact in a 3 um cell (31 x
# 31 x-y nodes at 0.1 um, nz 100, bake; nz 150 without), developed 60 s,
# sets at 20, 40, 60 s.  Per set, by tests/lib/meshcheck (independent
# code, brute-force point-to-triangle distances):
# - the two-sided distance, sampled at 15 points per triangle of each
#   surface to the nearest triangle of the other, <= tol + 1e-9 um (the
#   vertices of the dense surface are within tol by construction, the
#   written vertices are dense vertices; etch(1));
# - enclosed volume within area x tol of the dense one (a surface within
#   tol moves the volume at most so); area within 0.5 % (the plane pieces
#   cut the standing-wave ripples' chords);
# - conforming: no edge of three triangles or of two in one direction, no
#   open edge off the box faces, the same Euler characteristic;
# - at most half the dense triangles (measured 0.21-0.25 with bake, 0.40-0.45
#   without);
# - the contact's CDs at 10, 50, 90 % of the height (measure -rel) within
#   0.001 um of the dense surface's.
. "$TOP/tests/lib/common.sh"
M=$BUILD/tests/lib/meshcheck
[ -x "$M" ] || fail "$M not built"
E=$TOP/examples/contact
TOL=0.002
sed 's/^window .*/window -1.5 1.5 -1.5 1.5/; s/^grid .*/grid 31 31/; /^cutline/d' "$E/mask.in" >mask.in
sed 's/^grid nz .*/grid nz 100/' "$E/resist.in" >bake.in
sed 's/^grid nz .*/grid nz 150/' "$E/resist-nobake.in" >nobake.in
splat -q -o image.cont mask.in || fail "splat"
for r in bake nobake; do
	bleach -q -o $r.bin image.cont $r.in || fail "bleach ($r)"
	etch -q -et 60 -pt 20 -method fmm -o dec-$r.plot $r.bin || fail "etch -method fmm ($r)"
	etch -q -et 60 -pt 20 -method fmm -dense -o dense-$r.plot $r.bin || fail "etch -dense ($r)"
	$M stat dec-$r.plot >sd-$r.txt || fail "meshcheck stat dec-$r.plot"
	$M stat dense-$r.plot >sn-$r.txt || fail "meshcheck stat dense-$r.plot"
	$M dist dec-$r.plot dense-$r.plot 0.05 >dist-$r.txt || fail "meshcheck dist ($r)"
	[ "$(grep -c '' sd-$r.txt)" -eq 3 ] || fail "$r: $(grep -c '' sd-$r.txt) sets, want 3"
	paste sd-$r.txt sn-$r.txt dist-$r.txt | awk -v r=$r -v tol=$TOL '
		# set k triangles n area a volume v vertices . edges . euler e open o offbox f bad b (x2), set k ab d ba d
		{ n = $4; a = $6; v = $8; chi = $14; off = $18; bad = $20
		  n0 = $24; a0 = $26; v0 = $28; chi0 = $34; off0 = $38; bad0 = $40; ab = $44; ba = $46
		  print r ": set " $2 ": " n " triangles (dense " n0 "), area " a " (" a0 "), volume " v " (" v0 "), distance " ab " " ba
		  if (ab > tol + 1e-9 || ba > tol + 1e-9) { print "  distance over tol " tol; fail = 1 }
		  dv = v - v0; if (dv < 0) dv = -dv
		  if (dv > a0 * tol) { print "  volume moved " dv ", more than area x tol " a0 * tol; fail = 1 }
		  da = a - a0; if (da < 0) da = -da
		  if (da > 0.005 * a0) { print "  area moved " da; fail = 1 }
		  if (bad || off || bad0 || off0) { print "  not conforming: bad " bad " offbox " off " (dense " bad0 " " off0 ")"; fail = 1 }
		  if (chi != chi0) { print "  Euler characteristic " chi ", dense " chi0; fail = 1 }
		  if (2 * n > n0) { print "  more than half the dense triangles"; fail = 1 } }
		END { exit fail }' || fail "decimated and dense surfaces differ ($r)"
	measure -rel 10,50,90 -hole 0 0 dec-$r.plot >cd-dec-$r.txt || fail "measure dec-$r.plot"
	measure -rel 10,50,90 -hole 0 0 dense-$r.plot >cd-dense-$r.txt || fail "measure dense-$r.plot"
	paste cd-dec-$r.txt cd-dense-$r.txt | awk -v r=$r '/^#/ { next }
		{ d = $2 - $7; if (d < 0) d = -d; print r ": z " $1 " cd " $2 " (dense " $7 ")"
		  if (d > 0.001) { print "  CD moved " d " um"; fail = 1 } ; n++ }
		END { if (n != 3) { print "  " n " CD lines, want 3"; fail = 1 }; exit fail }' ||
		fail "CDs of the decimated surface ($r)"
done
exit 0
