# Decimated sets extracted on a subset of the z nodes (src/etch/fmm_levels.c):
# examples/defect's Shipley 1470 resist at 80 % (bake, nz 300: 0.0023 um
# in z against 0.1 um in x-y) in a 1.6 x 1.2 um window (the defect, the
# space, the lines' edges; the image of this window alone), -et 30 -pt
# 10.  Per set, against -dense (tests/lib/meshcheck, independent code):
# - the two-sided distance, 15 samples a triangle, <= tol + 1e-9 um
#   (0.002 um, the default: the levels' share and the decimator's add up
#   to it);
# - the written vertices' distances to the dense surface: max <= tol,
#   mean <= tol / 10 (measured 0-0.00009 um: the last set keeps every
#   level, where the levels would keep over a third);
# - conforming as -dense (no bad or off-box open edges, same Euler
#   characteristic) and under a quarter of its triangles (measured
#   0.06-0.12, as the decimator alone on every level);
# - the space's width at 10, 50, 90 % of the height (measure -space)
#   within tol of the dense surface's;
# and the same bytes for 1 and 2 threads.
. "$TOP/tests/lib/common.sh"
M=$BUILD/tests/lib/meshcheck
[ -x "$M" ] || fail "$M not built"
D=$TOP/examples/defect
TOL=0.002
cat >mask.in <<'X'
wavelength 0.436
na 0.28
sigma 0.5
background clear
window -0.8 0.8 -0.6 0.6
rect 0.65 -0.6 0.8 0.6 0 0
rect -0.8 -0.6 -0.65 0.6 0 0
rect -0.25 -0.25 0.25 0.25 0 0
grid 17 13
contour image.cont
X
splat -q -o image.cont mask.in || fail "splat"
bleach -q -o r.bin image.cont "$D/resist-shipley1470-80.in" || fail "bleach"
etch -q -threads 1 -et 30 -pt 10 -method fmm -o dec.plot r.bin || fail "etch -method fmm"
etch -q -threads 2 -et 30 -pt 10 -method fmm -o dec2.plot r.bin || fail "etch -method fmm -threads 2"
cmp -s dec.plot dec2.plot || fail "1 and 2 threads differ"
etch -q -et 30 -pt 10 -method fmm -dense -o dense.plot r.bin || fail "etch -dense"
$M stat dec.plot >sd.txt || fail "meshcheck stat dec.plot"
$M stat dense.plot >sn.txt || fail "meshcheck stat dense.plot"
$M dist dec.plot dense.plot 0.05 >dist.txt || fail "meshcheck dist"
$M nodes dec.plot dense.plot 0.05 >nodes.txt || fail "meshcheck nodes"
[ "$(grep -c '' sd.txt)" -eq 3 ] || fail "$(grep -c '' sd.txt) sets, want 3"
paste sd.txt sn.txt dist.txt nodes.txt | awk -v tol=$TOL '
	# set k triangles n ... (x2), set k ab d ba d, set k nodes n mean m p95 p max x
	{ n = $4; chi = $14; off = $18; bad = $20; n0 = $24; chi0 = $34; ab = $44; ba = $46
	  mean = $52; p95 = $54; max = $56
	  print "set " $2 ": " n " triangles (dense " n0 "), distance " ab " " ba ", nodes mean " mean " p95 " p95 " max " max
	  if (ab > tol + 1e-9 || ba > tol + 1e-9) { print "  distance over tol " tol; fail = 1 }
	  if (max > tol || mean > tol / 10) { print "  written vertices too far"; fail = 1 }
	  if (bad || off || chi != chi0) { print "  not conforming"; fail = 1 }
	  if (4 * n > n0) { print "  more than a quarter of the dense triangles"; fail = 1 } }
	END { exit fail }' || fail "decimated and dense surfaces differ"
for s in 1 2 3; do
	measure -s $s -rel 10,50,90 -space 0 0.5 x dec.plot >cd-dec.txt 2>/dev/null || fail "measure dec.plot set $s"
	measure -s $s -rel 10,50,90 -space 0 0.5 x dense.plot >cd-dense.txt 2>/dev/null || fail "measure dense.plot set $s"
	paste cd-dec.txt cd-dense.txt | awk -v s=$s -v tol=$TOL '/^#/ { next }
		{ d = $2 - $6; if (d < 0) d = -d; print "set " s ": z " $1 " cd " $2 " (dense " $6 ")"
		  if (d > tol) { print "  CD moved " d " um"; fail = 1 } ; n++ }
		END { if (n != 3) { print "  " n " CD lines, want 3"; fail = 1 }; exit fail }' ||
		fail "widths of the decimated surface (set $s)"
done
exit 0
