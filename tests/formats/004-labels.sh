# The labels line of plot and contour files (plot3d(5) LABELS, plot2d(5),
# contour(5)): the simulators write it, conv and contour -c keep it, the
# plot programs run by hand on a simulator's output label the axes in
# micrometres (checked in the PostScript text), an explicit label (command
# line, options-file) still wins, a file without the line reads as before
# (its picture is byte for byte the one with the labels given as options),
# and a malformed line is one error naming the file and line.
. "$TOP/tests/lib/common.sh"
F=$BUILD/tests/lib/fmtcat
MK=$BUILD/tests/lib/mkrate
built "$MK"
# ps_has FILE TEXT: the PostScript draws the string TEXT ("(" and ")" escaped)
ps_has() {
	_t=$(printf '%s' "$2" | sed 's/[()]/\\&/g')
	grep -qF "($_t) " "$1" || fail "$1 does not draw \"$2\": $(grep '^(' "$1" | head -n 6 | tr '\n' ' ')"
}
ps_hasnt() {
	_t=$(printf '%s' "$2" | sed 's/[()]/\\&/g')
	! grep -qF "($_t) " "$1" || fail "$1 draws \"$2\""
}

# etch's outputs: curves.plot (3D), curves.plot.2D, curves.cut
"$MK" -o r.bin 9 9 6 -1 1 -1 1 -0.5 0 '0.2 + 0.5 * exp(-(x^2 + y^2) / 0.2)' || fail "mkrate"
etch -q -et 1 -pt 0.5 -cut y 0 r.bin || fail "etch"
[ "$(head -n 1 curves.plot)" = '# labels title "Developed resist surface" x "x (um)" y "y (um)" z "z (um)"' ] ||
	fail "curves.plot labels: $(head -n 1 curves.plot)"
[ "$(head -n 1 curves.plot.2D)" = '# labels title "Developed resist surface, seen from above" x "x (um)" y "y (um)"' ] ||
	fail "curves.plot.2D labels: $(head -n 1 curves.plot.2D)"
[ "$(head -n 1 curves.cut)" = '# labels title "Resist cross-section" x "x (um)" y "z (um)"' ] ||
	fail "curves.cut labels: $(head -n 1 curves.cut)"
etch -q -et 1 -cut x 0 -o xc.plot r.bin || fail "etch -cut x"
head -n 1 xc.cut | grep -q ' x "y (um)" y "z (um)"$' || fail "a cut at x = 0 runs along y: $(head -n 1 xc.cut)"

# pdraw by hand: the file's labels, in micrometres
pdraw -noplot -psfile p.ps curves.plot || fail "pdraw"
for t in "Developed resist surface" "x (um)" "y (um)" "z (um)"; do ps_has p.ps "$t"; done
ps_hasnt p.ps "X-Axis"
# explicit labels win, one at a time: the others stay the file's
pdraw -noplot -psfile p2.ps -zl "depth (um)" -tl "Mine" curves.plot || fail "pdraw -zl"
ps_has p2.ps "depth (um)"; ps_has p2.ps "Mine"; ps_has p2.ps "x (um)"; ps_hasnt p2.ps "z (um)"
printf 'xlabel "across (um)"\n' >opts
pdraw -noplot -psfile p3.ps -o opts curves.plot || fail "pdraw -o"
ps_has p3.ps "across (um)"; ps_hasnt p3.ps "x (um)"; ps_has p3.ps "y (um)"
# the same file without the line: the old defaults, and with those labels
# given as options exactly the picture of the labelled file
grep -v '^#' curves.plot >old.plot
pdraw -noplot -psfile old.ps old.plot || fail "pdraw on a file without labels"
ps_has old.ps "X-Axis"; ps_has old.ps "3D Line Plot"
pdraw -noplot -psfile same.ps -tl "Developed resist surface" -xl "x (um)" -yl "y (um)" -zl "z (um)" old.plot ||
	fail "pdraw with labels"
# (the %%Title comment names the page title alike)
same p.ps same.ps

