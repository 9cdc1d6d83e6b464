# femwin's process window against a closed form.  A synthetic fem.dat
# samples CD(f, d) = T (1 + g ln(d / d0)) - a (f - f0)^2 (a Bossung parabola,
# CD growing with log dose) on foci -1:0.8:0.05 and doses 80:140:2.5.  In spec
# (|CD - T| <= p T), the best rectangle at exposure latitude e has its top
# dose at d0 exp(p / g), so
#   DOF(e) = 2 sqrt(T (g ln u1 + p) / a),  u1 = exp(p / g) (1 - e/2) / (1 + e/2),
# and the maximum EL (at any focus: a constant CD offset only moves the
# window in log dose) is 200 tanh(p / g) %.
# Where the formula goes below 0 the point is written uncleared with cd 0.
# Bilinear interpolation between the samples under-reads the parabola by at
# most a h^2 / 4 = 6.25e-4 um (h = 0.05 um) and the log by T g hd^2 / (8
# dmin^2) = 3.1e-5 um; at the window's edge |dCD/df| = 2 a r with r = DOF/2,
# so each edge moves by at most 6.6e-4 / (2 a r) = 1.1e-3 um: the DOF
# tolerance is 2.3e-3 um.  The maximum EL is exact up to the focus sampling
# of the search: 0.01 %.
# Also: window.dat's format, the EL/DOF curve decreasing, femwin -collect on
# hand-written measure tables (order, a missing point), and malformed
# fem.dat files refused with one line naming file and line.
. "$TOP/tests/lib/common.sh"
awk 'BEGIN { T = 0.5; g = 0.5; a = 1.0; f0 = -0.13
	print "# focus dose cd swa cleared resist_loss"
	for (i = 0; i <= 36; i++) for (j = 0; j <= 24; j++) {
		f = -1 + 0.05 * i; d = 80 + 2.5 * j
		cd = T * (1 + g * log(d / 100)) - a * (f - f0)^2
		printf "%.17g %.17g %.17g 88 %d -\n", f, d, (cd > 0 ? cd : 0), (cd > 0)
	} }' >fem.dat
femwin -target 0.5 -tol 10 -o window.dat -plot window.2D fem.dat >out.txt || fail "femwin failed"
cat out.txt
exact() { awk -v e="$1" 'BEGIN { T = 0.5; g = 0.5; a = 1; p = 0.1; e /= 100
	u1 = exp(p / g) * (1 - e / 2) / (1 + e / 2); printf "%.9f", 2 * sqrt(T * (g * log(u1) + p) / a) }'; }
dof() { awk -v e="$1" '$1 == e { print $2 }' window.dat; }
head -n 1 window.dat | grep -qx '# el dof focus_centre dose_centre' || fail "window.dat header"
[ -n "$(dof 5)" ] || fail "window.dat has no row at 5 % EL"
close "$(dof 5)" "$(exact 5)" 2.3e-3 "DOF at 5 % EL"
close "$(dof 10)" "$(exact 10)" 2.3e-3 "DOF at 10 % EL"
close "$(dof 0)" "$(exact 0)" 2.3e-3 "DOF at 0 % EL"
# the centre focus of the best rectangle is the parabola's vertex
close "$(awk '$1 == 5 { print $3 }' window.dat)" -0.13 2e-3 "focus centre at 5 % EL"
grep -q '^DOF at 5% EL: 0.59[01]' out.txt || fail "stdout: DOF at 5 % EL"
maxel=$(sed -n 's/^max EL: \([0-9.]*\) %$/\1/p' out.txt)
close "$maxel" "$(awk 'BEGIN { x = 0.2; printf "%.6f", 200 * (exp(x) - exp(-x)) / (exp(x) + exp(-x)) }')" 0.01 "max EL"
awk 'NR > 1 && NR > 2 && $2 > prev + 1e-12 { bad = 1 } NR > 1 { prev = $2 } END { exit bad }' window.dat ||
	fail "DOF must not grow with EL"
[ "$(awk 'END { print $1 }' window.dat)" = 39 ] || fail "the last EL row should be 39 %"
# plot files drawplot reads; the region: the two rectangles (5 points each,
# the 5 % one from window.dat's row) and one outline, labelled by the template
drawplot -noplot -ps window.2D || fail "drawplot cannot read window.2D"
femwin -target 0.5 -tol 10 -o w2.dat -region region.2D -region-template region.tpl fem.dat >/dev/null ||
	fail "femwin -region failed"
drawplot -noplot -ps -t region.tpl region.2D || fail "drawplot cannot read region.2D"
# (line 1 is its labels line, plot2d(5))
[ "$(sed -n 1p region.2D)" = '# labels title "In-spec region" x "focus (um)" y "dose (mJ/cm2)"' ] ||
	fail "region.2D labels: $(sed -n 1p region.2D)"
