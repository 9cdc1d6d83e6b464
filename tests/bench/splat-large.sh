#!/bin/sh
# tests/bench/splat-large.sh [BUILD] - splat on large windows:
# a contact array of 1 um pitch (0.5 um dark-field contacts), i-line
# 0.365 um, NA 0.6, sigma 0.5, a 0.05 um grid, at 5, 10, 20 and 40 um
# windows: wall time, CPU time and peak memory of -method abbe and of
# -method hopkins with their ratio (hopkins skipped above 20 um: minutes),
# all cores (SAMPLE3D_THREADS, default every core); then the 40 um window
# at NA 0.5 (aim: within 10 s) with the
# default -method auto, and the 20 um window with 1 thread and with 2
# threads (abbe).  Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
bin=$BUILD/bin/splat
[ -x "$bin" ] || { echo "splat-large: $bin not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "splat-large: /usr/bin/time missing"; exit 0; }
dir=$(mktemp -d "${TMPDIR:-/tmp}/splatlarge.XXXXXX")
trap 'rm -rf "$dir"' EXIT INT TERM
cd "$dir" || exit 1
# array L NA: the L um window's input on stdout
array() {
	awk -v L="$1" -v na="$2" 'BEGIN {
		print "wavelength 0.365"; print "na " na; print "sigma 0.5"
		print "background dark"; printf "window 0 %g 0 %g\n", L, L
		for (i = 0; i < L; i++)
			for (j = 0; j < L; j++)
				printf "rect %g %g %g %g\n", i + 0.25, j + 0.25, i + 0.75, j + 0.75
		printf "grid %d %d\n", L / 0.05 + 1, L / 0.05 + 1
	}'
}
# run LABEL ARGS..: prints the figures, sets $wall
run() {
	label=$1
	shift
	/usr/bin/time -f "%e %U %M" -o t.txt "$bin" -q "$@" || { echo "splat-large: $label failed"; wall=; return; }
	read -r wall cpu kb <t.txt
	printf 'splat %-28s %8.2f s wall %8.2f s cpu %7.0f MB\n' "$label" "$wall" "$cpu" "$((kb / 1024))"
}
echo "splat-large: $(nproc) cores, threads ${SAMPLE3D_THREADS:-all}"
for L in 5 10 20 40; do
	array $L 0.6 >a$L.in
	run "${L}um abbe" -method abbe -o a.cont a$L.in
	wa=$wall
	if [ "$L" -le 20 ]; then
		run "${L}um hopkins" -method hopkins -o h.cont a$L.in
		wh=$wall
		[ -n "$wa" ] && [ -n "$wh" ] &&
			awk -v a="$wa" -v h="$wh" -v L="$L" 'BEGIN { printf "splat %sum hopkins/abbe wall ratio %.1f\n", L, h / (a > 0.005 ? a : 0.005) }'
	fi
done
array 40 0.5 >b40.in
run "40um NA 0.5 auto" -o b.cont b40.in
run "20um abbe 1 thread" -method abbe -threads 1 -o a.cont a20.in
run "20um abbe 2 threads" -method abbe -threads 2 -o a.cont a20.in
exit 0
