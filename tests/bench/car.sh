#!/bin/sh
# tests/bench/car.sh [BUILD] - time and peak memory of bleach with the
# chemically amplified positive resist's reaction-diffusion bake (aim:
# a 5 x 5 um window, 100 x 100 x 200 points, a 60 s
# bake, under 10 s on one core).  The image is a stand-in array of
# contact holes (0.25 um holes on a 0.5 um pitch, 10 x 10 in the window);
# the resist is examples/car-krf-lines' 0.30 um thick on 200 points (1.5 nm,
# fine enough that the bake needs no z refinement).  One thread,
# best of two runs (elapsed and CPU seconds: on a loaded machine the CPU
# time is the figure); prints the step count bleach chose.
# Then the bake's cliff cases and the examples with a CA resist, each with
# this tree's bleach and with the base revision's (CAR_BASE, default
# c5814ae: main before the extrapolated deterministic bake; d3744ef,
# before the order-1 products kept for the whole bake, the
# closed-form derivative of the linear-noise reaction, the even circulant
# x-y products and the z factors made once a step; 5ab1070, before the
# column steps in place, the inline exponential of the order-1
# neutralisation, one reaction a step with x-y diffusion every step and
# the register-blocked circulant x-y products, and ed01cc5, before the
# graded steps, the one-exponential order-1 reaction, the circulant x-y
# step and the linear-noise bake, show the rounds before)
# exported with git archive and built in a temporary directory, in the
# same run: CPU seconds old and new, seconds per million bake points per
# bake minute, and the largest difference of m between the two (each
# within its own estimate of 1e-3 of a converged bake; the stochastic
# examples/euv-* bakes are not: their noise makes m at the chosen steps
# differ from a 256-step bake by 0.01-0.03, bleach(1)).  The cases: a clear-field
# column 3 x 3 x 401 and a 0.6 um-pitch line image 61 x 61 x 201 (401 bake
# nodes), examples/car-krf-lines' resist at orders 2 and 1, with and
# without quencher (the clear column runs within /usr/bin/time's 0.01 s
# resolution: its per-point figure is noise).  Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
bin=$BUILD/bin/bleach
[ -x "$bin" ] || { echo "car: $bin not built"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/carbench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
cd "$tmp" || exit 1
awk 'BEGIN { n = 100; print "-2.5 2.5 -2.5 2.5"; print n, n
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		x = -2.5 + 5 * i / (n - 1); y = -2.5 + 5 * j / (n - 1)
		u = cos(2 * 3.14159265358979 * x / 0.5); v = cos(2 * 3.14159265358979 * y / 0.5)
		printf "%.12g\n", 0.02 + 0.5 * (0.25 + 0.25 * u) * (1 + v) } }' >holes.cont
sed -e "s/^grid nz .*/grid nz 200/" -e "s/thickness 0.40/thickness 0.30/" "$TOP/examples/car-krf-lines/resist.in" >resist.in
if [ -x /usr/bin/time ]; then
	best=""
	for i in 1 2; do
		/usr/bin/time -f "%e %U %M" -o t.txt "$bin" -threads 1 holes.cont resist.in 2>log.txt ||
			{ echo "car: bleach failed: $(tail -n 1 log.txt)"; exit 1; }
		line=$(tail -n 1 t.txt)
		if [ -z "$best" ] || awk -v a="$line" -v b="$best" 'BEGIN { split(a, x, " "); split(b, y, " "); exit !(x[1] < y[1]) }'; then
			best=$line
		fi
	done
	grep 'peb:' log.txt | sed 's/^bleach: /car: /'
	echo "$best" | awk '{ printf "car: %-36s %6.2f s (%.2f s CPU) %7.1f MB\n", "100x100x200, 60 s bake, 1 thread", $1, $2, $3 / 1024 }'
else
	echo "car: /usr/bin/time missing, timing with the shell only"
	time "$bin" -q -threads 1 holes.cont resist.in
	exit 0
fi

BASE=${CAR_BASE:-c5814ae}
old=
if git -C "$TOP" rev-parse --verify -q "$BASE^{commit}" >/dev/null; then
	mkdir -p base
	if git -C "$TOP" archive "$BASE" | tar -x -C base &&
		make -s -C base -j2 BUILD=build build/bin/bleach >base.log 2>&1; then
		old=$tmp/base/build/bin/bleach
		echo "car: cliff cases, old = $BASE, new = this tree, one thread, CPU seconds"
	else
		echo "car: building $BASE failed; new only"
	fi
else
	echo "car: base revision $BASE missing; new only"
fi
awk 'BEGIN { print "-0.1 0.1 -0.1 0.1"; print 3, 3; for (i = 0; i < 9; i++) print 1 }' >clear.cont
awk 'BEGIN { n = 61; print "-0.3 0.3 -0.3 0.3"; print n, n
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		x = -0.3 + 0.6 * i / (n - 1)
		printf "%.12g\n", 0.5 + 0.45 * cos(2 * 3.14159265358979 * x / 0.6) } }' >lines.cont
