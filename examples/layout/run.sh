#!/bin/sh
# A layout clip from GDSII: the active layer of a 2 x 2 block of SRAM-like
# bit cells (sram.gds, written by make_sram.py with gdspy), Olin Hunt 6512, 30 s.
# Usage: sh run.sh [sample3D options, e.g. -deloop]; outputs go to $OUT (default: out/ here).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
# splat reads sram.gds beside mask.in (a relative gds FILE is relative to the input's folder)
sample3D -if "$here/mask.in" -bf "$here/resist.in" -et 30 -pt 10 -hidden "$@"