[ "$(sed -n 3p region.2D)" = 3 ] || fail "region.2D: expected 3 curves, found $(sed -n 3p region.2D)"
grep -q 'label = "in spec"' region.tpl || fail "region.tpl labels"
awk -v row="$(awk '$1 == 5' window.dat)" 'BEGIN { split(row, r, " "); h = 0.025
	f1 = r[3] - r[2] / 2; d1 = r[4] * (1 - h) }
	NR == 5 { exit !(($1 - f1)^2 < 1e-12 && ($2 - d1)^2 < 1e-8) }' region.2D ||
	fail "region.2D: the 5 % rectangle does not start at window.dat's corner"
# deterministic
femwin -target 0.5 -tol 10 -o again.dat fem.dat >/dev/null || fail "second run"
same window.dat again.dat

# nothing in spec
femwin -target 5 -tol 1 -o none.dat fem.dat >out.txt || fail "femwin with nothing in spec"
grep -q '^max EL: none' out.txt || fail "nothing in spec: $(cat out.txt)"
[ "$(wc -l <none.dat)" -eq 1 ] || fail "nothing in spec: window.dat should hold only its header"

# collect: points given in any order, one missing, one not cleared
printf '# z cd width_x width_y\n-0.63 0.8 0.81 0.79\n-0.07 1.1 1.1 1.1\n# swa 84.5\n# resist_loss 0.02\n# cleared yes\n' >a.tab
printf '# z cd\n-0.63 0\n# cleared no\n' >b.tab
printf '# z cd\n-0.63 0.9\n# swa 88\n# cleared yes\n' >c.tab
femwin -collect -o col.dat -bossung b.2D -template b.tpl -p 0.2 60 a.tab -p -0.2 80 c.tab \
	-p -0.2 60 b.tab -p 0.2 80 missing.tab 2>err.txt && fail "collect with a missing point should exit 1"
grep -q '1 of 4 points have no result' err.txt || fail "missing point not reported: $(cat err.txt)"
cat >expect.dat <<'X'
# focus dose cd swa cleared resist_loss
-0.2 60 0 - 0 -
-0.2 80 0.9 88 1 -
0.2 60 0.8 84.5 1 0.02
X
same col.dat expect.dat
grep -q 'label = "60 mJ/cm2"' b.tpl || fail "template labels"
drawplot -noplot -ps -t b.tpl b.2D || fail "drawplot cannot read the Bossung files"
printf '# z width\n1 2\n' >bad.tab
expect_file_error femwin bad.tab -collect -o x.dat -p 0 60 bad.tab
printf '# z cd\n1 2\n' >bad.tab
expect_file_error femwin bad.tab -collect -o x.dat -p 0 60 bad.tab
[ ! -e x.dat ] || fail "a failed collect left x.dat"

# malformed fem.dat: one line naming the file and line, nothing written
bad() {
	printf "$1" >bad.dat
	expect_file_error femwin bad.dat -target 1 -tol 10 -o w.dat bad.dat
	[ ! -e w.dat ] || fail "window.dat written from a bad fem.dat"
}
bad ''
bad '# focus dose cd\n'
bad '# focus dose cd swa cleared resist_loss\n0 60 1 - 1\n'
bad '# focus dose cd swa cleared resist_loss\n0 60 1 - 2 -\n'
bad '# focus dose cd swa cleared resist_loss\n0 60 nan - 1 -\n'
bad '# focus dose cd swa cleared resist_loss\n0 -60 1 - 1 -\n'
bad '# focus dose cd swa cleared resist_loss\n0 80 1 - 1 -\n0 60 1 - 1 -\n'
bad '# focus dose cd swa cleared resist_loss\n0 60 1 - 1 -\n0 60 1 - 1 -\n'
bad '# focus dose cd swa cleared resist_loss\n1 60 1 - 1 -\n0 60 1 - 1 -\n'
printf '# focus dose cd swa cleared resist_loss\n0 60 1 - 1 -\n0 80 1 - 1 -\n' >one.dat
expect_error femwin -target 1 -tol 10 one.dat
grep -q 'at least 2 foci' err.txt || fail "one focus: $(cat err.txt)"
# usage errors: exit 2
femwin -target 1 fem.dat >/dev/null 2>&1; [ $? -eq 2 ] || fail "-target without -tol: expected exit 2"
femwin -collect fem.dat >/dev/null 2>&1; [ $? -eq 2 ] || fail "-collect without -p: expected exit 2"
femwin -p 0 60 >/dev/null 2>&1; [ $? -eq 2 ] || fail "-p with two values: expected exit 2"
exit 0
