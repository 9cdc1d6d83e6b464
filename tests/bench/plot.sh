#!/bin/sh
# tests/bench/plot.sh [BUILD] - timings of the plot programs (best of 3,
# one core), asserting nothing:
#   pdraw -h on a 201 x 201 grid as triangles (80000 polygons, BSP painter);
#   pdraw without -h on the same file;
#   contour of a 501 x 501 grid at about ten levels;
#   drawplot of 10 curves of 10000 points;
#   memory: peak resident bytes per triangle of pdraw with and without -h,
#   and of conv -vtk, on a 501 x 501 grid as triangles (500000), beside
#   the estimate the programs check before reading (plot_budget: their
#   refusal at the machine's memory rests on it).
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
B=$BUILD/bin
for p in pdraw contour drawplot conv; do
	[ -x "$B/$p" ] || { echo "plot: $B/$p not built"; exit 1; }
done
dir=$(mktemp -d "${TMPDIR:-/tmp}/plotbench.XXXXXX")
trap 'rm -rf "$dir"' EXIT INT TERM
cd "$dir" || exit 1
grid() {
	awk -v n="$1" 'BEGIN { print -1, 1, -1, 1; print n, n
		for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
			x = -1 + 2 * i / (n - 1); y = -1 + 2 * j / (n - 1)
			printf "%.6g\n", sin(3 * x) * cos(2 * y) + x * x }
	}'
}
grid 201 >g201.cont
grid 501 >g501.cont
"$B/conv" -t -o g201.3D g201.cont || exit 1
awk 'BEGIN { print 0, 1, -1, 1; print 10
	for (c = 0; c < 10; c++) { print 10000
		for (i = 0; i < 10000; i++) print i / 9999, sin(20 * i / 9999 + c) * (1 - c / 20) } }' >c.2D
run() {
	name=$1; shift
	best=
	for r in 1 2 3; do
		t0=$(date +%s.%N)
		POSTSCRIPT=ON "$@" -noplot </dev/null >/dev/null 2>&1 || { echo "$name: failed"; return; }
		t1=$(date +%s.%N)
		t=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }')
		if [ -z "$best" ] || awk -v a="$t" -v b="$best" 'BEGIN { exit !(a < b) }'; then best=$t; fi
	done
	echo "plot: $name: ${best} s"
}
run "pdraw -h, 201x201 grid (80000 triangles)" "$B/pdraw" -h g201.3D
run "pdraw, 201x201 grid (80000 triangles)" "$B/pdraw" g201.3D
run "contour, 501x501 grid, ~10 levels" "$B/contour" g501.cont
run "drawplot, 10 curves x 10000 points" "$B/drawplot" c.2D

# memory per triangle, measured against the estimate
"$B/conv" -t -o g501.3D g501.cont || exit 1
ntri=$(awk 'NF == 1 && $1 == 4 { n++ } END { print n }' g501.3D)
mem() { # NAME BYTES-PER-NUMBER CMD...: peak RSS against the estimate
	name=$1 per=$2
	shift 2
	if [ ! -x /usr/bin/time ]; then echo "plot: $name: /usr/bin/time missing"; return; fi
	POSTSCRIPT=ON /usr/bin/time -f '%M' -o mem.out "$@" </dev/null >/dev/null 2>&1 ||
		{ echo "plot: $name: failed"; return; }
	awk -v n="$name" -v kb="$(cat mem.out)" -v t="$ntri" -v per="$per" \
		-v text="$(wc -c <g501.3D)" -v nums="$(awk 'NF == 3 { n += 3 } END { print n }' g501.3D)" 'BEGIN {
		e = text + 16 * nums; if (per * nums > e) e = per * nums
		printf "plot: %s: %.0f MB peak, %.0f bytes a triangle (estimate %.0f MB)\n",
			n, kb / 1024, kb * 1024 / t, e / 1e6 }'
}
mem "pdraw -h, 501x501 grid as triangles" 90 "$B/pdraw" -h -noplot g501.3D
mem "pdraw, 501x501 grid as triangles" 32 "$B/pdraw" -noplot g501.3D
mem "conv -vtk, 501x501 grid as triangles" 32 "$B/conv" -vtk -o g501.vtp g501.3D
