#!/bin/sh
# tests/bench/fmm-large.sh [BUILD] - etch -method fmm on a large window
# against a base revision, measured in the same run: the base (FMM_BASE,
# default d3744ef: before the tiles' surfaces were welded as they are
# extracted and held as vertices and triangles, and before etch freed
# the rate file once the solve holds its rates) is exported with git
# archive into a temporary directory and built there, then the same
# commands run with the old and the new etch.  Cases:
#   - examples/array40 at 20 um (401 x 401 x 300 rate points, 16
#     decimation tiles): splat and bleach once, then etch -et 60 -last
#     -method fmm alone on the rate file (as sample3D runs it);
#   - examples/defect's Shipley 1470 resist at 80 % dose, -et 30 -pt 10,
#     ray-string and fast marching.
# Figures: CPU (user + sys), wall and peak RSS (/usr/bin/time -v), one
# run each (the machine is shared: wall times move with its load, CPU
# less so); the old and new curves.plot are compared byte for byte.
# Then the users' targets, each with the figures it is judged on.  The
# 40 um array end to end is large.sh's LARGE_RUNS=fmm40 (about 4 times
# the 20 um etch's memory and CPU); FMM_LARGE_40=1 runs its etch here
# too; FMM_LARGE_SIZE (um, even, default 20) sets the first case's
# window.  Disk: 3 GB in $TMPDIR (6 GB more with FMM_LARGE_40).  Asserts
# nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
BASE=${FMM_BASE:-d3744ef}
NEW=$BUILD/bin
[ -x "$NEW/etch" ] || { echo "fmm-large: $NEW/etch not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "fmm-large: /usr/bin/time missing (Debian package time)"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fmmlarge.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
. "$TOP/tests/lib/bench.sh"
bench_base fmm-large "$BASE" "$tmp/base" || { [ $? = 2 ] && exit 0; exit 1; }
OLD=$base_bin
cd "$tmp" || exit 1
echo "fmm-large: old = $BASE, new = this tree; load $(cut -d ' ' -f 1-3 /proc/loadavg 2>/dev/null)"

size=${FMM_LARGE_SIZE:-20}
echo "examples/array40 at $size um, etch -et 60 -last -method fmm:"
sh "$TOP/examples/array40/make-mask.sh" "$size" >mask20.in
"$NEW/splat" -q -o a20.cont mask20.in || exit 1
"$NEW/bleach" -q -o a20.bin a20.cont "$TOP/examples/array40/resist.in" || exit 1
rm -f a20.cont
bench_run old20 "$OLD/etch" -q -et 60 -last -method fmm -o old.plot a20.bin
bench_run new20 "$NEW/etch" -q -et 60 -last -method fmm -o new.plot a20.bin
cmp -s old.plot new.plot && echo "  (same curves.plot)" || echo "  (curves.plot differs)"
rm -f old.plot* new.plot* a20.bin

echo "examples/defect, resist-shipley1470-80, -et 30 -pt 10:"
"$NEW/splat" -q -o defect.cont "$TOP/examples/defect/mask.in" || exit 1
"$NEW/bleach" -q -o defect.bin defect.cont "$TOP/examples/defect/resist-shipley1470-80.in" || exit 1
bench_run ray "$NEW/etch" -q -et 30 -pt 10 -o ray.plot defect.bin
bench_run oldd "$OLD/etch" -q -method fmm -et 30 -pt 10 -o old.plot defect.bin
bench_run newd "$NEW/etch" -q -method fmm -et 30 -pt 10 -o new.plot defect.bin
cmp -s old.plot new.plot && echo "  (same curves.plot)" || echo "  (curves.plot differs)"

if [ "${FMM_LARGE_40:-0}" = 1 ]; then
	echo "examples/array40 at 40 um, etch -et 60 -last -method fmm (new only):"
	"$NEW/splat" -q -o a40.cont "$TOP/examples/array40/mask.in" || exit 1
	"$NEW/bleach" -q -o a40.bin a40.cont "$TOP/examples/array40/resist.in" || exit 1
	rm -f a40.cont
	bench_run new40 "$NEW/etch" -q -et 60 -last -method fmm -o new.plot a40.bin
	rm -f new.plot* a40.bin
fi

echo "targets (old -> new):"
printf '  "fmm 20 um peak under 2 GB" (%s um): etch %s -> %s GB\n' "$size" \
	"$(bench_fig old20 3 | awk '{ printf "%.2f", $1 / 1024 }')" "$(bench_fig new20 3 | awk '{ printf "%.2f", $1 / 1024 }')"
printf '  "examples/defect with -method fmm under 3x the ray-string'"'"'s CPU": %s -> %s x (ray-string %s s CPU)\n' \
	"$(echo "$(bench_fig oldd 1) $(bench_fig ray 1)" | awk '{ printf "%.0f", $1 / $2 }')" \
	"$(echo "$(bench_fig newd 1) $(bench_fig ray 1)" | awk '{ printf "%.0f", $1 / $2 }')" "$(bench_fig ray 1)"
if [ -r new40.fig ]; then
	printf '  "the 40 x 40 um array end to end under 90 s wall and 3 GB on two cores, pictures included": etch alone %s s wall, %s s CPU, %s GB\n' \
		"$(bench_fig new40 2)" "$(bench_fig new40 1)" "$(bench_fig new40 3 | awk '{ printf "%.2f", $1 / 1024 }')"
else
	# the solve and the surfaces grow with the window's area: 4 times
	printf '  "the 40 x 40 um array end to end under 90 s wall and 3 GB on two cores, pictures included": etch alone projected from 20 um (x 4): %s s CPU, %s GB (FMM_LARGE_40=1 measures it)\n' \
		"$(bench_fig new20 1 | awk '{ printf "%.0f", 4 * $1 }')" "$(bench_fig new20 3 | awk '{ printf "%.1f", 4 * $1 / 1024 }')"
fi
exit 0
