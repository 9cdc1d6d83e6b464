#!/bin/sh
# tests/regen.sh BUILD - regenerates the golden files of tests/golden/
# (make regen).  Run it only after a deliberate change of output, look at
# "git diff --stat tests/golden" and commit the new files with the change.
set -eu
BUILD=${1:-build}
TOP=$(cd "$(dirname "$0")/.." && pwd)
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
PATH=$BUILD/bin:$PATH
export PATH TOP BUILD LC_ALL=C POSTSCRIPT=ON
unset DISPLAY
. "$TOP/tests/golden/cases.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/s3dregen.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
for c in $GOLDEN_CASES; do
	mkdir "$work/$c"
	(cd "$work/$c" && golden_case "$c")
	mkdir -p "$TOP/tests/golden/$c"
	for f in $GOLDEN_FILES; do
		cp "$work/$c/$f" "$TOP/tests/golden/$c/$f"
	done
	echo "regenerated tests/golden/$c"
done
# the plot programs' own golden PostScript and SVG (tests/<prog>/golden/):
# their tests rewrite the files when REGEN=1
REGEN=1 TESTS=007-golden sh "$TOP/tests/run.sh" "$BUILD" | tail -n 1
