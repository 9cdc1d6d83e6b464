#!/bin/sh
# 0.5 um lines and spaces at i-line in a resist developed by the notch model (bleach(5) develop notch).
# Usage: sh run.sh [sample3D options, e.g. -deloop]; outputs go to $OUT (default: out/ here).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
sample3D -if "$here/mask.in" -bf "$here/resist.in" -et 60 -pt 20 -hidden -cut y 0 "$@"
