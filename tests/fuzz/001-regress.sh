# Every input in tests/fuzz/regress/ (the fuzzers' and the hand-made
# findings) through the real programs: the exit status and the
# one-line message of tests/fuzz/regress/EXPECT, no crash, no sanitizer
# report (exit 98/99, or a signal), within the time and memory limits, and
# no temporary left behind.
. "$TOP/tests/lib/common.sh"
R=$TOP/tests/fuzz/regress
S=$TOP/tests/fuzz/corpus
# 20 s each (the 258-byte AREF of a million squares 10 s: it is refused
# within 0.3 s of one core), which leaves room for a machine loaded ten
# times over (none takes more than about 0.6 s of one core), and, outside the
# sanitizers (whose shadow memory needs terabytes of address space),
# 1.5 GB of address space as a stand-in for the 1 GB a reader may use on
# bad input
limit=20 mem="ulimit -v 1500000;"
case $BUILD in *asan*) limit=60 mem= ;; esac
n=0
grep -v '^#' "$R/EXPECT" | grep -v '^[[:space:]]*$' >list.txt
while IFS='|' read -r file st msg cmd check; do
	file=$(echo $file) st=$(echo $st) msg=$(echo "$msg" | sed 's/^ *//; s/ *$//')
	F=$R/$file
	[ -f "$F" ] || fail "$file: listed in EXPECT but missing"
	n=$((n + 1))
	rm -rf run && mkdir run
	lim=$limit
	case $file in gds-aref-1000x1000-*) [ -z "$mem" ] || lim=10 ;; esac
	(cd run && eval "$mem timeout $lim $cmd" </dev/null >out.txt 2>err.txt)
	got=$?
	[ $got -ne 124 ] || fail "$file: $cmd did not finish within $lim s"
	[ $got -eq "$st" ] || fail "$file: $cmd: exit $got, expected $st: $(head -c 400 run/err.txt)"
	if [ "$msg" = - ]; then
		[ "$st" -ne 0 ] || [ ! -s run/err.txt ] || fail "$file: unexpected messages: $(head -c 400 run/err.txt)"
	else
		# one line, or with -big the estimate's note and then one line
		lines=$(wc -l <run/err.txt)
		case $cmd in *-big*) max=2 ;; *) max=1 ;; esac
		[ "$lines" -ge 1 ] && [ "$lines" -le $max ] ||
			fail "$file: expected one line on stderr: $(head -c 600 run/err.txt)"
		tail -n 1 run/err.txt | grep -Eq -- "$msg" ||
			fail "$file: message does not match /$msg/: $(cat run/err.txt)"
	fi
	if [ -n "$check" ]; then
		(cd run && eval "$check") || fail "$file: check failed: $check"
	fi
	ls run | grep -q 'tmp' && fail "$file: temporaries left: $(ls run)"
done <list.txt
# every file in regress/ is listed
for f in "$R"/*; do
	b=$(basename "$f")
	[ "$b" = EXPECT ] && continue
	grep -q "^$b " "$R/EXPECT" || fail "$b is in tests/fuzz/regress/ but not in EXPECT"
done
echo "$n reproducers checked"
exit 0
