#!/bin/sh
# tests/bench/fmm-decimate.sh [BUILD] - the compact fast-marching
# surfaces: examples/contact with bake and without (etch -et 60 -pt 20,
# three sets), curves.plot bytes and triangles (all sets) of the
# ray-string engine and of -method fmm as -dense (every cell), -tol 0
# (exact-flat merging only: the output before decimation) and the
# default (decimated, -tol 0.02 of the x-y spacing), each with its ratio
# to the ray-string output, and etch's CPU and wall time (one run; the
# decimation's cost is the default's time less -tol 0's).  Also the
# largest CD change (measure -rel 10,50,90 -hole 0 0) against -dense.
# Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
B=$BUILD/bin
M=$BUILD/tests/lib/meshcheck
[ -x "$B/etch" ] && [ -x "$M" ] || { echo "fmm-decimate: $B/etch or $M not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "fmm-decimate: /usr/bin/time missing (Debian package time)"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fmmdec.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
cd "$tmp" || exit 1
E=$TOP/examples/contact
"$B/splat" -q -o image.cont "$E/mask.in" || exit 1
tris() { "$M" stat "$1" | awk '{ n += $4 } END { print n }'; }
for r in resist resist-nobake; do
	"$B/bleach" -q -o r.bin image.cont "$E/$r.in" || exit 1
	"$B/etch" -q -et 60 -pt 20 -o ray.plot r.bin || exit 1
	ray=$(wc -c <ray.plot)
	printf '%s: %-22s %10d bytes %8d triangles\n' "$r" "ray-string" "$ray" "$(tris ray.plot)"
	for v in "-dense" "-tol 0" ""; do
		# shellcheck disable=SC2086
		/usr/bin/time -f '%U %S %e' -o t.txt "$B/etch" -q -et 60 -pt 20 -method fmm $v -o f.plot r.bin || exit 1
		[ -n "$v" ] || v=default
		[ "$v" = -dense ] && "$B/measure" -rel 10,50,90 -hole 0 0 f.plot >dense.cd
		"$B/measure" -rel 10,50,90 -hole 0 0 f.plot >f.cd
		dcd=$(paste f.cd dense.cd | awk '!/^#/ { d = $2 - $7; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.6f", m }')
		b=$(wc -c <f.plot)
		printf '%s: fmm %-18s %10d bytes %8d triangles  %5.2f x ray  cpu %s s wall %s s  max |dCD| %s um\n' \
			"$r" "$v" "$b" "$(tris f.plot)" "$(echo "$b $ray" | awk '{ print $1 / $2 }')" \
			"$(awk '{ print $1 + $2 }' t.txt)" "$(awk '{ print $3 }' t.txt)" "$dcd"
	done
done
