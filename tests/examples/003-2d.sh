# The 2D examples run end to end through their run.sh: examples/defect-
# cutlines and examples/elbow-cutline (sample2D: splat, bleach -cutline,
# etch2d, drawplot) leave in every run directory cut.2D, rval.2D.binary,
# a profile.plot with one set per print time of the run's own command
# (4: -et 20 -pt 5 and -et 60 -pt 15) and a dataplot.ps with as many
# pages; examples/algorithms leaves every plot file its run.sh lists, each
# drawn.  Against: the files sample2D(1) and the run.sh comments promise.
. "$TOP/tests/lib/common.sh"
for name in defect-cutlines elbow-cutline algorithms; do
	OUT=$PWD/$name sh "$TOP/examples/$name/run.sh" >"$name.log" 2>&1 ||
		fail "example $name failed: $(tail -n 3 "$name.log")"
done
for d in defect-cutlines/north-south defect-cutlines/east-west elbow-cutline; do
	for f in cut.2D rval.2D.binary profile.plot dataplot.ps; do
		[ -s "$d/$f" ] || fail "$d: no $f"
	done
	sets=$(($(grep -c '^$' "$d/profile.plot") + 1))
	[ "$sets" -eq 4 ] || fail "$d: $sets sets, want 4"
	pages=$(grep -c '^%%Page: ' "$d/dataplot.ps")
	[ "$pages" -eq 4 ] || fail "$d: $pages pages, want 4"
done
for f in fig3.3-cells25 fig3.3-cells100 fig3.3-cells200 fig4.2-huygens10 fig4.2-huygens40 \
	fig6.4-string0.1 fig6.4-string0.02 fig7.7-raystring fig3.4-cell fig3.4-string \
	fig6.5-string fig6.5-string-fine fig6.5-raystring fig6.5-ray fig6.5-fmm \
	fig4.4a-huygens fig4.5b-huygens fig6.13-ray fig7.19-raystring fig6.20-ray fig7.21-raystring \
	table10.1-raystring table10.1-string table10.1-ray table10.1-cell table10.1-huygens table10.1-fmm; do
	[ -s "algorithms/$f.plot" ] || fail "algorithms: no $f.plot"
	[ -s "algorithms/$f.ps" ] || fail "algorithms: no $f.ps"
done
exit 0
