# measure on synthetic surfaces whose sections are known exactly, written
# by tests/measure/synth.awk with the triangles in random order (two
# seeds, results compared byte for byte) and random vertex order and
# orientation:
#   - a truncated-cone hole (bottom radius 0.3, top 0.6 um, 0.7 um resist),
#   - a trapezoidal line (bottom 0.8, top 0.5 um),
#   - an undercut space (bottom 0.9, top 0.5 um: swa above 90) and a
#     re-entrant hole (radius 0.6 at the bottom, 0.3 at the top),
#   - a hole that does not clear (bottom at -0.4 um, cd 0 below),
#   - a hole and a line with 0.05 um of resist loss.
# -plot writes the table's cd against z.
# Expected: cd within 0.5 % (the accuracy asked; a 256-sided polygon
# stands for the cone's circle, 1e-4 off), swa within 0.3 degree, resist
# loss within 1e-6 um, cleared exactly.
. "$TOP/tests/lib/common.sh"
synth() { awk -f "$TOP/tests/measure/synth.awk" "$@"; }
PI=3.14159265358979

# check TABLE Z CD: the row of height Z has cd within 0.5 % of CD (or 0)
check() {
	awk -v z="$2" -v cd="$3" '!/^#/ && ($1 - z < 1e-9 && z - $1 < 1e-9) { found = 1
		d = $2 - cd; if (d < 0) d = -d
		if (cd == 0 ? $2 != 0 : d > 0.005 * cd) { print "cd " $2 " at z " z ", expected " cd; exit 1 } }
		END { if (!found) { print "no row for z = " z; exit 1 } }' "$1" || fail "$1: $(cat "$1")"
}
figure() { awk -v k="# $2" 'index($0, k " ") == 1 { print $3 }' "$1"; }

# truncated cone: r(z) = 0.3 + 0.3 (z + 0.7) / 0.7; swa = 90 - atan(0.3 / 0.7)
synth -v kind=rev -v prof="0 -0.7 0.3 -0.7 0.6 0 3 0" -v seed=1 >cone.plot
synth -v kind=rev -v prof="0 -0.7 0.3 -0.7 0.6 0 3 0" -v seed=2 >cone2.plot
measure -rel 0,10,50,90,100 -hole 0 0 cone.plot >cone.txt || fail "measure cone: $(cat cone.txt)"
measure -rel 0,10,50,90,100 -hole 0 0 cone2.plot >cone2.txt || fail "measure cone2"
same cone.txt cone2.txt
for p in 0 10 50 90 100; do
	z=$(awk -v p=$p 'BEGIN { printf "%.10g", -0.7 + 0.007 * p }')
	check cone.txt "$z" "$(awk -v p=$p 'BEGIN { print 2 * (0.3 + 0.3 * p / 100) }')"
done
close "$(figure cone.txt swa)" "$(awk -v pi=$PI 'BEGIN { print 90 - atan2(0.3, 0.7) * 180 / pi }')" 0.3 "cone swa"
[ "$(figure cone.txt cleared)" = yes ] || fail "cone: not cleared: $(cat cone.txt)"
close "$(figure cone.txt resist_loss)" 0 1e-6 "cone resist loss"
# the extents through the centre: the polygon's vertices lie on the axes
awk '!/^#/ && $1 == -0.35 { if ($4 < 0.899 || $4 > 0.9001 || $5 < 0.899 || $5 > 0.9001) exit 1 }' cone.txt ||
	fail "cone extents at z = -0.35: $(cat cone.txt)"
# the same hole measured from off its centre, and by -at
measure -at -0.35 -hole 0.2 -0.1 cone.plot >off.txt || fail "measure off-centre"
check off.txt -0.35 0.9

# -plot: one set, one curve of (z, cd) in increasing z, the table's values
measure -rel 90,10,50 -hole 0 0 -plot cd.plot cone.plot >plot.txt || fail "measure -plot"
grep -v '^#' cd.plot | awk 'NR == 1 { if ($1 != -0.7 || $2 != 0 || $3 != 0 || $4 <= 1.14) exit 1; next }
	NR == 2 || NR == 3 { if ($1 != (NR == 2 ? 1 : 3)) exit 1; next }
	{ if (NR > 4 && $1 <= z) exit 1; z = $1; n++ } END { exit n != 3 }' ||
	fail "cd.plot is not one curve of 3 points in increasing z: $(cat cd.plot)"
awk 'NR == FNR { if (!/^#/) cd[sprintf("%.6f", $1)] = $2; next }
	/^#/ { next }
	FNR > 4 { d = cd[sprintf("%.6f", $1)] - $2; if (d > 1e-6 || d < -1e-6) exit 1 }' plot.txt cd.plot ||
	fail "cd.plot differs from the table: $(cat cd.plot plot.txt)"

