#!/bin/sh
# tests/bench/speed.sh [BUILD] - the speed-ups of etch, splat and bleach against the code
# before them, measured in the same run: the base revision (BENCH_BASE,
# default 8b1cf56, the tree before them) is exported with git archive
# into a temporary directory and built there, then the same commands run
# with the old and the new programs.  Figures are wall and CPU
# (user + sys) seconds, best of 3, and peak resident memory; the ratio is
# old / new.  The machine is shared, so wall times move with its load;
# CPU times are steadier but do not show the threads.  Asserts nothing;
# outputs are compared (byte for byte but for '#' comment lines) as a
# check that the runs are like for like.
#   - the contact example end to end (examples/contact/run.sh: splat,
#     bleach -solid, etch, pdraw, drawplot, contour; with and without
#     bake; each program set reads only its own intermediate files), like
#     for like:
#     both with the same explicit discretisation, -seg 0.05 (since
#     4e21cf4 etch's default S_ideal resolves standing waves, 0.05 um on
#     the unbaked contact where the base took 0.1: three times the
#     triangles, an intended accuracy change); then at each one's
#     defaults, for information only (unlike runs);
#   - bleach on the contact resampled to 201 x 201 x 300 (12 M points):
#     binary (CRC) and -ascii (number printing) output; each bleach reads
#     the image.cont its own splat wrote (the new one has a "# labels"
#     line the base cannot read);
#   - etch on that rate file, 30 s, -seg 0.083: memory (reading only the
#     rate, streamed) and time;
#   - bleach and etch of the new code at 1 and 2 threads.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
BASE=${BENCH_BASE:-8b1cf56}
NEW=$BUILD/bin
[ -x "$NEW/etch" ] || { echo "speed: $NEW/etch not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "speed: /usr/bin/time missing (Debian package time)"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/speedbench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
if ! git -C "$TOP" rev-parse --verify -q "$BASE^{commit}" >/dev/null; then
	echo "speed: base revision $BASE not in this repository; no comparison"
	exit 0
fi
mkdir -p "$tmp/base"
git -C "$TOP" archive "$BASE" | tar -x -C "$tmp/base" || { echo "speed: git archive failed"; exit 1; }
make -s -C "$tmp/base" -j2 BUILD=build all >"$tmp/base.log" 2>&1 ||
	{ echo "speed: building $BASE failed"; tail -n 5 "$tmp/base.log"; exit 1; }
OLD=$tmp/base/build/bin
echo "speed: old = $BASE, new = this tree; best of 3; ratio old / new"

# measure DIR CMD...: best wall and CPU of $REPS runs (default 3) in DIR,
# peak RSS of the best; sets w c m
REPS=3
measure() {
	d=$1
	shift
	w= c= m=
	for r in $(seq "$REPS"); do
		(cd "$d" && /usr/bin/time -f '%e %U %S %M' -o "$tmp/t.out" "$@" >/dev/null 2>"$tmp/err.out") ||
			{ echo "speed: failed: $*"; tail -n 3 "$tmp/err.out"; w=0 c=0 m=0; return 1; }
		read -r tw tu ts tm <"$tmp/t.out"
		tc=$(awk -v u="$tu" -v s="$ts" 'BEGIN { print u + s }')
		if [ -z "$w" ] || awk -v a="$tw" -v b="$w" 'BEGIN { exit !(a < b) }'; then w=$tw m=$tm; fi
		if [ -z "$c" ] || awk -v a="$tc" -v b="$c" 'BEGIN { exit !(a < b) }'; then c=$tc; fi
	done
}

# row LABEL: old figures in ow oc om, new in w c m
row() {
	awk -v l="$1" -v ow="$ow" -v oc="$oc" -v om="$om" -v w="$w" -v c="$c" -v m="$m" 'BEGIN {
		printf "speed: %-34s wall %6.2f -> %6.2f s (%4.1fx)  cpu %6.2f -> %6.2f s (%4.1fx)  mem %6.0f -> %6.0f MB\n",
			l, ow, w, (w > 0 ? ow / w : 0), oc, c, (c > 0 ? oc / c : 0), om / 1024, m / 1024 }'
}

