#!/bin/sh
# tests/bench/fmm-speed.sh [BUILD] - the cost of etch -method fmm's
# decimated output against an older revision, measured in the same run:
# the base revision (FMM_BASE, default c5814ae: before the sets were
# extracted on z levels; 5ab1070 is before the decimator weighed each
# vertex's candidates on one gathering of its star, ed01cc5 before the
# tiled extraction) is exported with git archive
# into a temporary directory and built there, then the same commands run
# with the old and the new etch.  Cases:
#   - examples/defect's Shipley 1470 resist at 80 % dose (one set at 30 s,
#     then the example's -et 30 -pt 10), and the ray-string on the same
#     rate file for comparison;
#   - a 281 x 281 x 31 window of examples/contact's baked resist with two
#     clear lines (9 decimation tiles), -et 60 -pt 10, at 2 threads.
# Figures: CPU (user + sys) and wall seconds and peak RSS (/usr/bin/time
# -v's maximum resident set), one run each (the machine is shared: wall
# times move with its load, CPU less so).  The old and new curves.plot
# are compared byte for byte (the z levels change the output; the
# decimator's speed-ups before them did not).  Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
BASE=${FMM_BASE:-c5814ae}
NEW=$BUILD/bin
[ -x "$NEW/etch" ] || { echo "fmm-speed: $NEW/etch not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "fmm-speed: /usr/bin/time missing (Debian package time)"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fmmspeed.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
. "$TOP/tests/lib/bench.sh"
bench_base fmm-speed "$BASE" "$tmp/base" || { [ $? = 2 ] && exit 0; exit 1; }
OLD=$base_bin
cd "$tmp" || exit 1
echo "fmm-speed: old = $BASE, new = this tree"

"$NEW/splat" -q -o defect.cont "$TOP/examples/defect/mask.in" || exit 1
"$NEW/bleach" -q -o defect.bin defect.cont "$TOP/examples/defect/resist-shipley1470-80.in" || exit 1
echo "examples/defect, resist-shipley1470-80:"
bench_run "ray-string -et 30 -pt 10" "$NEW/etch" -q -et 30 -pt 10 -o ray.plot defect.bin
for a in "-last" "-pt 10"; do
	# shellcheck disable=SC2086
	bench_run "fmm old -et 30 $a" "$OLD/etch" -q -method fmm -et 30 $a -o old.plot defect.bin
	# shellcheck disable=SC2086
	bench_run "fmm new -et 30 $a" "$NEW/etch" -q -method fmm -et 30 $a -o new.plot defect.bin
	cmp -s old.plot new.plot && echo "  (same curves.plot)" || echo "  (curves.plot differs)"
done

cat >window.in <<'X'
wavelength 0.436
na 0.28
sigma 0.5
background dark
window -7 7 -7 7
rect -0.4 -3 0.4 3 1 0
rect 2 -3 3 3 1 0
grid 281 281
contour window.cont
X
sed 's/^grid nz .*/grid nz 30/' "$TOP/examples/contact/resist.in" >window-r.in
"$NEW/splat" -q window.in || exit 1
"$NEW/bleach" -q -o window.bin window.cont window-r.in || exit 1
echo "contact resist, 281 x 281 x 31 window (9 tiles), 2 threads:"
bench_run "ray-string -et 60 -pt 10" "$NEW/etch" -q -threads 2 -et 60 -pt 10 -o ray.plot window.bin
bench_run "fmm old -et 60 -pt 10" "$OLD/etch" -q -threads 2 -method fmm -et 60 -pt 10 -o old.plot window.bin
bench_run "fmm new -et 60 -pt 10" "$NEW/etch" -q -threads 2 -method fmm -et 60 -pt 10 -o new.plot window.bin
cmp -s old.plot new.plot && echo "  (same curves.plot)" || echo "  (curves.plot differs)"
exit 0