# trapezoidal line along y: width 0.8 - 0.3 (z + 0.7) / 0.7
synth -v kind=ext -v prof="-2.5 -0.7 -0.4 -0.7 -0.25 0 0.25 0 0.4 -0.7 2.5 -0.7" -v seed=3 >line.plot
measure -rel 5,50,95 -line 0 0 x line.plot >line.txt || fail "measure line: $(cat line.txt)"
for p in 5 50 95; do
	z=$(awk -v p=$p 'BEGIN { printf "%.10g", -0.7 + 0.007 * p }')
	check line.txt "$z" "$(awk -v p=$p 'BEGIN { print 0.8 - 0.3 * p / 100 }')"
done
close "$(figure line.txt swa)" "$(awk -v pi=$PI 'BEGIN { print 90 - atan2(0.15, 0.7) * 180 / pi }')" 0.3 "line swa"
[ "$(figure line.txt cleared)" = yes ] || fail "line: foot not cleared: $(cat line.txt)"
close "$(figure line.txt resist_loss)" 0 1e-6 "line resist loss"
# the space beside the line, from its wall (x = 0.325 at 50 %) to the box edge
measure -rel 50 -space 1 0 x line.plot >sp.txt 2>sp.err || fail "measure space beside the line"
check sp.txt -0.35 2.175
grep -q "reaches the box edge" sp.err || fail "no warning that the space reaches the box edge"

# undercut space along y: 0.9 at the bottom, 0.5 at the top; swa above 90
synth -v kind=ext -v prof="-2.5 0 -0.25 0 -0.45 -0.7 0.45 -0.7 0.25 0 2.5 0" -v seed=4 >under.plot
measure -rel 10,50,90 -space 0 0 x under.plot >under.txt || fail "measure undercut: $(cat under.txt)"
for p in 10 50 90; do
	z=$(awk -v p=$p 'BEGIN { printf "%.10g", -0.7 + 0.007 * p }')
	check under.txt "$z" "$(awk -v p=$p 'BEGIN { print 0.9 - 0.4 * p / 100 }')"
done
close "$(figure under.txt swa)" "$(awk -v pi=$PI 'BEGIN { print 90 + atan2(0.2, 0.7) * 180 / pi }')" 0.3 "undercut swa"
# the resist under the overhang: a line measured there is the overhang's
# own width (from the wall to the box edge)
measure -rel 10 -line -0.44 0 x under.plot >ov.txt 2>/dev/null || fail "measure under the overhang"
# (at 10 % the left wall is at x = -0.45 + 0.2 * 0.1)
check ov.txt -0.63 "$(awk 'BEGIN { print 2.5 - 0.45 + 0.2 * 0.1 }')"
[ "$(figure under.txt cleared)" = yes ] || fail "undercut space not cleared"

# a re-entrant hole (radius 0.6 at the bottom, 0.3 at the top): the
# resist overhangs it, swa = 90 + atan(0.3 / 0.7)
synth -v kind=rev -v prof="0 -0.7 0.6 -0.7 0.3 0 3 0" -v seed=8 >reent.plot
measure -rel 10,50,90 -hole 0 0 reent.plot >reent.txt || fail "measure re-entrant: $(cat reent.txt)"
for p in 10 50 90; do
	z=$(awk -v p=$p 'BEGIN { printf "%.10g", -0.7 + 0.007 * p }')
	check reent.txt "$z" "$(awk -v p=$p 'BEGIN { print 2 * (0.6 - 0.3 * p / 100) }')"
done
close "$(figure reent.txt swa)" "$(awk -v pi=$PI 'BEGIN { print 90 + atan2(0.3, 0.7) * 180 / pi }')" 0.3 "re-entrant swa"

# a hole that stops at z = -0.4: cd 0 below, not cleared, swa "-"
synth -v kind=rev -v prof="0 -0.4 0.2 -0.4 0.5 0 3 0" -v seed=5 >shallow.plot
measure -at -0.6,-0.2 -hole 0 0 shallow.plot >shallow.txt || fail "measure shallow"
check shallow.txt -0.6 0
check shallow.txt -0.2 "$(awk 'BEGIN { print 2 * (0.2 + 0.3 * 0.2 / 0.4) }')"
[ "$(figure shallow.txt cleared)" = no ] || fail "shallow hole cleared: $(cat shallow.txt)"
[ "$(figure shallow.txt swa)" = - ] || fail "shallow hole has a swa: $(cat shallow.txt)"

# resist loss: the top at -0.05 around a hole and on a line
synth -v kind=rev -v prof="0 -0.7 0.3 -0.7 0.5 -0.05 3 -0.05" -v seed=6 >loss.plot
measure -rel 10,50 -hole 0 0 loss.plot >loss.txt || fail "measure loss"
close "$(figure loss.txt resist_loss)" 0.05 1e-6 "hole resist loss"
check loss.txt -0.35 "$(awk 'BEGIN { print 2 * (0.3 + 0.2 * 0.35 / 0.65) }')"
synth -v kind=ext -v prof="-2.5 -0.7 -0.4 -0.7 -0.3 -0.05 0.3 -0.05 0.4 -0.7 2.5 -0.7" -v seed=7 >lloss.plot
measure -rel 10,50 -line 0 0 x lloss.plot >lloss.txt || fail "measure line loss"
close "$(figure lloss.txt resist_loss)" 0.05 1e-6 "line resist loss"
exit 0
