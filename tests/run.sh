#!/bin/sh
# tests/run.sh BUILD - runs every test, several at a time, and prints
# "N passed, N failed".
#
# A test is either a shell script tests/<area>/NNN-name.sh or a C program
# built from tests/<area>/<name>.c into BUILD/tests/<area>/<name>.  Each
# runs in a fresh empty directory (its cwd) with the freshly built programs
# first on PATH, so an installed copy is never what gets tested.  Exit 0
# is a pass, 77 a skip (a tool such as ghostscript is missing), anything
# else a failure; a failing test's output is shown.
#
# Tests run TEST_JOBS at a time (default: the number of cores), the
# slowest of the previous run first (their wall times are kept in
# BUILD/test-times).  Each test's CPU time (user + system of everything it
# ran) goes to BUILD/test-cpu and each area's line shows its wall and CPU
# seconds, so that the cost of a test can be measured on a busy machine,
# where the wall time says more about the others' load.  An area (tests/<area>/) is reported as soon as all
# its tests are done: its tests' results in name order, then a line with
# its counts; the areas come in the order they finish, the closing line
# "N passed, N failed" last.
#
# Environment: TESTS="pattern ..." runs only the tests whose name contains
# one of the patterns (words: TESTS="etch fmm");
# TEST_TIMEOUT (seconds, default 600) bounds each test; TEST_JOBS sets the
# number of tests run at once.
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
jobs=${TEST_JOBS:-$(nproc 2>/dev/null || echo 2)}
case $jobs in ''|*[!0-9]*|0) echo "run.sh: TEST_JOBS must be a positive integer" >&2; exit 2 ;; esac
work=$(mktemp -d "${TMPDIR:-/tmp}/s3dtest.XXXXXX")
pool=""
cleanup() {
	[ -n "$pool" ] && kill "$pool" 2>/dev/null
	rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

list=$( (cd "$TOP" && ls tests/*/*.sh 2>/dev/null | grep -v '^tests/\(lib\|bench\|fuzz/corpus\)/';
         cd "$BUILD" && ls tests/*/* 2>/dev/null | grep -v '^tests/\(lib\|bench\)/') | sort)
sel=""
for t in $list; do
	name=${t#tests/}
	case $name in *.sh) ;; *) [ -x "$BUILD/$t" ] || continue ;; esac
	if [ -n "${TESTS:-}" ]; then
		hit=""
		for pat in $TESTS; do
			case $name in *"$pat"*) hit=yes ;; esac
		done
		[ -n "$hit" ] || continue
	fi
	sel="$sel $name"
done
ntests=$(echo $sel | wc -w)

# the previous run's times (seconds) order the start, slowest first
times=$BUILD/test-times
# a fresh build starts from the times kept in the tree (tests/test-times,
# refreshed now and then from a build's), so the long tests start first
[ -f "$times" ] || cp "$TOP/tests/test-times" "$times" 2>/dev/null ||
	: >"$times" 2>/dev/null || times=/dev/null