# drawplot by hand on the cross-section
drawplot -noplot -psfile d.ps curves.cut || fail "drawplot"
for t in "Resist cross-section" "x (um)" "z (um)"; do ps_has d.ps "$t"; done
drawplot -noplot -psfile d2.ps -yl "height" curves.cut || fail "drawplot -yl"
ps_has d2.ps "height"; ps_hasnt d2.ps "z (um)"; ps_has d2.ps "x (um)"

# splat's contour-file: contour labels it, conv and contour -c keep the labels
cat >m.in <<'E'
wavelength 0.436
na 0.28
sigma 0.5
window -1 1 -1 1
grid 11 11
background dark
rect -0.4 -0.4 0.4 0.4
contour img.cont
E
splat -q m.in || fail "splat"
head -n 1 img.cont | grep -q '^# labels title "Aerial image" x "x (um)" y "y (um)" z "intensity' ||
	fail "img.cont labels: $(head -n 1 img.cont)"
contour -noplot -psfile c.ps -cstep 0.2 img.cont || fail "contour"
ps_has c.ps "Aerial image"; ps_has c.ps "x (um)"; ps_has c.ps "y (um)"; ps_hasnt c.ps "X-AXIS"
contour -noplot -psfile c2.ps -cstep 0.2 -xl "u" img.cont || fail "contour -xl"
ps_has c2.ps "u"; ps_hasnt c2.ps "x (um)"
contour -noplot -ps -c 0.3 img.cont || fail "contour -c"
[ "$(head -n 1 image.cont)" = '# labels title "Aerial image" x "x (um)" y "y (um)"' ] ||
	fail "image.cont labels: $(head -n 1 image.cont)"
drawplot -noplot -psfile ic.ps image.cont || fail "drawplot image.cont"
ps_has ic.ps "x (um)"
conv -o img.3D img.cont || fail "conv"
[ "$(head -n 1 img.3D)" = "$(head -n 1 img.cont)" ] || fail "conv dropped the labels: $(head -n 1 img.3D)"
# (bleach reads a labelled image as before: tests/golden/contact-small's
# curves.plot gained only its labels line)

# reading: round trips keep the line; free comments; malformed lines
$F plot3 curves.plot rt.plot || fail "fmtcat plot3"
same curves.plot rt.plot
printf '# made by hand\n#\n  # labels x "a" title "T"\n# labels x "b"\n0 1 0 1\n1\n2\n0 0\n1 1\n' >hand.2D
$F plot2 hand.2D hand.out || fail "comments at the head"
[ "$(head -n 1 hand.out)" = '# labels title "T" x "b"' ] || fail "labels of hand.2D: $(head -n 1 hand.out)"
printf '0 1 0 1\n# late\n1\n2\n0 0\n1 1\n' >late.2D
expect_file_error drawplot late.2D -noplot -ps late.2D
printf '# labels w "a"\n0 1 0 1\n0\n' >bad1.2D
expect_file_error drawplot bad1.2D -noplot -ps bad1.2D
grep -q 'bad1.2D:1: labels: unknown key "w"' err.txt || fail "message: $(cat err.txt)"
printf '\n# labels x "a\n0 1 0 1\n0\n' >bad2.2D
expect_file_error drawplot bad2.2D -noplot -ps bad2.2D
grep -q 'bad2.2D:2: labels: x: unterminated' err.txt || fail "message: $(cat err.txt)"
printf '# labels z "depth"\n0 1 0 1\n0\n' >bad3.2D
expect_file_error drawplot bad3.2D -noplot -ps bad3.2D
printf '# labels x y\n0 1 0 1 0 1\n0\n' >bad4.3D
expect_file_error pdraw bad4.3D -noplot -ps bad4.3D
awk 'BEGIN { printf "# labels title \""; for (i = 0; i < 120; i++) printf "a"; print "\""; print "0 1 0 1"; print 0 }' >long.2D
expect_file_error drawplot long.2D -noplot -ps long.2D
printf '# labels\n' >only.2D
expect_file_error drawplot only.2D -noplot -ps only.2D
exit 0
