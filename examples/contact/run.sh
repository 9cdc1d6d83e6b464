#!/bin/sh
# Thesis Figures 8.14-8.18: 1.25 um isolated contact in Olin Hunt 6512, with bake (8.17-8.18) and without (8.15-8.16).
# Usage: sh run.sh [sample3D options, e.g. -deloop]; outputs go to $OUT (default: out/ here).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out/bake" "$out/nobake"
cd "$out/bake"
sample3D -if "$here/mask.in" -bf "$here/resist.in" -et 60 -pt 20 -hidden -solid "$@"
cd "$out/nobake"
sample3D -if "$here/mask.in" -bf "$here/resist-nobake.in" -et 60 -pt 20 -hidden "$@"
