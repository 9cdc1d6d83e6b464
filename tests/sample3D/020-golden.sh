# Regression on plot files: the cases of tests/golden/cases.sh must give
# curves.plot, curves.plot.2D and dataplot.ps byte-identical to the golden
# files in tests/golden/<case>/ (our output is deterministic, so any
# difference is a finding).  After a deliberate change, regenerate them
# with "make regen" and commit them with the change.  On a mismatch the
# first numeric difference is shown by plotdiff.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/golden/cases.sh"
for c in $GOLDEN_CASES; do
	mkdir "$c"
	(cd "$c" && golden_case "$c") || fail "case $c did not run"
	for f in $GOLDEN_FILES; do
		g=$TOP/tests/golden/$c/$f
		[ -f "$g" ] || fail "no golden file $g: run make regen"
		if ! cmp -s "$c/$f" "$g"; then
			plotdiff "$g" "$c/$f" | head -3
			fail "$c/$f differs from the golden file (make regen after a deliberate change)"
		fi
	done
done
exit 0
