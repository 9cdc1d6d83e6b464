#!/bin/sh
# Thesis Figures 9.28 and 9.30: 0.8 lambda/NA contact with astigmatism 0.4 lambda at field (1,0), Olin Hunt 6512 and Shipley 1470, 30 s.
# Usage: sh run.sh [sample3D options, e.g. -deloop]; outputs go to $OUT (default: out/ here).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
for r in olinhunt6512 shipley1470; do
	mkdir -p "$out/$r" && cd "$out/$r"
	sample3D -if "$here/mask.in" -bf "$here/resist-$r.in" -et 30 -hidden "$@"
done
