#!/bin/sh
# tests/bench/fmm.sh [BUILD] - timings of etch's fast-marching engine
# (on 51 x 51 x 300 and 128^3 grids; a plain
# single-threaded C fast marching takes about 0.5 s for 100^3).  Drives
# the solver through the bench mode of the fmm_exact unit test: a contact
# hole in a resist with standing waves, solved from the resist top, then
# the surface T = 20 s extracted.  Prints one line per grid; asserts
# nothing (speed is measured here, never in a test).
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
drv=$BUILD/tests/etch/fmm_exact
[ -x "$drv" ] || { echo "fmm: $drv not built"; exit 1; }
for g in "100 100 100" "51 51 300" "51 51 300 4" "128 128 128"; do
	# shellcheck disable=SC2086
	"$drv" bench $g || exit 1
done
