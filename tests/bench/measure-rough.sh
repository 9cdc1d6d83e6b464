#!/bin/sh
# tests/bench/measure-rough.sh [BUILD] - time and peak memory of measure's
# whole-feature figures on synthetic surfaces of tests/lib/roughsurf:
# -ler on a rough line meshed on 4096 and on 16384 rows (41k and 164k
# triangles; every row is read) and -lcdu on a 40 x 40 array of 64-gon
# holes (1521 holes inside the box; lines enough for 400 across the
# smallest), each with 1 thread and with every core, best of three.
# The line's faces are strips across the whole feature, a thousand times
# longer than wide: the ray test's grid (surf.c) coarsens in both
# directions to hold them, so the time per ray test grows with the rows
# (4096 to 16384 rows: about 10 times the time for 4 times the lines).
# Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
bin=$BUILD/bin/measure rs=$BUILD/tests/lib/roughsurf
[ -x "$bin" ] && [ -x "$rs" ] || { echo "measure-rough: $bin or $rs not built"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/roughbench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
cd "$tmp" || exit 1
for m in 4096 16384; do
	"$rs" line -rows $m -left ar:-0.2:0.004:20:1 -right ar:0.2:0.004:20:2 -truth l.txt -o line$m.plot ||
		{ echo "measure-rough: roughsurf line failed"; exit 1; }
done
"$rs" holes -nx 40 -ny 40 -truth h.txt -o holes.plot ||
	{ echo "measure-rough: roughsurf holes failed"; exit 1; }
run() { # label, threads, file, then measure arguments
	label=$1 threads=$2 file=$3
	shift 3
	best=""
	for i in 1 2 3; do
		if [ -x /usr/bin/time ]; then
			SAMPLE3D_THREADS=$threads /usr/bin/time -f "%e %U %M" -o t.txt "$bin" "$@" "$file" \
				>out.txt 2>err.txt || { echo "measure-rough: $label failed: $(cat err.txt)"; return; }
			line=$(tail -n 1 t.txt)
		else
			s=$(date +%s.%N)
			SAMPLE3D_THREADS=$threads "$bin" "$@" "$file" >out.txt 2>err.txt ||
				{ echo "measure-rough: $label failed"; return; }
			line="$(echo "$(date +%s.%N) - $s" | bc) 0 0"
		fi
		if [ -z "$best" ] || awk -v a="$line" -v b="$best" 'BEGIN { split(a, x, " "); split(b, y, " "); exit !(x[1] < y[1]) }'; then
			best=$line
		fi
	done
	echo "$best" | awk -v l="$label" -v t="$threads" \
		'{ printf "measure: %-36s %2d thr %6.2f s (user %5.2f s) %7.1f MB\n", l, t, $1, $2, $3 / 1024 }'
}
echo "measure: lines of $(sed -n 2p line4096.plot) and $(sed -n 2p line16384.plot) triangles, holes of $(sed -n 2p holes.plot)"
n=$(nproc 2>/dev/null || echo 2)
for t in 1 "$n"; do
	run "-ler, 4096 rows" "$t" line4096.plot -force -rel 50 -ler -line 0 0 x
	run "-ler, 16384 rows" "$t" line16384.plot -force -rel 50 -ler -line 0 0 x
	run "-lcdu, 40 x 40 holes" "$t" holes.plot -force -rel 50 -lcdu -holes
done
