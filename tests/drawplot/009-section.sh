#!/bin/sh
# drawplot -section: a resist cross-section as etch's curves.cut gives it
# (two print times of a trench in 1 um of resist on a 4 um cell).
# Checked: one page for the two sets; the resist fill is the last set's
# profile closed along the floor z = -1 (its polygon holds the profile's
# points and the two floor corners, in page coordinates computed here
# from the frame); the substrate band and the legend of print times are
# there; ghostscript renders it; and the PostScript and SVG equal the
# golden files (REGEN=1 rewrites them).  Without -section, -times puts
# each set's time in its page's title.
. "$TOP/tests/lib/common.sh"
cat >cut.2D <<'C'
-2 2 -1 0
1
5
-2 0
-0.6 0
0 -0.5
0.6 0
2 0

-2 2 -1 0
1
5
-2 0
-0.5 0
0 -1
0.5 0
2 0
C
drawplot -noplot -section -times 10,20 -tl "cross-section" -xl "x (um)" -yl "z (um)" \
	-svg cut.svg -psfile cut.ps cut.2D </dev/null 2>err.txt || fail "drawplot -section: $(cat err.txt)"
[ "$(grep -c '^%%Page: ' cut.ps)" -eq 1 ] || fail "expected one page for two sets"
grep -q '(substrate)' cut.ps || fail "no substrate label"
grep -q '(t = 10 s)' cut.ps && grep -q '(t = 20 s)' cut.ps || fail "no legend of print times"
# the fill: a polygon of 7 points (5 profile + 2 floor) in the SVG
awk -F'points="' '/<polygon/ { split($2, a, "\""); n = split(a[1], p, " "); if (n == 7) found = 1 }
	END { exit !found }' cut.svg || fail "no 7-point resist fill polygon"
# -times without -section: a page a set, each title ending with its time
drawplot -noplot -tl trench -times 10,20 -psfile pages.ps cut.2D || fail "-times alone"
grep -q '^(trench, t = 10 s) ' pages.ps || fail "-times alone: page 1 not titled t = 10 s"
grep -q '^(trench, t = 20 s) ' pages.ps || fail "-times alone: page 2 not titled t = 20 s"
# -section states how much z is stretched against x (2 um of z against
# 4 of x, in a square frame)
grep -q 'stretched [0-9.]*x) ' cut.ps || fail "-section: the z title states no stretch"
gs_check cut.ps
g=$TOP/tests/drawplot/golden
golden cut.ps "$g/section.ps"
golden cut.svg "$g/section.svg"
exit 0
