#!/bin/sh
# tests/bench/etch.sh [BUILD] - time, peak memory and final mesh size of
# etch:
#   - the seed-point sphere (uniform 1 um/s, 1 s, thesis Figure 8.3);
#   - R = exp(-4(x^2 + y^2))(1.05 - cos(8 pi z)) for 3 s (the function of
#     thesis Figure 6.20), 51 x 51 x 300 over 2 x 2 x 2 um;
#   - 30 s of development of the 1.25 um contact of thesis Figures
#     8.14-8.18 (51 x 51 x 300, Olin Hunt 6512, bake in z) from bleach.
#     The aerial image comes from splat on examples/contact/mask.in when
#     splat is built, otherwise a stand-in contact (a Gaussian spot of the same size on
#     the same 51 x 51 window, as tests/bench/bleach.sh does): the rates,
#     and so the developed profile, then differ from the thesis';
#   - the same contact with -seg 0.2, 0.1, 0.05 um: the cost should grow
#     linearly with the number of nodes (thesis Table 7.2 found the same
#     in 2D).
# The thesis took 5-10 minutes on a SUN 4/280 for the contact (8.7); the
# aim here is under 1 s.  Prints figures (best of three runs); asserts
# nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
etch=$BUILD/bin/etch
mkrate=$BUILD/tests/lib/mkrate
bleach=$BUILD/bin/bleach
[ -x "$etch" ] || { echo "etch: $etch not built"; exit 1; }
[ -x "$mkrate" ] || { echo "etch: $mkrate not built"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/etchbench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
cd "$tmp" || exit 1

run() { # label, then etch arguments
	label=$1
	shift
	best=""
	for i in 1 2 3; do
		if [ -x /usr/bin/time ]; then
			/usr/bin/time -f "%e %M" -o t.txt "$etch" "$@" 2>log.txt ||
				{ echo "etch: $label failed: $(tail -n 1 log.txt)"; return; }
			line=$(tail -n 1 t.txt)
		else
			s=$(date +%s.%N)
			"$etch" "$@" 2>log.txt || { echo "etch: $label failed"; return; }
			line="$(echo "$(date +%s.%N) - $s" | bc) 0"
		fi
		if [ -z "$best" ] || awk -v a="$line" -v b="$best" 'BEGIN { split(a, x, " "); split(b, y, " "); exit !(x[1] < y[1]) }'; then
			best=$line
		fi
	done
	mesh=$(sed -n 's/.*final mesh \([0-9]*\) nodes, [0-9]* segments, \([0-9]*\) triangles.*/\1 \2/p' log.txt)
	steps=$(sed -n 's/.* in \([0-9]*\) steps of \([^ ]*\) s.*/\1 \2/p' log.txt)
	echo "$best $mesh $steps" | awk -v l="$label" '{ printf "etch: %-40s %6.2f s %6.1f MB %7d nodes %7d triangles %5d steps of %.3g s\n", l, $1, $2 / 1024, $3, $4, $5, $6 }'
}

"$mkrate" -o one.bin 5 5 5 -1.5 1.5 -1.5 1.5 -3 0 1 || exit 1
run "sphere from a seed, 1 s, -seg 0.1" -et 1 -seg 0.1 -seed 0 0 -1.5 one.bin
run "sphere from a seed, 1 s, -seg 0.05" -et 1 -seg 0.05 -seed 0 0 -1.5 one.bin

"$mkrate" -o f620.bin 51 51 300 -1 1 -1 1 -2 0 'exp(-4*(x^2+y^2))*(1.05-cos(8*pi*z))' || exit 1
run "Figure 6.20 function, 3 s" -et 3 f620.bin

if [ -x "$bleach" ]; then
	# the real aerial image from splat when it is built, else a stand-in
	img=image.cont
	what="contact"
	if ! "$BUILD/bin/splat" -q -o "$img" "$TOP/examples/contact/mask.in" >/dev/null 2>&1; then
		img=spot.cont
		what="stand-in contact"
		awk 'BEGIN { n = 51; print "-2.5 2.5 -2.5 2.5"; print n, n
			for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
				x = -2.5 + 5 * i / (n - 1); y = -2.5 + 5 * j / (n - 1)
				printf "%.12g\n", 0.02 + 0.9 * exp(-(x * x + y * y) / 0.5) } }' >"$img"
	fi
	"$bleach" -q "$img" "$TOP/examples/contact/resist.in" >/dev/null 2>&1 &&
		mv rval.3D.binary bake.bin &&
	"$bleach" -q "$img" "$TOP/examples/contact/resist-nobake.in" >/dev/null 2>&1 &&
		mv rval.3D.binary nobake.bin || { echo "etch: bleach failed, no contact case"; exit 0; }
	run "$what, bake, 30 s" -et 30 -pt 10 bake.bin
	run "$what, no bake, 30 s" -et 30 -pt 10 nobake.bin
	for s in 0.2 0.1 0.05 0.025; do
		run "$what, no bake, 30 s, -seg $s" -et 30 -seg $s nobake.bin
	done
else
	echo "etch: bleach not built, no contact case"
fi
