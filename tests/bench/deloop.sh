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
BASE=${DELOOP_BASE:-6931a7e}
old=
if [ -x /usr/bin/time ] && git -C "$TOP" rev-parse --verify -q "$BASE^{commit}" >/dev/null; then
	mkdir -p "$tmp/base"
	if git -C "$TOP" archive "$BASE" | tar -x -C "$tmp/base" &&
		make -s -C "$tmp/base" -j2 BUILD=build build/bin/etch >"$tmp/base.log" 2>&1; then
		old=$tmp/base/build/bin/etch
		echo "deloop: old = $BASE, new = this tree, in the same run; ratio old / new of the deloop CPU time"
	else
		echo "deloop: building $BASE failed; no comparison"
	fi
else
	echo "deloop: base revision $BASE (or /usr/bin/time) missing; no comparison"
fi
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
exit 0
