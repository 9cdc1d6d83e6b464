#!/bin/sh
# tests/bench/tile.sh [BUILD] - a 100 x 100 um clip of examples/array40's
# contacts (0.5 um on a 1 um pitch, i-line NA 0.6, a 0.05 um grid, nz 300,
# bake, 60 s development) end to end through sample3D -tile 4 -halo 2 -j 2
# (fast marching), and the same contacts untiled on a 20 um window (the
# 40 um window does not fit fast marching's memory on this machine).
# Prints the wall time and peak memory of each run, the tiles simulated,
# the stitched surface's size, and the CDs at 50 % of the height of
# contacts inside cores, on seams and under corners, tiled against
# untiled.  Targets: under 15 min and 4 GB for the tiled run, CDs equal
# within 0.5 nm.  Asserts nothing.  Disk: the stitched surface of 100 um
# is tens of GB at etch's default -tol (TILE_TOL sets -tol, default 0.01).
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
[ -x /usr/bin/time ] || { echo "tile: /usr/bin/time missing (Debian package time)"; exit 0; }
[ -x "$BUILD/bin/sample3D" ] || { echo "tile: $BUILD/bin/sample3D not built"; exit 1; }
PATH=$BUILD/bin:$PATH
ex=$TOP/examples/array40
size=${TILE_SIZE:-100}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/tilebench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
cd "$tmp" || exit 1
sh "$ex/make-mask.sh" "$size" >clip.in
sh "$ex/make-mask.sh" 20 >w20.in
mkdir tiled untiled
(cd tiled && /usr/bin/time -o ../time.txt -f "%e %M" sample3D -q -if ../clip.in -bf "$ex/resist.in" \
	-et 60 -last -tol "${TILE_TOL:-0.01}" -tile 4 -halo 2 -j 2 >log.txt 2>&1) ||
	echo "tile: the tiled run failed: $(tail -n 2 tiled/log.txt)"
awk -v s="$size" '{ printf "tile: %d um tiled (4 um cores, 2 um halo): %8.1f s wall %8.0f MB peak\n", s, $1, $2 / 1024 }' time.txt
echo "tile: tiles $(wc -l <tiled/tiles/tiles.txt), simulated $(ls tiled/tiles/u | wc -l), stitched surface $(du -m tiled/curves.plot | cut -f1) MB"
(cd untiled && /usr/bin/time -o ../time.txt -f "%e %M" sample3D -q -if ../w20.in -bf "$ex/resist.in" \
	-et 60 -last -method fmm -tol "${TILE_TOL:-0.01}" >log.txt 2>&1) ||
	echo "tile: the untiled run failed: $(tail -n 2 untiled/log.txt)"
awk '{ printf "tile: 20 um untiled: %8.1f s wall %8.0f MB peak\n", $1, $2 / 1024 }' time.txt
# contact centres: inside a core, on a seam, under a corner (the clip's
# and the 20 um window's contacts sit at half-integer um)
for h in "0.5 0.5" "-1.5 -1.5" "2.5 0.5" "-3.5 4.5"; do
	# shellcheck disable=SC2086
	a=$(measure -rel 50 -hole $h untiled/curves.plot 2>/dev/null | awk '!/^#/ { print $2 }')
	# shellcheck disable=SC2086
	b=$(measure -rel 50 -hole $h tiled/curves.plot 2>/dev/null | awk '!/^#/ { print $2 }')
	echo "tile: cd at 50 % of the hole at ($h): untiled ${a:-?} tiled ${b:-?} um"
done
