#!/bin/sh
# Thesis Figure 9.5: SAMPLE along the two cutlines of the 0.5 um opaque
# defect in a 1.3 um line/space array (Figure 9.4), 0.7 um of Shipley 1470
# at 80 mJ/cm2, profiles at 5, 10, 15 and 20 s: the north-south cut (along
# the space, through the defect) clears the defect's centre by 15 s, the
# east-west cut (across the lines) still leaves resist there; the 3D
# result of Figure 9.6 is examples/defect (sample3D).  Measured: the
# centre clears at 13.7 s north-south, 15.2 s east-west (docs/workbench.md).
# Usage: sh run.sh [sample2D options, e.g. -method fmm]; outputs in $OUT (default out/ here).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample2D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
resist=$here/../defect/resist-shipley1470-80.in
mkdir -p "$out/north-south" "$out/east-west"
cd "$out/north-south"
sample2D -if "$here/../defect/mask.in" -cut 0 -2.6 0 2.6 -bf "$resist" -et 20 -pt 5 "$@"
cd "$out/east-west"
sample2D -if "$here/../defect/mask.in" -cut -2.6 0 2.6 0 -bf "$resist" -et 20 -pt 5 "$@"
