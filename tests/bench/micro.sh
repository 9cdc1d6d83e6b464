#!/bin/sh
# tests/bench/micro.sh [BUILD] - library kernels against the code they
# replaced, in the same run (tests/bench/micro.c).  Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
bin=$BUILD/tests/bench/micro
[ -x "$bin" ] || { echo "micro: $bin not built"; exit 1; }
"$bin"
