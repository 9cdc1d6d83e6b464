# Every thesis example in examples/ runs end to end through its run.sh
# (sample3D: splat, bleach, etch, pdraw) and leaves, in every run
# directory, a non-empty curves.plot that reads back as a plot file with
# one set per print time, its curves.plot.2D, and a dataplot.ps that
# ghostscript renders (when installed).  Against: the files each run must
# leave (sample3D(1) FILES), and the print times in the run's own command.
. "$TOP/tests/lib/common.sh"
for run in "$TOP"/examples/*/run.sh; do
	name=$(basename "$(dirname "$run")")
	# the 2D examples (sample2D, etch2d) are tests/examples/003-2d.sh's
	grep -q 'sample2D\|etch2d' "$run" && continue
	OUT=$PWD/$name sh "$run" -q >"$name.log" 2>&1 || fail "example $name failed: $(tail -n 3 "$name.log")"
	n=0
	for plot in $(find "$name" -name curves.plot | sort); do
		d=$(dirname "$plot")
		[ -s "$d/curves.plot.2D" ] || fail "$d: curves.plot.2D missing"
		[ -s "$d/dataplot.ps" ] || fail "$d: dataplot.ps missing"
		PATH=$BUILD/tests/lib:$PATH fmtcat plot3 "$plot" check.plot || fail "$plot does not read back"
		sets=$(($(grep -c '^$' "$plot") + 1))
		pages=$(grep -c '^%%Page: ' "$d/dataplot.ps")
		[ "$sets" -eq "$pages" ] || fail "$d: $sets sets but $pages pages"
		if command -v gs >/dev/null; then gs_check "$d/dataplot.ps"; fi
		n=$((n + 1))
	done
	[ $n -gt 0 ] || fail "example $name produced no curves.plot"
	echo "$name: $n runs"
done
exit 0
