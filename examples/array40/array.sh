#!/bin/sh
# The large-mask case: a SIZE x SIZE um (default 40) array of 0.5 um
# contacts on a 1 um pitch through sample3D (splat, bleach, etch).
# Usage: sh array.sh [SIZE] [sample3D options]; outputs go to $OUT/SIZE
# (default: out/SIZE here).  Minutes and gigabytes: see README.
# Developed by fast marching (-method fmm), whose surface measure reads:
# the ray-string's fronts meet between the contacts in loops measure
# refuses (tests/bench/large.sh times both engines).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
size=40
case ${1:-} in [0-9]*) size=$1; shift ;; esac
out=${OUT:-$here/out}/$size
mkdir -p "$out"
cd "$out"
sh "$here/make-mask.sh" "$size" >mask.in
sample3D -if mask.in -bf "$here/resist.in" -et 60 -last -hidden -method fmm "$@"
