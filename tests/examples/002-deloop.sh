# Every thesis example also runs with -deloop (passed by its run.sh through
# sample3D to etch) and every etch run ends with a loop-free mesh: its
# summary reports "0 crossings left" (etch(1): crossings of a segment
# through a triangle it does not touch, found by the deloop pass's own
# spatial index after the last pass).  Examples that develop by fast
# marching (-method fmm in their run.sh) have no mesh and are passed over.
. "$TOP/tests/lib/common.sh"
for run in "$TOP"/examples/*/run.sh; do
	name=$(basename "$(dirname "$run")")
	# an example developed by fast marching has no mesh to deloop
	if grep -q -- '-method fmm' "$run"; then
		echo "$name: fast marching, nothing to deloop"
		continue
	fi
	# the 2D examples (sample2D, etch2d) are tests/examples/003-2d.sh's
	grep -q 'sample2D\|etch2d' "$run" && continue
	OUT=$PWD/$name sh "$run" -deloop >"$name.log" 2>&1 || fail "example $name -deloop failed: $(tail -n 3 "$name.log")"
	runs=$(grep -c 'etch: deloop:' "$name.log")
	[ "$runs" -gt 0 ] || fail "example $name: no deloop summary"
	clean=$(grep 'etch: deloop:' "$name.log" | grep -c ' 0 crossings left')
	[ "$clean" -eq "$runs" ] || fail "example $name: loops left: $(grep 'etch: deloop:' "$name.log" | grep -v ' 0 crossings left' | head -n 2)"
	echo "$name: $runs runs, all loop-free"
done
exit 0
