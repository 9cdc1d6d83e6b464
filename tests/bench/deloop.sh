#!/bin/sh
# tests/bench/deloop.sh [BUILD] - time of etch -deloop (aim:
# under 5 s at 1e6 triangles): two spheres grown
# from seeds (0,0,0) and (0,1,0) at 1 um/s (thesis Figure 8.13), delooped
# at 0.8 s and 1.0 s, with S_ideal 0.1, 0.032 and 0.01 um: meshes of
# about 1e4, 1e5 and 1e6 triangles (the final count; the mesh before the
# last deloop has some 40 % more).
# Prints the final triangle count, the CPU time (all threads, etch's
# clock) of the two deloop runs without building the classifier (the
# fast-marching solve, shown apart), that time per triangle, which should
# stay nearly flat (O(N) grid search; the thesis' pair test was O(N^2)),
# and the wall and CPU seconds of the whole etch run.
# With the base revision (DELOOP_BASE, default 6931a7e: main before the
# one-grid-per-search rework) exported with git archive and built in a
# temporary directory, the same runs are made with its etch, in the same
# run of this script, and the ratio old / new of the deloop time printed;
# the outputs are compared byte for byte (they must not differ).  The
# machine is shared: the figures move with its load, the ratio less.
# Then the examples the test suite deloops most, examples/defect and
# examples/corner-defect with -deloop (their run.sh's etch: -et 30 -pt 10
# -cut y 0, on each of the nine resist/dose rate files, made once by
# this tree's splat and bleach), run by this tree's etch and by the base
# revision's (DELOOP_EXAMPLES_BASE, default 5ab1070: main before the
# classifier's lazy march and the closing's search of its new triangles
# alone), built likewise: the CPU seconds (user + sys,
# all threads) of the nine runs of each, the ratio old / new, and a cmp
# of every output (curves.plot, curves.plot.2D, curves.cut, and the
# "deloop:" summary line without its timings): they must not differ.
# Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
etch=$BUILD/bin/etch
mkrate=$BUILD/tests/lib/mkrate
[ -x "$etch" ] || { echo "deloop: $etch not built"; exit 1; }
[ -x "$mkrate" ] || { echo "deloop: $mkrate not built"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/deloopbench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
. "$TOP/tests/lib/bench.sh"
# base_etch REV DIR: etch of revision REV built in $tmp/DIR (bench_base),
# its path in $base_bin, or a line saying why not and base_bin empty
base_etch() {
	base_bin=
	if [ ! -x /usr/bin/time ]; then
		echo "deloop: /usr/bin/time missing; no comparison with $1"
		return
	fi
	bench_base deloop "$1" "$tmp/$2" build/bin/etch && base_bin=$base_bin/etch
}
BASE=${DELOOP_BASE:-6931a7e}
base_etch "$BASE" base
old=$base_bin
[ -z "$old" ] || echo "deloop: old = $BASE, new = this tree, in the same run; ratio old / new of the deloop CPU time"
cd "$tmp" || exit 1
"$mkrate" -o two.bin 31 41 31 -1.5 1.5 -1.5 2.5 -1.5 1.5 1 || exit 1

# run ETCH SEG OUT: etch's log in log.txt, /usr/bin/time's "wall user sys"
# in time.txt (when it is there)
run() {
	if [ -x /usr/bin/time ]; then
		/usr/bin/time -f '%e %U %S' -o time.txt "$1" -et 1 -dt 0.1 -pt 0.8 -seg "$2" \
			-seed 0 0 0 -seed 0 1 0 -deloop -o "$3" two.bin 2>log.txt
	else
		echo "0 0 0" >time.txt
		"$1" -et 1 -dt 0.1 -pt 0.8 -seg "$2" -seed 0 0 0 -seed 0 1 0 -deloop -o "$3" two.bin 2>log.txt
	fi
}

# figures from log.txt and time.txt: "triangles deloop classifier wall cpu"
figures() {
	awk '
		/final mesh/ { for (i = 1; i <= NF; i++) if ($i == "triangles") { tri = $(i - 1); break } }
		/deloop:/ { for (i = 1; i <= NF; i++) { if ($i == "in") all = $(i + 1); if ($i == "(classifier") cl = $(i + 1) } }
		END { printf "%d %.3f %.3f", tri, all - cl, cl }' log.txt
	awk '{ printf " %.2f %.2f\n", $1, $2 + $3 }' time.txt
}

printf '%-8s %10s %9s %12s %10s %13s' "S_ideal" "triangles" "deloop s" "us/triangle" "classif. s" "etch wall/cpu"
[ -n "$old" ] && printf ' %9s %7s %13s' "old s" "ratio" "old wall/cpu"
printf '\n'
for seg in 0.1 0.032 0.01; do
	run "$etch" $seg new.plot || { echo "deloop: etch failed: $(tail -n 1 log.txt)"; continue; }
	set -- $(figures)
	line=$(awk -v seg=$seg -v tri="$1" -v t="$2" -v cl="$3" -v w="$4" -v c="$5" 'BEGIN {
		printf "%-8s %10d %9.3f %12.2f %10.3f %6.1f/%-6.1f", seg, tri, t, 1e6 * t / tri, cl, w, c }')
	if [ -n "$old" ]; then
		t=$2
		if run "$old" $seg old.plot; then
			set -- $(figures)
			line=$line$(awk -v o="$2" -v t="$t" -v w="$4" -v c="$5" 'BEGIN {
				printf " %9.3f %6.2fx %6.1f/%-6.1f", o, (t > 0 ? o / t : 0), w, c }')
			cmp -s old.plot new.plot || line="$line  (outputs differ)"
		else
			line="$line  (old etch failed)"
		fi
	fi
	echo "$line"
done

# the examples: CPU seconds of etch -deloop, this tree's and the base's
XBASE=${DELOOP_EXAMPLES_BASE:-5ab1070}
base_etch "$XBASE" xbase
xold=$base_bin
# xrun ETCH DIR RATE: etch as the examples' run.sh runs it, in DIR; the
# CPU seconds appended to DIR/../cpu
xrun() {
	mkdir -p "$2" && (cd "$2" && /usr/bin/time -f '%U %S' -a -o ../cpu \
		"$1" -et 30 -pt 10 -deloop -cut y 0 "$3" 2>log.txt &&
		sed -n 's/^[^:]*: deloop:/deloop:/; s/ in [0-9.e+-]* s (classifier [0-9.e+-]* s)//p' \
			log.txt >summary.txt)
}
if [ -n "$xold" ]; then
	echo "deloop: etch -deloop on the examples, old = $XBASE, new = this tree, CPU s of the nine runs"
	printf '%-16s %9s %9s %7s\n' "example" "old s" "new s" "ratio"
	for ex in defect corner-defect; do
		d=$tmp/ex-$ex
		mkdir -p "$d" && cd "$d" || exit 1
		"$BUILD/bin/splat" -q "$TOP/examples/$ex/mask.in" >/dev/null 2>&1 ||
			{ echo "deloop: splat failed on examples/$ex"; continue; }
		bad=0
		for r in "$TOP/examples/$ex"/resist-*.in; do
			n=$(basename "$r" .in)
			"$BUILD/bin/bleach" -o "$n.bin" image.cont "$r" >/dev/null 2>&1 &&
				xrun "$xold" old/"$n" "$d/$n.bin" && xrun "$etch" new/"$n" "$d/$n.bin" ||
				{ echo "deloop: examples/$ex $n failed"; bad=1; continue; }
			for f in curves.plot curves.plot.2D curves.cut summary.txt; do
				cmp -s old/"$n"/$f new/"$n"/$f || { echo "deloop: examples/$ex $n: $f differs"; bad=1; }
			done
		done
		awk -v ex="$ex" -v bad=$bad 'FNR == 1 { k++ } { c[k] += $1 + $2 }
			END { printf "%-16s %9.2f %9.2f %6.2fx%s\n", ex, c[1], c[2],
				(c[2] > 0 ? c[1] / c[2] : 0), (bad ? "  (outputs differ)" : "  (outputs identical)") }' \
			old/cpu new/cpu
	done
fi
exit 0
