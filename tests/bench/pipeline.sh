#!/bin/sh
# tests/bench/pipeline.sh [BUILD] - the 1.25 um contact end to end
# (examples/contact: splat 51x51, bleach 51x51x300 with bake, etch 30 s,
# pdraw): wall time and peak resident memory of each stage, best of 3.
# The thesis spent 5-10 minutes on the development alone; the aim is the
# whole pipeline under 1 s.  Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
PATH=$BUILD/bin:$PATH
E=$TOP/examples/contact
dir=$(mktemp -d "${TMPDIR:-/tmp}/pipebench.XXXXXX")
trap 'rm -rf "$dir"' EXIT INT TERM
cd "$dir" || exit 1
timeit() { # timeit LABEL CMD...: best of 3 wall times, peak RSS of the last run
	best= rss=
	for r in 1 2 3; do
		if [ -x /usr/bin/time ]; then
			/usr/bin/time -f '%e %M' -o t.out "$@" >/dev/null 2>&1 || { echo "$1 failed"; return; }
			t=$(cut -d' ' -f1 t.out); rss=$(cut -d' ' -f2 t.out)
		else
			t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N)
			t=$(echo "$t1 - $t0" | bc 2>/dev/null || echo "?")
		fi
		best=$(awk -v a="${best:-1e9}" -v b="$t" 'BEGIN { print (b < a ? b : a) }')
	done
	printf '%-8s %6.3f s  %6s MB\n' "$(basename "$1")" "$best" "$(awk -v k="${rss:-0}" 'BEGIN { printf "%.1f", k / 1024 }')"
	total=$(awk -v a="${total:-0}" -v b="$best" 'BEGIN { print a + b }')
}
total=0
timeit splat -q "$E/mask.in"
timeit bleach -q image.cont "$E/resist.in"
timeit etch -q -et 30 rval.3D.binary
timeit pdraw -noplot -h curves.plot
printf 'total    %6.3f s  (splat + bleach + etch + pdraw, best of 3 each)\n' "$total"
