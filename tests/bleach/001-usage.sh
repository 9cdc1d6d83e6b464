# bleach's command line: -h/--help prints the usage and exits 0; a bad
# option, a missing input, a third input or an -m level outside [0, 1]
# each print the problem and the usage on stderr and exit 2, having
# written nothing.  Checked against the exit statuses of bleach.1.
. "$TOP/tests/lib/common.sh"
bleach -h >out.txt 2>err.txt || fail "-h exits non-zero"
grep -q '^usage: bleach' out.txt || fail "-h prints no usage"
bleach --help >out.txt || fail "--help exits non-zero"
grep -q -- '-solid' out.txt || fail "--help does not list -solid"
printf '0 1 0 1\n2 2\n1 1 1 1\n' >clear.cont
cp "$TOP/examples/resists/olinhunt6512.in" in.txt
usage_error() {
	bleach "$@" >out.txt 2>err.txt </dev/null
	st=$?
	[ $st -eq 2 ] || fail "bleach $*: exit $st, expected 2"
	grep -q '^usage: bleach' err.txt || fail "bleach $*: no usage on stderr"
	[ ! -e rval.3D.binary ] && [ ! -e rval.3D ] || fail "bleach $*: wrote output"
}
usage_error -bogus clear.cont in.txt
usage_error clear.cont
usage_error
usage_error clear.cont in.txt extra
usage_error -m 1.5 clear.cont in.txt
usage_error -m clear.cont in.txt
usage_error -o
# every bad option is reported, not only the first
bleach -x -y clear.cont in.txt 2>err.txt
grep -q -- '-x' err.txt && grep -q -- '-y' err.txt || fail "not every bad option reported: $(cat err.txt)"
exit 0
