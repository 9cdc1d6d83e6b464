#!/bin/sh
# etch: the command line.  Checks: -h prints usage and exits 0; every
# option of the usage text is documented in man/man1/etch.1; bad options,
# missing -et, a missing or malformed rate file and points outside the
# box each give a one-line error with the documented status (2 for usage,
# 1 for run-time) and no output file; -cut writes curves.cut with one set
# per print time; -deloop is accepted.
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
etch -h >usage.txt || fail "-h failed"
grep -q "^usage: etch" usage.txt || fail "-h does not print usage"
for opt in $(grep -o -- ' -[a-z][a-z0-9]*' usage.txt | sort -u); do
	grep -qF -- "\\$opt" "$TOP/man/man1/etch.1" ||
		fail "option $opt not in man/man1/etch.1"
done
$MKRATE -o rate.bin 5 5 5 -1 1 -1 1 -1 0 1 || fail "mkrate"
# run-time errors: status 1, exactly one line "etch: ..."
runtime_error() {
	"$@" </dev/null >/dev/null 2>err.txt
	st=$?
	[ $st -eq 1 ] || fail "$*: status $st, expected 1: $(head -c 300 err.txt)"
	[ "$(wc -l <err.txt)" -eq 1 ] || fail "$*: not one line: $(head -c 300 err.txt)"
	grep -q "^etch: " err.txt || fail "$*: message not 'etch: ...'"
}
# usage errors: status 2, the problem on the first line, then one line
# saying where the usage is (two lines in all)
usage_error() {
	"$@" </dev/null >/dev/null 2>err.txt
	st=$?
	[ $st -eq 2 ] || fail "$*: status $st, expected 2: $(head -c 300 err.txt)"
	[ "$(wc -l <err.txt)" -eq 2 ] || fail "$*: not two lines: $(head -c 300 err.txt)"
	head -n 1 err.txt | grep -q "^etch: " || fail "$*: first line not 'etch: ...'"
	grep -qx "etch: etch --help prints the usage" err.txt || fail "$*: no pointer to the usage"
}
usage_error etch rate.bin
usage_error etch -et 1 -bogus rate.bin
usage_error etch -et -1 rate.bin
usage_error etch -et 1 -cut z 0 rate.bin
usage_error etch -et 1 -method foo rate.bin
usage_error etch -et 1 -seed 0 0 rate.bin
usage_error etch -et 1 -seed 0 0 5 rate.bin
usage_error etch -et 1 -cut x 7 rate.bin
usage_error etch -et 1 -smin 0.7 rate.bin
runtime_error etch -et 1 missing.bin
printf 'garbage\n' >bad.bin
runtime_error etch -et 1 bad.bin
head -c 100 rate.bin >short.bin
runtime_error etch -et 1 short.bin
[ ! -e curves.plot ] || fail "an error left curves.plot behind"
etch -et 0.5 -pt 0.25 -cut x 0 -deloop -q rate.bin || fail "-cut run failed"
n=$(awk 'NF == 4' curves.cut | wc -l)
[ "$n" -eq 2 ] || fail "curves.cut has $n sets, expected 2"
# the cut of a flat front at depth 0.25 then 0.5: every point at that z
awk 'NF == 4 { s++ } NF == 2 { w = -0.25 * s; d = $2 - w; if (d < 0) d = -d;
	if (d > 1e-9) { print "z " $2 " not " w; exit 1 } }' curves.cut || fail "cut profile wrong"
exit 0
