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
# decimator's speed-ups before them did not).
# Then the solve alone (fmm_solve, fmm.c) against FMM_SOLVE_BASE (default
# c5814ae: before the TRIAL nodes kept their cell slownesses): a driver
# written here is built against each revision's etch objects and times
# fmm_solve by its process CPU clock (the better of two solves), on
# examples/euv-contacts' rate file (shot noise: z refined 16 times,
# 121 x 121 x 321 nodes) and examples/contact's without bake (z x4,
# 51 x 51 x 1197), and prints a checksum of the times T, so that "same
# T" is read off the two lines.  Asserts nothing.
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

# the solve alone: one driver, built against each revision's objects
SBASE=${FMM_SOLVE_BASE:-c5814ae}
sbase=$tmp/base      # the same revision as above: built once
if [ "$SBASE" != "$BASE" ]; then
	sbase=$tmp/sbase
	bench_base fmm-speed "$SBASE" "$sbase" build/bin/etch || { [ $? = 2 ] && exit 0; exit 1; }
fi
cat >solve.c <<'X'
#include "fmm.h"
#include "fmt_rate.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
/* solve RATEFILE: fmm_solve at fmm_auto_refine's z refinement, twice;
 * prints the better CPU time and an FNV-1a hash of T's bytes */
int main(int argc, char **argv)
{
	if (argc != 2)
		return 2;
	struct ratefile *r = fmt_rate_read(argv[1]);
	int ref[3] = {1, 1, fmm_auto_refine(r)};
	double best = 1e300;
	struct fmm *f = NULL;
	for (int k = 0; k < 2; k++) {
		fmm_free(f);
		clock_t c0 = clock();
		f = fmm_solve(r, ref);
		double c = (double)(clock() - c0) / CLOCKS_PER_SEC;
		best = c < best ? c : best;
	}
	size_t n = (size_t)f->n[0] * (size_t)f->n[1] * (size_t)f->n[2];
	unsigned long long h = 14695981039346656037ULL;
	const unsigned char *b = (const unsigned char *)f->t;
	for (size_t i = 0; i < n * sizeof *f->t; i++)
		h = (h ^ b[i]) * 1099511628211ULL;
	printf("%d x %d x %d nodes (z x%d): solve cpu %.2f s, T hash %016llx\n", f->n[0], f->n[1],
	       f->n[2], ref[2], best, h);
	fmm_free(f);
	fmt_rate_free(r);
	return 0;
}
X
solve_driver() { # TREE BUILD OUT: the driver against TREE's headers, BUILD's objects
	_inc=$(for d in "$1"/src/lib/*/; do printf ' -I%s' "$d"; done)
	_obj=$(for o in "$2"/src/etch/*.o; do case $o in */main.o) ;; *) printf ' %s' "$o" ;; esac; done)
	# shellcheck disable=SC2086
	${CC:-cc} -O2 -std=c11 -D_XOPEN_SOURCE=700 $_inc -I"$1/src/etch" -o "$3" solve.c \
		$_obj "$2/libsample3d.a" -lm -lpthread
}
solve_driver "$sbase" "$sbase/build" solve-old || { echo "fmm-speed: solve driver (old) not built"; exit 1; }
solve_driver "$TOP" "$BUILD" solve-new || { echo "fmm-speed: solve driver (new) not built"; exit 1; }
"$NEW/splat" -q -o euv.cont "$TOP/examples/euv-contacts/mask.in" || exit 1
"$NEW/bleach" -q -o euv.bin euv.cont "$TOP/examples/euv-contacts/resist.in" || exit 1
"$NEW/splat" -q -o contact.cont "$TOP/examples/contact/mask.in" || exit 1
"$NEW/bleach" -q -o nobake.bin contact.cont "$TOP/examples/contact/resist-nobake.in" || exit 1
echo "fmm_solve alone, old = $SBASE, new = this tree (CPU, the better of two):"
for c in euv nobake; do
	for v in old new; do
		printf '  %-7s %s: ' "$c" "$v"
		./solve-$v $c.bin || echo "failed"
	done
done
exit 0
