#!/bin/sh
# tests/bench/run.sh BUILD - make bench: runs every tests/bench/*.sh and
# prints their figures.  Measures; asserts nothing.
set -u
BUILD=${1:-build}
TOP=$(cd "$(dirname "$0")/../.." && pwd)
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
export BUILD TOP LC_ALL=C
echo "machine: $(nproc) cores, $(uname -m), $(${CC:-cc} --version | head -n 1)"
for b in "$TOP"/tests/bench/*.sh; do
	[ "$(basename "$b")" = run.sh ] && continue
	echo "== $(basename "$b" .sh)"
	sh "$b" "$BUILD" || echo "(bench $(basename "$b") failed)"
done
