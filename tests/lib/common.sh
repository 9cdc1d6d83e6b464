# tests/lib/common.sh - helpers for shell tests; source it with
#   . "$TOP/tests/lib/common.sh"
# Every helper prints what went wrong and exits 1 on failure.  Helpers'
# own variables start with _ so they never clobber a test's.

fail() { echo "FAIL: $*"; exit 1; }
skip() { echo "skipped: $*"; exit 77; }

# expect_error PROG ARGS...: running "PROG ARGS" must exit non-zero, print exactly
# one line on stderr starting "PROG: ", and not crash (no signal, no
# sanitizer report).
expect_error() {
	_ee_prog=$1
	"$@" </dev/null >/dev/null 2>err.txt
	_ee_st=$?
	[ $_ee_st -ne 0 ] || fail "$* succeeded, expected an error"
	[ $_ee_st -lt 90 ] || fail "$* crashed or was flagged by a sanitizer (exit $_ee_st): $(head -c 600 err.txt)"
	_ee_n=$(wc -l <err.txt)
	[ "$_ee_n" -eq 1 ] || fail "$*: expected one line on stderr, got $_ee_n: $(head -c 600 err.txt)"
	grep -q "^$_ee_prog: " err.txt || fail "$*: message does not start '$_ee_prog: ': $(cat err.txt)"
}

# expect_file_error PROG FILE ARGS...: runs "PROG ARGS" as expect_error, and the message names
# FILE and a line number "FILE:N:".
expect_file_error() {
	_ef_prog=$1 _ef_file=$2
	shift 2
	expect_error "$_ef_prog" "$@"
	grep -q "^$_ef_prog: $_ef_file:[0-9][0-9]*: " err.txt ||
		fail "$_ef_prog $*: message does not name $_ef_file:line: $(cat err.txt)"
}

# same FILE1 FILE2: byte-identical.
same() { cmp -s "$1" "$2" || { diff "$1" "$2" | head -20; fail "$1 and $2 differ"; }; }

# close A B TOL [what]: |A - B| <= TOL.
close() {
	awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }' ||
		fail "${4:-value}: $1 is not within $3 of $2"
}

# need TOOL: skip the test when TOOL, an external tool (ghostscript,
# groff, Xvfb, ...), is not installed.  Never for our own programs: built.
need() { command -v "$1" >/dev/null 2>&1 || skip "$1 is not installed"; }

# built FILE...: each FILE, one of our programs (a name: the build's
# $BUILD/bin/FILE, never another on PATH) or test tools (a path, e.g.
# "$BUILD/tests/lib/mkrate"), must be built; one that is not is a build
# fault, so the test fails (a skip would let it pass unnoticed).
built() {
	for _b_f in "$@"; do
		case $_b_f in */*) ;; *) _b_f=$BUILD/bin/$_b_f ;; esac
		[ -f "$_b_f" ] && [ -x "$_b_f" ] || fail "$_b_f is not built (run make)"
	done
}

# gs_check FILE.ps: ghostscript renders every page without an error.
gs_check() {
	need gs
	gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=nullpage "$1" >gs.out 2>&1 </dev/null ||
		fail "ghostscript failed on $1: $(head -c 600 gs.out)"
	! grep -q "Error" gs.out || fail "ghostscript reported on $1: $(head -c 600 gs.out)"
}

# golden FILE GOLDEN: FILE must be byte-identical to the golden file
# GOLDEN; with REGEN=1 in the environment (make regen) GOLDEN is first
# rewritten from FILE, so review "git diff" before committing it.
golden() {
	[ -z "${REGEN:-}" ] || cp "$1" "$2"
	same "$1" "$2"
}