compare() { # LABEL DIR-OLD DIR-NEW FILE...: the same but for '#' lines
	l=$1 a=$2 b=$3
	shift 3
	for f in "$@"; do
		case $f in
		*.binary) cp "$a/$f" "$tmp/cmp-a"; cp "$b/$f" "$tmp/cmp-b" ;;
		*) grep -v '^#' "$a/$f" >"$tmp/cmp-a"; grep -v '^#' "$b/$f" >"$tmp/cmp-b" ;;
		esac 2>/dev/null
		if [ ! -e "$a/$f" ] || [ ! -e "$b/$f" ]; then
			echo "speed: $l: $f missing"
		elif ! cmp -s "$tmp/cmp-a" "$tmp/cmp-b"; then
			echo "speed: $l: $f differs between old and new"
		fi
	done
}

# 1. the contact example end to end: like for like (-seg 0.05), then
# the defaults; each program set reads only its own intermediate files
e2e() { # LABEL SAMPLE3D-OPTIONS...
	l=$1
	shift
	for v in old new; do rm -rf "$tmp/e2e-$v"; mkdir -p "$tmp/e2e-$v"; done
	measure "$tmp/e2e-old" env OUT="$tmp/e2e-old/out" PATH="$OLD:$PATH" sh "$TOP/examples/contact/run.sh" "$@"
	ow=$w oc=$c om=$m
	measure "$tmp/e2e-new" env OUT="$tmp/e2e-new/out" PATH="$NEW:$PATH" sh "$TOP/examples/contact/run.sh" "$@"
	row "$l"
}
# like for like: the same numbers but for comment lines (the new files
# carry a "# labels" line); the pictures differ by intent (labels, -walls)
e2e "contact end to end, -seg 0.05" -seg 0.05
for b in bake nobake; do
	compare "contact $b -seg 0.05" "$tmp/e2e-old/out/$b" "$tmp/e2e-new/out/$b" \
		image.cont rval.3D.binary curves.plot curves.plot.2D
done
echo "speed: (the figure above is like for like; the one below is not: the new"
echo "speed:  default S_ideal is finer on the unbaked contact, 3x the triangles)"
e2e "contact end to end, defaults"
# the bleach rows read each one's own image.cont (splat's, which -seg
# does not change)
for v in old new; do mkdir -p "$tmp/b-$v"; cp "$tmp/e2e-$v/out/bake/image.cont" "$tmp/b-$v/"; done

# 2. bleach at 201 x 201 x 300
E=$TOP/examples/contact
sed 's/^grid nz 300/grid nx 201 ny 201 nz 300/' "$E/resist.in" >"$tmp/big.in"
measure "$tmp/b-old" "$OLD/bleach" -q image.cont ../big.in
ow=$w oc=$c om=$m
measure "$tmp/b-new" "$NEW/bleach" -q image.cont ../big.in
row "bleach 201x201x300 binary"
compare "bleach binary" "$tmp/b-old" "$tmp/b-new" rval.3D.binary
REPS=1 # the old one takes half a minute
measure "$tmp/b-old" "$OLD/bleach" -q -ascii image.cont ../big.in
ow=$w oc=$c om=$m
measure "$tmp/b-new" "$NEW/bleach" -q -ascii image.cont ../big.in
row "bleach 201x201x300 -ascii (1 run)"
REPS=3
compare "bleach -ascii" "$tmp/b-old" "$tmp/b-new" rval.3D
rm -f "$tmp/b-old/rval.3D" "$tmp/b-new/rval.3D"

# 3. etch on that rate file
measure "$tmp/b-old" "$OLD/etch" -q -et 30 -seg 0.083 rval.3D.binary
ow=$w oc=$c om=$m
measure "$tmp/b-new" "$NEW/etch" -q -et 30 -seg 0.083 rval.3D.binary
row "etch 201x201x300 30 s"
compare "etch" "$tmp/b-old" "$tmp/b-new" curves.plot curves.plot.2D

# 4. threads, new code only
measure "$tmp/b-new" "$NEW/bleach" -q -threads 1 image.cont ../big.in
ow=$w oc=$c om=$m
measure "$tmp/b-new" "$NEW/bleach" -q -threads 2 image.cont ../big.in
row "bleach 201x201x300, 1 -> 2 threads"
measure "$tmp/b-new" "$NEW/etch" -q -threads 1 -et 30 -seg 0.083 rval.3D.binary
ow=$w oc=$c om=$m
measure "$tmp/b-new" "$NEW/etch" -q -threads 2 -et 30 -seg 0.083 rval.3D.binary
row "etch 201x201x300, 1 -> 2 threads"
exit 0
