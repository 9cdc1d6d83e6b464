# Compact fast-marching surfaces: etch -method fmm writes
# every rectangle of cells whose surface is one exactly horizontal plane
# as a few large triangles; -dense writes them cell by cell.  The two must
# be the same surface: per set, the same area and enclosed volume (sum of
# p0 . p1 x p2 / 6) to 1e-9 relative, and the same open edges (count and
# length, vertices welded at 1e-9 um: tests/etch/fmm_exact surfstat), so
# no crack and no T-junction was made.  Case: a 0.9 um opaque line in a
# clear field, 3 um cell, 31 x 31 x 60, Shipley 1470 (examples/
# clear-lines-2) at 80 mJ/cm2, developed 20 s: from 5 s the field is
# cleared to the substrate (merged) beside the line (not), and at 40
# mJ/cm2 (nothing reaches the substrate) nothing may change at all.
. "$TOP/tests/lib/common.sh"
X=$BUILD/tests/etch/fmm_exact
[ -x "$X" ] || fail "$X not built"
E=$TOP/examples/clear-lines-2
cat >mask.in <<'M'
wavelength 0.436
na 0.28
sigma 0.5
background clear
window -1.5 1.5 -1.5 1.5
rect -0.45 -1 0.45 1 0 0
grid 31 31
contour image.cont
M
splat -q -o image.cont mask.in || fail "splat"
for d in 80 40; do
	sed "s/^grid nz .*/grid nz 60/; s/^dose .*/dose $d/" "$E/resist.in" >r$d.in
	bleach -q -o r$d.bin image.cont r$d.in || fail "bleach (dose $d)"
	etch -q -et 20 -pt 5 -method fmm -tol 0 -o c$d.plot r$d.bin || fail "etch -method fmm ($d)"
	etch -q -et 20 -pt 5 -method fmm -dense -o d$d.plot r$d.bin || fail "etch -method fmm -dense ($d)"
	$X surfstat c$d.plot >c$d.txt || fail "surfstat c$d.plot"
	$X surfstat d$d.plot >d$d.txt || fail "surfstat d$d.plot"
	[ "$(grep -c '' c$d.txt)" -eq 4 ] || fail "dose $d: $(grep -c '' c$d.txt) sets, want 4"
	paste c$d.txt d$d.txt | awk -v dose=$d '
		function rel(a, b) { d = a - b; if (d < 0) d = -d; s = b < 0 ? -b : b; return d / (s > 1e-3 ? s : 1e-3) }
		{ # set k triangles n area a volume v open o length l (twice)
		  print "dose " dose ": set " $2 ": " $4 " triangles (dense " $16 "), area " $6 ", volume " $8 ", open " $10 " " $12
		  if (rel($6, $18) > 1e-9) { print "  area differs: " $6 " " $18; bad = 1 }
		  if (rel($8, $20) > 1e-9) { print "  volume differs: " $8 " " $20; bad = 1 }
		  if ($10 != $22 || rel($12, $24) > 1e-9) { print "  open edges differ: " $10 " " $12 " / " $22 " " $24; bad = 1 }
		  if ($4 > $16) { print "  more triangles than dense"; bad = 1 }
		  if ($4 < $16) fewer++ }
		END { if (bad) exit 1
		      if (dose == 80 && fewer < 3) { print "dose 80: merged in " fewer " sets, want 3 or more"; exit 1 }
		      if (dose == 40 && fewer > 0) { print "dose 40: triangles merged where nothing is flat"; exit 1 } }' ||
		fail "compact and dense surfaces differ (dose $d)"
done
# the flat regions really shrink: the cleared field of the last set
n=$(sed -n '4s/.* triangles \([0-9]*\) .*/\1/p' c80.txt)
m=$(sed -n '4s/.* triangles \([0-9]*\) .*/\1/p' d80.txt)
[ $((n * 100)) -lt $((m * 97)) ] || fail "last set: $n triangles compact, $m dense: under 3 % saved"
exit 0
