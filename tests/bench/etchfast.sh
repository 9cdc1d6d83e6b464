#!/bin/sh
# tests/bench/etchfast.sh [BUILD] - etch's speed-ups against the
# code before it, in the same run (the base revision BENCH_BASE, default
# 8b1cf56 as tests/bench/speed.sh, exported with git archive and built in
# a temporary directory; BENCH_BASE=none skips it):
#   - fast-marching output of the contact example (examples/contact with
#     bake, etch -method fmm -et 60 -pt 20): bytes of curves.plot, old and
#     new, and their ratio to the ray-string output of the same case;
#     time (wall and CPU, best of 3);
#   - deloop at about 1e5 and 1e6 triangles (tests/bench/deloop.sh's two
#     spheres, S_ideal 0.032 and 0.01 um): the time etch reports for the
#     deloop passes (CPU seconds, clock(): every thread's, classifier
#     included), one run each, at 1 thread and at the default count;
#   - the fast-marching engine on a 20 x 20 um contact array (1 um pitch,
#     0.5 um contacts, i-line NA 0.6 sigma 0.5, 0.05 um grid, nz 300,
#     bake, 60 s): the rate file is made once (splat and bleach, not
#     timed here), then etch -method fmm alone, new code only (the old one
#     took 451 s; BENCH_FMM_OLD=1 runs it too).  BENCH_QUICK=1 skips the
#     1e6 deloop and the array.
# The machine is shared: wall times move with its load; CPU times are
# steadier but do not show the threads.  Asserts nothing; the outputs of
# old and new are compared (cmp) where they should be equal.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
NEW=$BUILD/bin
BASE=${BENCH_BASE:-8b1cf56}
mkrate=$BUILD/tests/lib/mkrate
[ -x "$NEW/etch" ] && [ -x "$mkrate" ] || { echo "etchfast: $NEW/etch or $mkrate not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "etchfast: /usr/bin/time missing (Debian package time)"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/etchfast.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
OLD=
if [ "$BASE" != none ] && git -C "$TOP" rev-parse --verify -q "$BASE^{commit}" >/dev/null; then
	mkdir -p "$tmp/base"
	if git -C "$TOP" archive "$BASE" | tar -x -C "$tmp/base" &&
		make -s -C "$tmp/base" -j2 BUILD=build all >"$tmp/base.log" 2>&1; then
		OLD=$tmp/base/build/bin
		echo "etchfast: old = $BASE, new = this tree"
	else
		echo "etchfast: building $BASE failed; new code only"
	fi
else
	echo "etchfast: no base revision; new code only"
fi

# run DIR BIN ARGS...: one run, wall and CPU seconds in w c
run() {
	d=$1
	shift
	(cd "$d" && /usr/bin/time -f '%e %U %S' -o "$tmp/t.out" "$@" >/dev/null 2>"$tmp/err.out") ||
		{ echo "etchfast: failed: $*"; tail -n 3 "$tmp/err.out"; w=0 c=0; return 1; }
	read -r w tu ts <"$tmp/t.out"
	c=$(awk -v u="$tu" -v s="$ts" 'BEGIN { print u + s }')
}

# best DIR BIN ARGS...: best wall and CPU of 3 runs in bw bc
best() {
	bw= bc=
	for r in 1 2 3; do
		run "$@" || return 1
		if [ -z "$bw" ] || awk -v a="$w" -v b="$bw" 'BEGIN { exit !(a < b) }'; then bw=$w; fi
		if [ -z "$bc" ] || awk -v a="$c" -v b="$bc" 'BEGIN { exit !(a < b) }'; then bc=$c; fi
	done
}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.1fx", a / b; else printf "-" }'; }

# 1. fast-marching output of the contact example
E=$TOP/examples/contact
mkdir -p "$tmp/c"
(cd "$tmp/c" && "$NEW/splat" -q -o image.cont "$E/mask.in" &&
	"$NEW/bleach" -q -o bake.bin image.cont "$E/resist.in") || { echo "etchfast: splat/bleach failed"; exit 1; }
run "$tmp/c" "$NEW/etch" -q -et 60 -pt 20 -o ray.plot bake.bin
ray=$(wc -c <"$tmp/c/ray.plot")
best "$tmp/c" "$NEW/etch" -q -et 60 -pt 20 -method fmm -o new.plot bake.bin
nw=$bw nc=$bc
new=$(wc -c <"$tmp/c/new.plot")
if [ -n "$OLD" ]; then
	best "$tmp/c" "$OLD/etch" -q -et 60 -pt 20 -method fmm -o old.plot bake.bin
	old=$(wc -c <"$tmp/c/old.plot")
	printf 'etchfast: fmm contact output   %10d -> %10d bytes (%s smaller); ray-string %d bytes: fmm/ray %s -> %s\n' \
		"$old" "$new" "$(ratio "$old" "$new")" "$ray" "$(ratio "$old" "$ray")" "$(ratio "$new" "$ray")"
	printf 'etchfast: fmm contact time     wall %6.2f -> %6.2f s (%s)  cpu %6.2f -> %6.2f s (%s)\n' \
		"$bw" "$nw" "$(ratio "$bw" "$nw")" "$bc" "$nc" "$(ratio "$bc" "$nc")"
else
	printf 'etchfast: fmm contact output   %10d bytes; ray-string %d bytes: fmm/ray %s\n' \
		"$new" "$ray" "$(ratio "$new" "$ray")"
	printf 'etchfast: fmm contact time     wall %6.2f s  cpu %6.2f s\n' "$nw" "$nc"
fi

# 2. deloop at about 1e5 and 1e6 triangles
mkdir -p "$tmp/d"
"$mkrate" -o "$tmp/d/two.bin" 31 41 31 -1.5 1.5 -1.5 2.5 -1.5 1.5 1 >/dev/null || exit 1
segs="0.032 0.01"
[ "${BENCH_QUICK:-0}" = 1 ] && segs=0.032
# dl BIN THREADS|old SEG: the deloop CPU seconds etch reports, summed
# over its runs, in dt; the final triangles in ntri
dl() {
	th="-threads $2"
	[ "$2" = old ] && th=    # the base code may have no -threads: one thread
	(cd "$tmp/d" && "$1" $th -et 1 -dt 0.1 -pt 0.8 -seg "$3" -seed 0 0 0 -seed 0 1 0 \
		-deloop -o "x$2.plot" two.bin >/dev/null 2>log.txt) || { echo "etchfast: deloop run failed"; dt=0; return 1; }
	dt=$(awk '/deloop:/ { for (i = 1; i <= NF; i++) if ($i == "in") s += $(i + 1) } END { print s + 0 }' "$tmp/d/log.txt")
	ntri=$(awk '/final mesh/ { for (i = 1; i <= NF; i++) if ($i == "triangles") { print $(i - 1); exit } }' "$tmp/d/log.txt")
}
for seg in $segs; do
	dl "$NEW/etch" 1 "$seg"
	n1=$dt
	dl "$NEW/etch" "$(nproc)" "$seg"
	n2=$dt
	cmp -s "$tmp/d/x1.plot" "$tmp/d/x$(nproc).plot" || echo "etchfast: deloop output differs with the thread count!"
	if [ -n "$OLD" ]; then
		cp "$tmp/d/x1.plot" "$tmp/d/new.plot"
		dl "$OLD/etch" old "$seg"
		o1=$dt
		same=same
		cmp -s "$tmp/d/xold.plot" "$tmp/d/new.plot" || same=DIFFERENT
		printf 'etchfast: deloop %8s triangles  cpu, 1 thread %6.2f -> %6.2f s (%s), %d threads %6.2f s; output %s\n' \
			"$ntri" "$o1" "$n1" "$(ratio "$o1" "$n1")" "$(nproc)" "$n2" "$same"
	else
		printf 'etchfast: deloop %8s triangles  cpu, 1 thread %6.2f s, %d threads %6.2f s\n' "$ntri" "$n1" "$(nproc)" "$n2"
	fi
done

# 3. the fast-marching engine on a 20 x 20 um contact array
[ "${BENCH_QUICK:-0}" = 1 ] && exit 0
mkdir -p "$tmp/a"
{
	echo "wavelength 0.365"
	echo "na 0.6"
	echo "sigma 0.5"
	echo "background dark"
	echo "window -10 10 -10 10"
	awk 'BEGIN { for (j = 0; j < 20; j++) for (i = 0; i < 20; i++)
		printf "rect %g %g %g %g\n", -9.75 + i, -9.75 + j, -9.25 + i, -9.25 + j }'
	echo "grid 401 401"
	echo "contour image.cont"
} >"$tmp/a/mask.in"
sed 's/^grid nz .*/grid nz 300/' "$TOP/examples/contact-highna/resist.in" >"$tmp/a/resist.in"
run "$tmp/a" "$NEW/splat" -q -o image.cont mask.in || exit 0
sw=$w
run "$tmp/a" "$NEW/bleach" -q -o rate.bin image.cont resist.in || exit 0
printf 'etchfast: 20 um array rate file: splat %.1f s, bleach %.1f s wall (not in the figure below)\n' "$sw" "$w"
run "$tmp/a" "$NEW/etch" -q -et 60 -method fmm -o fmm.plot rate.bin
aw=$w ac=$c
asz=$(wc -c <"$tmp/a/fmm.plot")
printf 'etchfast: 20 um array fmm etch wall %7.1f s  cpu %7.1f s  curves.plot %d bytes\n' "$aw" "$ac" "$asz"
if [ -n "$OLD" ] && [ "${BENCH_FMM_OLD:-0}" = 1 ]; then
	run "$tmp/a" "$OLD/etch" -q -et 60 -method fmm -o old.plot rate.bin
	printf 'etchfast: 20 um array fmm etch old wall %7.1f s  cpu %7.1f s  curves.plot %d bytes\n' \
		"$w" "$c" "$(wc -c <"$tmp/a/old.plot")"
fi
exit 0
