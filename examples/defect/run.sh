#!/bin/sh
# Thesis Figures 9.4-9.9: 0.5 um opaque defect in a 1.3 um line/space array, on Shipley 1470, Olin Hunt 6512 and Kodak 820 at 80%, 100% and 120% of their best dose, 30 s.
# Usage: sh run.sh [sample3D options, e.g. -deloop]; outputs go to $OUT (default: out/ here).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
# the aerial image once, then each resist and dose
splat -q "$here/mask.in"
for r in "$here"/resist-*.in; do
	name=$(basename "$r" .in)
	mkdir -p "$out/$name"
	cd "$out/$name"
	sample3D -cf "$out/image.cont" -bf "$r" -et 30 -pt 10 -hidden -cut y 0 "$@"
done
