#!/bin/sh
# tests/bench/etch2d.sh [BUILD] - the thesis' study of 2D etching
# algorithms remade (thesis chapters 3-7, Table 10.1):
#   - Figure 3.3: Dill's cells etching uniformly (1 um/s, 1 s) from a seed
#     at 25 to 400 cells/um: the radius along rays at 0, 22.5, 45, 67.5 and
#     90 degrees from straight down (a perfect octagon: 1/cos 22.5 = 1.082
#     at 22.5 and 67.5); the thesis saw the facets sharpen with cell count;
#   - Figure 4.2: the Huygens cells at 10 and 40 cells a step: largest
#     error of the radius;
#   - Table 3.1: the cell method's CPU time for 15 s on the Figure 2.3 rate
#     at 100x50, 200x100, 400x200 (and 800x400) cells, and the growth per
#     doubling (the thesis: 6.4 and 7.5, "about N^3" = 8);
#   - Figures 3.4-3.5: the half-width of the bottom standing wave at 15 s
#     (at fixed heights above the fast-marching bottom), cells (100x50 to
#     800x400) against the string, the ray-string and fmm;
#   - Table 10.1: each method on the Figure 2.3 rate (examples/algorithms:
#     splat's 1.25 um isolated space, Kodak 820 of Figure 2.2, the cutline
#     across it), 30 s: CPU time, the method's memory (and the process's
#     peak RSS), and the distance of its profiles at 15 and 30 s from the
#     fast-marching solution on an 800 x 400 grid (median and 95th
#     percentile, um; the reference's own change from 400 x 200 is
#     printed first), beside the thesis' SUN 4/280 times.
# Prints figures; asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
B=$BUILD/bin
mkrate=$BUILD/tests/lib/mkrate
plotdist=$BUILD/tests/lib/plotdist
for p in "$B/etch2d" "$B/splat" "$B/bleach" "$mkrate" "$plotdist"; do
	[ -x "$p" ] || { echo "etch2d: $p not built"; exit 1; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/etch2dbench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
cd "$tmp" || exit 1

# "cpu S s, memory B bytes (peak RSS K kB), ..." -> fields
stat() { sed -n 's/.*cpu \([0-9.]*\) s, memory \([0-9]*\) bytes (peak RSS \([0-9]*\) kB).*/\1 \2 \3/p' "$1"; }
# largest |r/t - 1| (and the angle below the top of the largest r/t - 1)
radial() {
	awk -v t="$2" 'NF == 4 { set++ } set == 1 && NF == 2 {
		r = sqrt($1 * $1 + $2 * $2); e = r / t - 1
		if (e > over) { over = e; ang = atan2(-$2, ($1 < 0 ? -$1 : $1)) * 45 / atan2(1, 1) }
		if (-e > under) under = -e }
		END { printf "%.4f %.1f %.4f\n", over, ang, under }' "$1"
}

"$mkrate" -o uni.bin 3 1 3 -1.2 1.2 0 0 -1.2 0 1 || exit 1
echo "Figure 3.3: Dill's cells from a seed, uniform 1 um/s, 1 s: radius / (R t) along rays from straight down"
echo "  (a perfect octagon: 1.0824 at 22.5 and 67.5 degrees, 1 at 0, 45, 90; the thesis: the facets sharpen with cell count)"
for n in 25 50 100 200 400; do
	"$B/etch2d" -et 1 -method cell -seed 0 0 -cells $((24 * n / 10)) $((12 * n / 10)) -o c.plot uni.bin
	printf '  %3s cells/um  ' $n; awk -v t=1 -f "$TOP/tests/bench/radius-at-angles.awk" c.plot
done
echo "Figure 4.2: Huygens cells from a seed, uniform 1 um/s, 1 s"
for n in 10 40; do
	"$B/etch2d" -et 1 -method huygens -seed 0 0 -dt 0.1 -cells $((24 * n)) $((12 * n)) -o h.plot uni.bin
	radial h.plot 1 | { read -r o a u; printf '  %s cells a step: radius +%s / -%s\n' $n "$o" "$u"; }
done

"$B/splat" -q "$TOP/examples/algorithms/space.in" || exit 1
"$B/bleach" -q -cutline -o fig23.bin space.2D "$TOP/examples/resists/kodak820-fig22.in" || exit 1
echo "Table 3.1: the cell method, 15 s on the Figure 2.3 rate (thesis, SUN 4/280: 22, 141, 1058 s)"
prev=""
for c in "100 50" "200 100" "400 200" "800 400"; do
	# shellcheck disable=SC2086
	"$B/etch2d" -et 15 -method cell -cells $c -stats -o c.plot fig23.bin 2>s.txt
	cpu=$(stat s.txt | cut -d' ' -f1)
	g=""
	[ -n "$prev" ] && g=$(awk -v a="$prev" -v b="$cpu" 'BEGIN { if (a > 0) printf "x%.1f", b / a }')
	printf '  %-9s cells  %8s s  %s\n' "$(echo $c | tr ' ' x)" "$cpu" "$g"
	prev=$cpu
