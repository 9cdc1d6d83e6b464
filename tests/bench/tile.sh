#!/bin/sh
# tests/bench/tile.sh [BUILD] - a 100 x 100 um clip of examples/array40's
# contacts (0.5 um on a 1 um pitch, i-line NA 0.6, a 0.05 um grid, nz 300,
# bake, 60 s development) end to end through sample3D -tile 2 -halo 1
# -j 2 (fast marching; 2500 tiles of 4 um, all the same file, so one is
# simulated), and the same contacts untiled on a 20 um window imaged by
# Abbe's method as the tiles are (the 40 um window does not fit fast
# marching's memory on this machine: 4 x the 20 um run's 7 GB).  Prints
# the wall time and peak memory of each run, the tiles and those
# simulated, the stitched surface's size, and the CDs at 10, 50 and 90 %
# of the height of five contacts of the middle 20 um, read from that part
# of the tiled result (stitch -window, as measure cannot hold the whole
# 100 um surface in 4 GB) and from the untiled run.  Targets: under 15 min
# and 4 GB for the tiled run, CDs equal within 0.5 nm.  Asserts nothing.
# Both runs decimate with etch -tol 0.01 (TILE_TOL): at the default the
# 100 um surface would be about 34 GB of text, at 0.01 about 9 GB.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
[ -x /usr/bin/time ] || { echo "tile: /usr/bin/time missing (Debian package time)"; exit 0; }
[ -x "$BUILD/bin/sample3D" ] || { echo "tile: $BUILD/bin/sample3D not built"; exit 1; }
PATH=$BUILD/bin:$PATH
ex=$TOP/examples/array40
size=${TILE_SIZE:-100}
tol=${TILE_TOL:-0.01}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/tilebench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
cd "$tmp" || exit 1
sh "$ex/make-mask.sh" "$size" >clip.in
sh "$ex/make-mask.sh" 20 >w20.in
mkdir tiled untiled
(cd tiled && /usr/bin/time -o ../time.txt -f "%e %M" sample3D -q -if ../clip.in -bf "$ex/resist.in" \
	-et 60 -last -etch "-tol $tol" -tile 2 -halo 1 -j 2 >log.txt 2>&1) ||
	echo "tile: the tiled run failed: $(tail -n 2 tiled/log.txt)"
awk -v s="$size" '{ printf "tile: %d um tiled (2 um cores, 1 um halo): %8.1f s wall %8.0f MB peak\n", s, $1, $2 / 1024 }' time.txt
echo "tile: $(wc -l <tiled/tiles/tiles.txt) tiles, $(ls tiled/tiles/u | wc -l) simulated, stitched surface $(du -m tiled/curves.plot | cut -f1) MB"
# the middle 20 um of the tiled result, for measure
set --
while read -r k dx dy x0 x1 y0 y1; do
	set -- "$@" -t "tiled/tiles/u/$k/curves.plot" "$dx" "$dy" "$x0" "$x1" "$y0" "$y1"
done <tiled/tiles/keys.txt
/usr/bin/time -o time.txt -f "%e %M" stitch -o mid.plot -window -10 10 -10 10 "$@" ||
	echo "tile: stitch -window failed"
awk '{ printf "tile: stitch -window of the middle 20 um: %8.1f s wall %8.0f MB peak\n", $1, $2 / 1024 }' time.txt
(cd untiled && /usr/bin/time -o ../time.txt -f "%e %M" sh -c '
	splat -q -method abbe ../w20.in && bleach -q -o rval.3D.binary image.cont "$1" &&
	etch -q -method fmm -no2d -et 60 -last -tol "$2" rval.3D.binary' sh "$ex/resist.in" "$tol" \
	>log.txt 2>&1) || echo "tile: the untiled run failed: $(tail -n 2 untiled/log.txt)"
awk '{ printf "tile: 20 um untiled: %8.1f s wall %8.0f MB peak\n", $1, $2 / 1024 }' time.txt
# contact centres (half-integer um in both): inside, near a seam, near a
# corner of the 2 um cores, and at the 20 um window's edge region
for h in "0.5 0.5" "-0.5 -0.5" "1.5 -0.5" "-5.5 3.5" "8.5 -8.5"; do
	# shellcheck disable=SC2086
	measure -rel 10,50,90 -hole $h untiled/curves.plot >a.txt 2>/dev/null
	# shellcheck disable=SC2086
	measure -rel 10,50,90 -hole $h mid.plot >b.txt 2>b.err
	paste a.txt b.txt | awk -v h="$h" '/^#/ { next }
		{ printf "tile: hole (%s) z %s: cd untiled %s tiled %s um, diff %.2g nm\n", h, $1, $2, $7, ($7 - $2) * 1000 }'
	[ ! -s b.err ] && continue
	echo "tile: measure on the stitched piece said: $(head -n 1 b.err)"
done
