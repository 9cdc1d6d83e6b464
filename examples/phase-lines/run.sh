#!/bin/sh
# Thesis Figures 9.19-9.22: 1 um phase-shifted spaces with 0/180 and 0/90/180 joints, Olin Hunt 6512 and Shipley 1470, 10 s.
# Usage: sh run.sh [sample3D options, e.g. -deloop]; outputs go to $OUT (default: out/ here).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
for r in olinhunt6512 shipley1470; do
	mkdir -p "$out/$r" && cd "$out/$r"
	sample3D -if "$here/mask.in" -bf "$here/resist-$r.in" -et 10 -hidden "$@"
done
