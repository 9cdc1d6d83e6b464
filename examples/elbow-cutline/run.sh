#!/bin/sh
# Thesis Figure 2.7: SAMPLE along the diagonal cutline (0,0)-(5,5) of two
# 1.0 um line-space elbows (Figure 2.6), on the Kodak 820 of Figures
# 2.2-2.4, profiles every 15 s to 60 s.
# Usage: sh run.sh [sample2D options, e.g. -method string]; outputs in $OUT (default out/ here).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample2D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
sample2D -if "$here/mask.in" -cut 0 0 5 5 -bf "$here/../resists/kodak820-fig22.in" -et 60 -pt 15 "$@"
