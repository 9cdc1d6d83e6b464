#!/bin/sh
# tests/bench/stochastic.sh [BUILD] - time and peak memory of an EUV window
# with photon and acid shot noise (bleach(5) stochastic) through bleach
# and etch -method fmm: 1 nm voxels in a 40 nm film, 0.64 x 0.64 um (20
# periods of examples/euv-lines' 32 nm pitch lines; 641 x 641 x 41 nodes,
# 16.8 M voxels), examples/euv-lines' resist at 30 mJ/cm2 with the image
# a cosine of that pitch (0.35 -+ 0.32, about the dipole image's).
# Threads: SAMPLE3D_THREADS or every core; elapsed and CPU seconds of each
# stage (on a loaded machine the CPU time is the figure).  Asserts nothing.
# NX=2001 (2 x 2 um, 164 M voxels) for the larger window.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
for p in bleach etch; do
	[ -x "$BUILD/bin/$p" ] || { echo "stochastic: $BUILD/bin/$p not built"; exit 1; }
done
NX=${NX:-641}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/stochbench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
cd "$tmp" || exit 1
awk -v n="$NX" 'BEGIN { w = (n - 1) / 1000; print -w / 2, w / 2, -w / 2, w / 2; print n, 2
	for (j = 0; j < 2; j++) for (i = 0; i < n; i++) {
		x = -w / 2 + w * i / (n - 1)
		printf "%.12g\n", 0.35 - 0.32 * cos(2 * 3.14159265358979 * x / 0.032) } }' >lines.cont
sed -e "s/^grid .*/grid nx $NX ny $NX nz 41/" -e "s/^dose .*/dose 30/" \
	"$TOP/examples/euv-lines/resist.in" >resist.in
run() { # run WHAT COMMAND...: one line of seconds and MB
	what=$1
	shift
	if [ -x /usr/bin/time ]; then
		/usr/bin/time -f "%e %U %S %M" -o t.txt "$@" 2>log.txt ||
			{ echo "stochastic: $what failed: $(tail -n 2 log.txt)"; exit 1; }
		awk -v w="$what" '{ printf "stochastic: %-44s %7.2f s (%.2f s CPU) %8.1f MB\n", w, $1, $2 + $3, $4 / 1024 }' t.txt
	else
		"$@" 2>log.txt || { echo "stochastic: $what failed"; exit 1; }
	fi
}
v=$(awk -v n="$NX" 'BEGIN { printf "%.3g M voxels", n * n * 41 / 1e6 }')
run "bleach, $NX x $NX x 41 ($v)" "$BUILD/bin/bleach" -o rate.bin lines.cont resist.in
grep 'peb:\|stochastic:' log.txt | sed 's/^bleach: /stochastic:   /'
run "etch -method fmm -et 20 -no2d" "$BUILD/bin/etch" -method fmm -et 20 -pt 20 -no2d rate.bin
tail -n 1 log.txt | sed 's/^etch: /stochastic:   /'
