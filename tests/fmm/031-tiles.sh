# Decimation by tiles (etch(1), FMM_TILE_CELLS = 128 rate-grid cells a
# side): a window of 140 x 6 cells (0.1 um; the contact resist of
# examples/contact with bake, nz 60) is decimated as two tiles with a
# seam at x = 0, through a 0.8 um clear line across it.  The decimated
# surface must stay conforming across the seam (tests/lib/meshcheck: no
# edge of three triangles or of two in one direction, no open edge off
# the box, the Euler characteristic of -dense), within tol (0.002 um) of
# the dense one (two-sided, 15 samples a triangle, + 1e-9 um), and have
# under half its triangles; and the same for 1, 2 and 3 threads (cmp).
. "$TOP/tests/lib/common.sh"
M=$BUILD/tests/lib/meshcheck
[ -x "$M" ] || fail "$M not built"
E=$TOP/examples/contact
cat >mask.in <<'X'
wavelength 0.436
na 0.28
sigma 0.5
background dark
window -7 7 -0.3 0.3
rect -0.4 -0.3 0.4 0.3 1 0
grid 141 7
contour image.cont
X
sed 's/^grid nz .*/grid nz 60/' "$E/resist.in" >r.in
splat -q -o image.cont mask.in || fail "splat"
bleach -q -o r.bin image.cont r.in || fail "bleach"
for t in 1 2 3; do
	etch -q -threads $t -et 60 -pt 30 -method fmm -o dec$t.plot r.bin || fail "etch -method fmm -threads $t"
done
cmp -s dec1.plot dec2.plot && cmp -s dec1.plot dec3.plot && cmp -s dec1.plot.2D dec3.plot.2D ||
	fail "decimated output differs with the thread count"
etch -q -et 60 -pt 30 -method fmm -dense -o dense.plot r.bin || fail "etch -dense"
$M stat dec1.plot >sd.txt && $M stat dense.plot >sn.txt && $M dist dec1.plot dense.plot 0.05 >dist.txt ||
	fail "meshcheck"
[ "$(grep -c '' sd.txt)" -eq 2 ] || fail "$(grep -c '' sd.txt) sets, want 2"
paste sd.txt sn.txt dist.txt | awk -v tol=0.002 '
	{ n = $4; chi = $14; off = $18; bad = $20; n0 = $24; chi0 = $34; ab = $44; ba = $46
	  print "set " $2 ": " n " triangles (dense " n0 "), euler " chi " (" chi0 "), open off the box " off ", bad " bad ", distance " ab " " ba
	  if (ab > tol + 1e-9 || ba > tol + 1e-9) { print "  distance over tol"; fail = 1 }
	  if (bad || off || chi != chi0) { print "  not conforming"; fail = 1 }
	  if (2 * n > n0) { print "  more than half the dense triangles"; fail = 1 } }
	END { exit fail }' || fail "tiled decimation"
exit 0