done

echo "Figures 3.4-3.5: 15 s on the Figure 2.3 rate, the bottom standing wave (thesis: cells ~0.05 um wider than the string,"
echo "  worse from 100x50 to 200x100 cells, then converged at 400x200)"
# half-width of the opening (from the space's centre, 1 um along the cut)
# at the heights 0.01 to 0.09 um above the reference's bottom (fmm 800 x
# 400): the lowest standing wave, the same heights for every method
"$B/etch2d" -et 15 -method fmm -cells 800 400 -o f.plot fig23.bin
zb=$(awk 'NF == 2 && (m == "" || $2 < m) { m = $2 } END { print m }' f.plot)
z0=$(awk -v z="$zb" 'BEGIN { print z + 0.01 }')
z1=$(awk -v z="$zb" 'BEGIN { print z + 0.09 }')
bottom() {
	printf 'bottom z %.3f, half-width of the lowest standing wave %s um\n' \
		"$(awk 'NF == 2 && (m == "" || $2 < m) { m = $2 } END { print m }' "$1")" \
		"$(awk -v C=1 -v Z0="$z0" -v Z1="$z1" -v DZ=0.01 -f "$TOP/tests/lib/halfwidth.awk" "$1")"
}
for c in "100 50" "200 100" "400 200" "800 400"; do
	# shellcheck disable=SC2086
	"$B/etch2d" -et 15 -method cell -cells $c -o c.plot fig23.bin
	printf '  cell %-9s ' "$(echo $c | tr ' ' x)"; bottom c.plot
done
for m in string raystring; do
	"$B/etch2d" -et 15 -method $m -o c.plot fig23.bin
	printf '  %-14s ' $m; bottom c.plot
done
printf '  %-14s ' "fmm 800x400"; bottom f.plot

echo "Table 10.1 remade: 30 s on the Figure 2.3 rate (2 x 1 um, Kodak 820)"
"$B/etch2d" -et 30 -pt 15 -method fmm -cells 800 400 -o ref.plot fig23.bin
"$B/etch2d" -et 30 -pt 15 -method fmm -cells 400 200 -o ref2.plot fig23.bin
"$plotdist" ref2.plot ref.plot | awk '{ m = $2 > m ? $2 : m; p = $3 > p ? $3 : p }
	END { printf "  reference: fmm 800 x 400; fmm 400 x 200 lies %s (median) / %s (p95) um from it\n", m, p }'
printf '  %-10s %-30s %9s %10s %9s %9s %9s  %s\n' method options "cpu (s)" "mem (kB)" "RSS (kB)" "med (um)" "p95 (um)" "thesis SUN 4/280"
run() {
	name=$1 thesis=$2; shift 2
	"$B/etch2d" -et 30 -pt 15 -stats -o m.plot "$@" fig23.bin 2>s.txt || { echo "  $name failed"; return; }
	set -- $(stat s.txt) 
	cpu=$1 mem=$(( $2 / 1024 )) rss=$3
	"$plotdist" m.plot ref.plot | awk -v n="$name" -v o="$opts" -v c="$cpu" -v m="$mem" -v r="$rss" -v t="$thesis" '
		{ md = $2 > md ? $2 : md; p = $3 > p ? $3 : p }
		END { printf "  %-10s %-30s %9s %10s %9s %9.4f %9.4f  %s\n", n, o, c, m, r, md, p, t }'
}
opts="-cells 200 100"; run cell "400 s (200x100)" -method cell -cells 200 100
opts="-cells 400 200"; run cell "" -method cell -cells 400 200
opts="-cells 400 200 -dt 0.1"; run huygens "N/A (5 s: 1 hour, wrong)" -method huygens -cells 400 200 -dt 0.1
opts="-cells 2000 1000 -dt 0.1"; run huygens "" -method huygens -cells 2000 1000 -dt 0.1
opts="-seg 0.04 -dt 0.092"; run string "30 s (50 segments, dt 0.092)" -method string -seg 0.04 -dt 0.092
opts="-seg 0.04 -dt 0.1"; run ray "N/A (no surface)" -method ray -seg 0.04 -dt 0.1
opts="-seg 0.04 -dt 0.1 -rl 0.1"; run raystring "80 s (50 segments, dt 0.1)" -method raystring -seg 0.04 -dt 0.1 -rl 0.1
opts="-seg 0.04 -dt 0.1 -rl 2"; run raystring "67 s (no vector checking)" -method raystring -seg 0.04 -dt 0.1 -rl 2
opts="-seg 0.04 -dt 0.5 -rl 0.1"; run raystring "52 s (dt 0.5)" -method raystring -seg 0.04 -dt 0.5 -rl 0.1
opts="-cells 200 100"; run fmm "-" -method fmm -cells 200 100
