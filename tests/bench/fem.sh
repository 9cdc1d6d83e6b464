#!/bin/sh
# tests/bench/fem.sh [BUILD] - a 7 x 7 focus-exposure matrix of the contact
# example (examples/contact, 60 s development; doses 50-110 mJ/cm2, foci
# -3 to 3 um) with fem -j 2: wall time of the sweep (splat 7 times,
# bleach, etch and measure 49 times, the collection and the plots) and the
# disk the sweep directory uses at the end, and the CPU time of every
# process (wall >= CPU / 2 on an idle machine).  Aim: under 60 s on 2 cores.
# Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
PATH=$BUILD/bin:$PATH
E=$TOP/examples/contact
dir=$(mktemp -d "${TMPDIR:-/tmp}/fembench.XXXXXX")
trap 'rm -rf "$dir"' EXIT INT TERM
cd "$dir" || exit 1
run() {
	fem -q -if "$E/mask.in" -bf "$E/resist.in" -et 60 -dose 50:110:10 -focus -3:3:1 \
		-measure "-rel 10,90 -hole 0 0" -target 1.0 -tol 10 -j 2 -d m >window.txt 2>err.txt
}
t0=$(date +%s.%N)
if [ -x /usr/bin/time ]; then
	/usr/bin/time -f '%U %S' -o cpu.txt sh -c "$(command -v fem) -q -if '$E/mask.in' -bf '$E/resist.in' \
		-et 60 -dose 50:110:10 -focus -3:3:1 -measure '-rel 10,90 -hole 0 0' \
		-target 1.0 -tol 10 -j 2 -d m >window.txt 2>err.txt"
else
	run
fi || { echo "fem failed: $(head -n 3 err.txt)"; exit 1; }
t1=$(date +%s.%N)
cpu=$(awk '{ printf "%.1f", $1 + $2 }' cpu.txt 2>/dev/null)
printf 'fem 7x7 contact, -j 2: %.1f s wall, %s s CPU, %s disk at the end (%s points)\n' \
	"$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" "${cpu:-?}" "$(du -sh m | cut -f1)" \
	"$(grep -vc '^#' m/fem.dat)"
sed 's/^/  /' window.txt