# cpu BIN OUT CONT IN: user seconds of one run into $cpu
cpu() {
	/usr/bin/time -f "%U" -o c.txt "$1" -q -ascii -threads 1 -o "$2" "$3" "$4" 2>log.txt ||
		{ echo "car: bleach failed: $(tail -n 1 log.txt)"; exit 1; }
	cpu=$(tail -n 1 c.txt)
}
for c in "clear 401 2 0" "lines 201 2 0" "clear 401 1 0.15" "lines 201 1 0.15" "lines 201 2 0.15"; do
	set -- $c
	sed -e "s/^grid nz .*/grid nz $2/" -e "s/order 1/order $3/" -e "s/quencher 0.15/quencher $4/" \
		"$TOP/examples/car-krf-lines/resist.in" >cliff.in
	cpu "$bin" new.txt "$1.cont" cliff.in
	new=$cpu
	pts=$(awk 'NR == 2 { print $1 * $2 * ($3 * 2 - 1) }' new.txt)
	[ "$1" = clear ] && pts=$(awk 'NR == 2 { print $1 * $2 * $3 }' new.txt)
	line=$(printf "%s order %s quencher %s, nz %s" "$1" "$3" "$4" "$2")
	if [ -n "$old" ]; then
		cpu "$old" old.txt "$1.cont" cliff.in
		dm=$(awk 'FNR == 1 { f++; m = 0; n = 0 } /^M/ { m = 1; next }
			m { for (i = 1; i <= NF; i++) { n++; if (f == 1) a[n] = $i
				else { d = $i - a[n]; if (d < 0) d = -d; if (d > x) x = d } } }
			END { printf "%.2g", x }' old.txt new.txt)
		echo "$line $cpu $new $pts $dm" | awk '{ printf "car: %-36s old %7.2f s new %6.2f s (%.2f s per Mpoint-minute) max |dm| %s\n",
			$1 " " $2 " " $3 " " $4 " " $5 " " $6 " " $7, $8, $9, $9 / ($10 / 1e6), $11 }'
	else
		echo "$line $new $pts" | awk '{ printf "car: %-36s new %6.2f s (%.2f s per Mpoint-minute)\n",
			$1 " " $2 " " $3 " " $4 " " $5 " " $6 " " $7, $8, $8 / ($9 / 1e6) }'
	fi
done
# the examples with a CA resist, their own images (splat) and grids
for e in car-krf-lines car-arf-contact euv-contacts euv-lines; do
	"$BUILD/bin/splat" -q "$TOP/examples/$e/mask.in" 2>/dev/null && [ -f image.cont ] ||
		{ echo "car: splat fails on examples/$e"; continue; }
	mv image.cont "$e.cont"
	/usr/bin/time -f "%U" -o c.txt "$bin" -ascii -threads 1 -o new.txt "$e.cont" "$TOP/examples/$e/resist.in" 2>log.txt ||
		{ echo "car: bleach failed on examples/$e: $(tail -n 1 log.txt)"; continue; }
	new=$(tail -n 1 c.txt)
	# bake points: the refined z grid when the bake refines it
	nze=$(sed -n 's/.*peb: on \([0-9]*\) points through the resist.*/\1/p' log.txt)
	pts=$(awk -v z="$nze" 'NR == 2 { print $1 * $2 * (z != "" ? z : $3) }' new.txt)
	mins=$(awk '/^peb/ { for (i = 1; i < NF; i++) if ($i == "time") print $(i + 1) / 60 }' "$TOP/examples/$e/resist.in")
	if [ -n "$old" ]; then
		cpu "$old" old.txt "$e.cont" "$TOP/examples/$e/resist.in"
		dm=$(awk 'FNR == 1 { f++; m = 0; n = 0 } /^M/ { m = 1; next }
			m { for (i = 1; i <= NF; i++) { n++; if (f == 1) a[n] = $i
				else { d = $i - a[n]; if (d < 0) d = -d; if (d > x) x = d } } }
			END { printf "%.2g", x }' old.txt new.txt)
		echo "$e $cpu $new $pts $mins $dm" | awk '{ printf "car: %-36s old %7.2f s new %6.2f s (%.2f s per Mpoint-minute) max |dm| %s\n",
			"examples/" $1, $2, $3, $3 / ($4 / 1e6) / $5, $6 }'
	else
		echo "$e $new $pts $mins" | awk '{ printf "car: %-36s new %6.2f s (%.2f s per Mpoint-minute)\n",
			"examples/" $1, $2, $2 / ($3 / 1e6) / $4 }'
	fi
done
