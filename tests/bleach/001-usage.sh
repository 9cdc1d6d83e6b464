# bleach's command line: -h/--help prints the usage and exits 0; a bad
# option, a missing input, a third input or an -m level outside [0, 1]
# each print the problem and a line naming --help on stderr (bleach alone
# prints the usage itself) and exit 2, having
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
	if [ $# -eq 0 ]; then
		grep -q '^usage: bleach' err.txt || fail "bleach alone: no usage on stderr"
	else
		grep -qx 'bleach: bleach --help prints the usage' err.txt || fail "bleach $*: no pointer to the usage"
	fi
	[ ! -e rval.3D.binary ] && [ ! -e rval.3D ] || fail "bleach $*: wrote output"
}
usage_error -bogus clear.cont in.txt
usage_error clear.cont
usage_error
usage_error clear.cont in.txt extra
usage_error -m 1.5 clear.cont in.txt
usage_error -m clear.cont in.txt
usage_error -o
# only the first bad option is reported (two lines in all): later ones
# are often the echo of the first
bleach -x -y clear.cont in.txt 2>err.txt
grep -q -- 'unknown option -x' err.txt || fail "the first bad option is not reported: $(cat err.txt)"
[ "$(wc -l <err.txt)" -eq 2 ] || fail "not two lines: $(cat err.txt)"
exit 0
