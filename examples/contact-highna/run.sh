#!/bin/sh
# The image inside the resist: a 0.5 um contact at NA 0.6, i-line, in 1 um of resist, focused 0.3 um inside the resist and 0.3 um above it.
# Usage: sh run.sh [sample3D options, e.g. -q]; outputs go to $OUT (default: out/ here).
# Each run: splat -defocus writes the image stack, sample3D passes it to
# bleach and etch (ray-string, delooped so that measure can read it), and
# measure (when built) writes the CD table at 5%, 50% and 95% of the
# thickness to cd.txt.  out/vector repeats the run inside the resist with
# mask-vector.in (imaging vector; splat -bf images through the film).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v sample3D >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
for d in -0.3 0.3; do
	mkdir -p "$out/defocus$d" && cd "$out/defocus$d"
	splat -q -defocus "$d" "$here/mask.in"
	sample3D -cf image.stack -bf "$here/resist.in" -et 60 -deloop -hidden "$@"
	if command -v measure >/dev/null 2>&1; then
		measure -rel 5,50,95 -hole 0 0 curves.plot >cd.txt
	fi
done
# the same contact by the vector model through the film, focused inside
mkdir -p "$out/vector" && cd "$out/vector"
splat -q -defocus -0.3 -bf "$here/resist.in" "$here/mask-vector.in"
sample3D -cf image.stack -bf "$here/resist.in" -et 60 -deloop -hidden "$@"
if command -v measure >/dev/null 2>&1; then
	measure -rel 5,50,95 -hole 0 0 curves.plot >cd.txt
fi
