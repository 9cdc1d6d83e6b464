#!/bin/sh
# Thesis Figure 9.31: 0.9 um contact with 180-degree outrigger phase shifters, Olin Hunt 6512 with and without bake, 30 s.
# Usage: sh run.sh [sample3D options, e.g. -deloop]; outputs go to $OUT (default: out/ here).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out/bake" "$out/nobake"
cd "$out/bake"
sample3D -if "$here/mask.in" -bf "$here/resist.in" -et 30 -hidden "$@"
cd "$out/nobake"
sample3D -if "$here/mask.in" -bf "$here/resist-nobake.in" -et 30 -hidden "$@"
