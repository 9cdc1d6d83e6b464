#!/bin/sh
# tests/bench/deloop.sh [BUILD] - time of etch -deloop (issue "deloop",
# Performance): two spheres grown from seeds (0,0,0) and (0,1,0) at
# 1 um/s (thesis Figure 8.13), delooped at 0.8 s and 1.0 s, with S_ideal
# 0.1, 0.032 and 0.01 um: meshes of about 1e4, 1e5 and 1e6 triangles.
# Prints the final triangle count, the time of the two deloop passes
# without building the classifier (the fast-marching solve, shown apart)
# and that time per triangle, which should stay nearly flat (O(N) grid
# search; the thesis' pair test was O(N^2)).  Asserts nothing.
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
cd "$tmp" || exit 1
"$mkrate" -o two.bin 31 41 31 -1.5 1.5 -1.5 2.5 -1.5 1.5 1 || exit 1
printf '%-10s %12s %12s %14s %12s\n' "S_ideal" "triangles" "deloop s" "us/triangle" "classifier s"
for seg in 0.1 0.032 0.01; do
	"$etch" -et 1 -dt 0.1 -pt 0.8 -seg $seg -seed 0 0 0 -seed 0 1 0 -deloop \
		-o x.plot two.bin 2>log.txt || { echo "deloop: etch failed: $(tail -n 1 log.txt)"; continue; }
	awk -v seg=$seg '
		/final mesh/ { for (i = 1; i <= NF; i++) if ($i == "triangles") { tri = $(i - 1); break } }
		/deloop:/ { for (i = 1; i <= NF; i++) { if ($i == "in") all = $(i + 1); if ($i == "(classifier") cl = $(i + 1) } }
		END { t = all - cl; printf "%-10s %12d %12.3f %14.2f %12.3f\n", seg, tri, t, 1e6 * t / tri, cl }' log.txt
done
