#!/bin/sh
# Thesis Figure 9.23: 0.9 x 2 um clear-field lines, Shipley 1470, 10 s.
# Usage: sh run.sh [sample3D options, e.g. -deloop]; outputs go to $OUT (default: out/ here).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
sample3D -if "$here/mask.in" -bf "$here/resist.in" -et 10 -hidden "$@"
