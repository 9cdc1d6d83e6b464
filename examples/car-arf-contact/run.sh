#!/bin/sh
# 100 nm contact holes at ArF, NA 0.80, in a chemically amplified positive resist (bleach(5) car, peb).
# Usage: sh run.sh [sample3D options, e.g. -q]; outputs go to $OUT (default: out/ here).
# Developed by fast marching (-method fmm): at this 0.014 um image grid
# the ray-string's fronts meet in thousands of loops, which measure
# refuses, and its CD lies further from the converged one (docs/accuracy.md).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
sample3D -if "$here/mask.in" -bf "$here/resist.in" -et 20 -pt 10 -hidden -cut y 0 -method fmm "$@"
