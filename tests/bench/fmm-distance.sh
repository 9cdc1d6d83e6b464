#!/bin/sh
# tests/bench/fmm-distance.sh [BUILD] - the cost of the distances from a
# mesh's nodes to the fast-marching surface (fmm_distance_many: the cut
# cells of T = t indexed once, each point searching only those of its
# block).  Cases: etch -xcheck on examples/defect (Kodak 820, -et 15
# -deloop, about 19000 nodes, as tests/xcheck/005), whose extra CPU over
# the same run without -xcheck is the refined solve plus the distances;
# and tests/etch/deloop_trench (about 3500 nodes).  Figures: CPU seconds
# (user + sys), one run each.  Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
[ -x "$BUILD/bin/etch" ] || { echo "fmm-distance: $BUILD/bin/etch not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "fmm-distance: /usr/bin/time missing (Debian package time)"; exit 1; }
PATH=$BUILD/bin:$PATH
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fmmdist.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
cd "$tmp" || exit 1
D=$TOP/examples/defect
splat -q -o defect.cont "$D/mask.in" && bleach -q -o k.bin defect.cont "$D/resist-kodak820-110.in" ||
	{ echo "fmm-distance: splat or bleach failed"; exit 1; }
cpu() { # cpu LABEL COMMAND...: prints LABEL and the command's CPU seconds
	label=$1
	shift
	/usr/bin/time -f "%U %S" -o t.txt "$@" >/dev/null 2>&1 || echo "fmm-distance: $label failed"
	awk -v l="$label" '{ printf "  %-40s %.2f s CPU\n", l, $1 + $2 }' t.txt
}
cpu "etch -et 15 -deloop (defect)" etch -et 15 -deloop k.bin
cpu "etch -et 15 -deloop -xcheck (defect)" etch -et 15 -deloop -xcheck k.bin
if [ -x "$BUILD/tests/etch/deloop_trench" ]; then
	cpu "tests/etch/deloop_trench" "$BUILD/tests/etch/deloop_trench"
else
	echo "fmm-distance: $BUILD/tests/etch/deloop_trench not built"
fi
