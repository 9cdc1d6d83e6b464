#!/bin/sh
# tests/run.sh BUILD - runs every test and prints "N passed, N failed".
#
# A test is either a shell script tests/<area>/NNN-name.sh or a C program
# built from tests/<area>/<name>.c into BUILD/tests/<area>/<name>.  Each
# runs in a fresh empty directory (its cwd) with the freshly built programs
# first on PATH, so an installed copy is never what gets tested.  Exit 0
# is a pass, 77 a skip (a tool such as ghostscript is missing), anything
# else a failure; a failing test's output is shown.
#
# Environment: TESTS="pattern" runs only the tests whose name contains it;
# TEST_TIMEOUT (seconds, default 600) bounds each test.
set -u
BUILD=${1:-build}
TOP=$(cd "$(dirname "$0")/.." && pwd)
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
PATH=$BUILD/bin:$PATH
export PATH TOP BUILD
export SRCDIR="$TOP"
export LC_ALL=C
export POSTSCRIPT=ON
unset DISPLAY
# sanitizer runs: fail on any report; leaks are errors too
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:exitcode=99}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1:exitcode=98}"
timeout_s=${TEST_TIMEOUT:-600}
work=$(mktemp -d "${TMPDIR:-/tmp}/s3dtest.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM

pass=0 fail=0 skip=0 failed=""
list=$( (cd "$TOP" && ls tests/*/*.sh 2>/dev/null | grep -v '^tests/\(lib\|bench\)/';
         cd "$BUILD" && ls tests/*/* 2>/dev/null | grep -v '^tests/\(lib\|bench\)/') | sort)
for t in $list; do
	name=${t#tests/}
	case $name in *.sh) ;; *) [ -x "$BUILD/$t" ] || continue ;; esac
	if [ -n "${TESTS:-}" ]; then
		case $name in *"$TESTS"*) ;; *) continue ;; esac
	fi
	dir=$work/$(echo "$name" | tr '/.' '__')
	mkdir -p "$dir"
	case $name in
	*.sh) cmd="sh $TOP/$t" ;;
	*) cmd="$BUILD/$t" ;;
	esac
	(cd "$dir" && timeout "$timeout_s" $cmd) >"$dir.log" 2>&1
	st=$?
	if [ $st -eq 0 ]; then
		pass=$((pass + 1))
		echo "PASS $name"
	elif [ $st -eq 77 ]; then
		skip=$((skip + 1))
		echo "SKIP $name: $(tail -n 1 "$dir.log")"
	else
		fail=$((fail + 1))
		failed="$failed $name"
		echo "FAIL $name (exit $st)"
		tail -n 30 "$dir.log" | sed 's/^/    /'
	fi
done
[ -n "$failed" ] && echo "failed:$failed"
if [ $skip -gt 0 ]; then
	echo "$pass passed, $fail failed, $skip skipped"
else
	echo "$pass passed, $fail failed"
fi
[ $fail -eq 0 ]