order=$(for name in $sel; do
	s=$(awk -v n="$name" '$2 == n { s = $1 } END { print s + 0 }' "$times")
	echo "$s $name"
done | sort -k1,1nr -k2 | awk '{ print $2 }')
est=$(for name in $sel; do echo "$name"; done |
	awk -v j="$jobs" 'NR == FNR { t[$2] = $1; next } { s += t[$1] }
		END { printf "%d", s / j + 0.5 }' "$times" -)
if [ "$est" -gt 0 ]; then
	echo "$ntests tests, $jobs at a time; the last run suggests about $est s"
else
	echo "$ntests tests, $jobs at a time"
fi

# one test: its log and, last, its status file (the printer waits for it)
cat >"$work/one.sh" <<'ONE'
work=$1 timeout_s=$2 name=$3
id=$(echo "$name" | tr '/.' '__')
dir=$work/$id
mkdir -p "$dir"
case $name in
*.sh) set -- sh "$TOP/tests/$name" ;;
*) set -- "$BUILD/tests/$name" ;;
esac
t0=$(date +%s)
(cd "$dir" && exec timeout "$timeout_s" "$@") >"$dir.log" 2>&1 </dev/null
st=$?
# the CPU seconds of the children (user + system): the second line of
# times, "XmY.YYs XmY.YYs"; this shell ran only the one test.  (Into a
# file: in a pipe or $(...) times would run in a new process, which has
# no children yet.)
times >"$dir.times"
cpu=$(awk 'NR == 2 { split($1, u, /[ms]/); split($2, s, /[ms]/)
	printf "%.1f", u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$dir.times")
echo "$st $(( $(date +%s) - t0 )) ${cpu:-0}" >"$dir.st.tmp" && mv "$dir.st.tmp" "$dir.st"
rm -rf "$dir"
ONE
( for name in $order; do echo "$name"; done |
	xargs -P "$jobs" -n 1 sh "$work/one.sh" "$work" "$timeout_s"
) >/dev/null 2>&1 &
pool=$!

pass=0 fail=0 skip=0 failed=""
newtimes=$work/times
newcpu=$work/cpu
# the areas, in name order, each with its tests
areas=$(for name in $sel; do echo "${name%%/*}"; done | uniq)
area_tests() { for name in $sel; do case $name in "$1"/*) echo "$name" ;; esac; done; }
# each area's number of tests, " area=N" words (no process a lookup: the
# loop below asks every 0.3 s for every area left)
counts=""
for a in $areas; do
	case $a in *_*) echo "run.sh: tests/$a: an area's name has no _" >&2; exit 2 ;; esac
	n=0
	for name in $sel; do case $name in "$a"/*) n=$((n + 1)) ;; esac; done
	counts="$counts $a=$n"
done
# true when every test of the area has finished: as many status files
# "AREA_*.st" (a test's id is its name with / and . made _, and an area is
# a folder name without _) as the area has tests, counted by a glob
area_done() {
	_want=0
	for _c in $counts; do case $_c in "$1="*) _want=${_c#*=} ;; esac; done
	set -- "$work/$1"_*.st
	[ -e "$1" ] || return 1
	[ $# -ge "$_want" ]
}
# prints an area's results, its tests in name order, then its line
report_area() {
	apass=0 afail=0 askip=0 atime=0 acpu=0
	for name in $(area_tests "$1"); do
		id=$(echo "$name" | tr '/.' '__')
		if [ -f "$work/$id.st" ]; then
			read st secs cpu <"$work/$id.st"
		else
			st=125 secs=0 cpu=0
			echo "run.sh: the test was never run" >>"$work/$id.log"
		fi
		echo "$secs $name" >>"$newtimes"
		echo "$cpu $name" >>"$newcpu"
		atime=$((atime + secs))
		acpu=$(awk -v a="$acpu" -v b="$cpu" 'BEGIN { printf "%.1f", a + b }')
		if [ "$st" -eq 0 ]; then
			pass=$((pass + 1)) apass=$((apass + 1))
			echo "PASS $name"
		elif [ "$st" -eq 77 ]; then
			skip=$((skip + 1)) askip=$((askip + 1))
			echo "SKIP $name: $(tail -n 1 "$work/$id.log")"
		else
			fail=$((fail + 1)) afail=$((afail + 1))
			failed="$failed $name"
			echo "FAIL $name (exit $st)"
			tail -n 30 "$work/$id.log" | sed 's/^/    /'
		fi
	done
	line="== $1: $apass passed, $afail failed"
	[ $askip -gt 0 ] && line="$line, $askip skipped"
	echo "$line ($atime s, $acpu s CPU)"
}
# an area is reported as soon as all its tests are done, so a long test
# holds back only its own area's lines
left=$areas
while [ -n "$left" ]; do
	rest=""
	alive=1
	kill -0 "$pool" 2>/dev/null || alive=0
	for a in $left; do
		if [ $alive -eq 0 ] || area_done "$a"; then
			report_area "$a"
		else
			rest="$rest $a"
		fi
	done
	left=$rest
	[ -z "$left" ] || sleep 0.3
done
wait "$pool" 2>/dev/null
pool=""
# keep the times of this run (and of tests it did not run) for the next
if [ "$times" != /dev/null ] && [ -f "$newtimes" ]; then
	awk 'NR == FNR { t[$2] = $1; next } !($2 in t) { print } END { for (n in t) print t[n], n }' \
		"$newtimes" "$times" | sort -k2 >"$times.tmp" && mv "$times.tmp" "$times"
fi
# this run's CPU seconds, those of the tests it did not run kept
cputimes=$BUILD/test-cpu
if [ -f "$newcpu" ] && { [ -f "$cputimes" ] || : >"$cputimes"; } 2>/dev/null; then
	awk 'NR == FNR { t[$2] = $1; next } !($2 in t) { print } END { for (n in t) print t[n], n }' \
		"$newcpu" "$cputimes" | sort -k2 >"$cputimes.tmp" && mv "$cputimes.tmp" "$cputimes"
	total=$(awk '{ s += $1 } END { printf "%.0f", s }' "$newcpu")
	echo "CPU time of the tests run: $total s"
fi
[ -n "$failed" ] && echo "failed:$failed"
if [ $skip -gt 0 ]; then
	echo "$pass passed, $fail failed, $skip skipped"
else
	echo "$pass passed, $fail failed"
fi
[ $fail -eq 0 ]
