#!/bin/sh
# Thesis Figure 9.26: 0.4 um lines in a negative chemically amplified resist (248 nm), 120 s: the lines neck at the substrate.
# Usage: sh run.sh [sample3D options, e.g. -deloop]; outputs go to $OUT (default: out/ here).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
sample3D -if "$here/mask.in" -bf "$here/resist.in" -et 120 -pt 40 -hidden -cut y 0 "$@"
