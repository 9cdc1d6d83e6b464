#!/bin/sh
# tests/bench/splat.sh [BUILD] - timings of splat:
# the 1.25 um contact of examples/contact (51 x 51; aim under 0.05 s) and
# a 10 um x 10 um cell at 201 x 201 with sigma 0.5 (aim under 1 s), the
# latter also with defocus and coma (the pupil phase then needs a row
# quadrature in every TCC).  Best of 3 runs, one core.  Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
bin=$BUILD/bin/splat
[ -x "$bin" ] || { echo "splat: $bin not built"; exit 1; }
dir=$(mktemp -d "${TMPDIR:-/tmp}/splatbench.XXXXXX")
trap 'rm -rf "$dir"' EXIT INT TERM
cp "$TOP/examples/contact/mask.in" "$dir/contact.in"
cell='window 0 10 0 10
sigma 0.5
rect 1 1 3 8
rect 4 1 5 9
rect 6 2 9 3
rect 6 5 9 9 0.5 180
grid 201 201'
printf '%s\n' "$cell" >"$dir/cell.in"
printf '%s\ndefocus 1\ncoma 0.4 field 1 0\n' "$cell" >"$dir/cell-aberr.in"
cd "$dir" || exit 1
for c in contact cell cell-aberr; do
	best=
	for r in 1 2 3; do
		t0=$(date +%s.%N)
		"$bin" -q -o out.cont $c.in || exit 1
		t1=$(date +%s.%N)
		best=$(awk -v a="$t0" -v b="$t1" -v m="$best" 'BEGIN { d = b - a; if (m != "" && m < d) d = m; print d }')
	done
	printf 'splat %-11s %8.3f s\n' "$c" "$best"
done
