#!/bin/sh
# No two texts of a pdraw picture overlap (once "-0.70" was drawn
# on "2.5"), measured on the SVG with Helvetica's real advance
# widths (tests/lib/textoverlap.awk), over boxes thin and thick, views
# from every side, -e, -zs, and labelled axes as sample3D writes them.
# The old placement fails the thin-resist case this test starts with.
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
# a 5 x 5 um cell of 0.7 um resist with a developed dip, as the contact
$MKRATE -o rate.bin 21 21 15 -2.5 2.5 -2.5 2.5 -0.7 0 '0.002 + 0.05 * exp(-(x^2 + y^2) / 0.3)' ||
	fail "mkrate"
etch -q -et 20 -pt 10 -no2d rate.bin || fail "etch"
n=0
for view in "-1 -2 1.5" "2 -1 1" "1 2 1" "-2 1 0.7" "0.3 -1 3"; do
	for scale in "" "-e" "-zs auto" "-zs 3"; do
		for lab in "" "-xl x_(um) -yl y_(um) -zl z_(um)"; do
			n=$((n + 1))
			# shellcheck disable=SC2086
			pdraw -noplot -ps -svg p$n.svg -v $view $scale $lab curves.plot 2>err.txt ||
				fail "pdraw -v $view $scale $lab: $(cat err.txt)"
			awk -f "$TOP/tests/lib/textoverlap.awk" p$n.svg >ov.txt ||
				fail "pdraw -v $view $scale $lab: $(head -n 3 ov.txt)"
		done
	done
done
exit 0
