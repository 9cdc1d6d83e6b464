# A mistyped option costs two lines on stderr and exit 2, in every C
# program (src/lib/system/args.c) and every driver (usage_error in
# scripts/etchopts.sh): "prog: unknown option -X; did you mean -Y?" when
# one known option is a slip of the keyboard away (checked against
# hand-made near misses: a dropped, doubled, swapped or changed letter),
# the bare "unknown option -X" when none is near (-zzzz), then
# "prog: prog --help prints the usage".  A misspelled option's value is
# not reported again as an operand too many (measure, splat), and a
# program run with no argument at all prints its usage.
. "$TOP/tests/lib/common.sh"
built splat bleach etch etch2d measure pdraw contour conv drawplot drawmask plotdiff femwin \
	sample3D sample2D fem
# two PROG WORD NEAR ARGS...: PROG ARGS gives exactly the two lines
two() {
	_p=$1 _w=$2 _n=$3
	shift 3
	"$_p" "$@" </dev/null >/dev/null 2>err.txt
	st=$?
	[ $st -eq 2 ] || fail "$_p $*: exit $st, expected 2: $(head -c 300 err.txt)"
	[ "$(wc -l <err.txt)" -eq 2 ] || fail "$_p $*: not two lines: $(head -c 600 err.txt)"
	if [ -n "$_n" ]; then
		want="$_p: unknown option $_w; did you mean $_n?"
	else
		want="$_p: unknown option $_w"
	fi
	[ "$(head -n 1 err.txt)" = "$want" ] || fail "$_p $*: \"$(head -n 1 err.txt)\", expected \"$want\""
	[ "$(tail -n 1 err.txt)" = "$_p: $_p --help prints the usage" ] ||
		fail "$_p $*: second line \"$(tail -n 1 err.txt)\""
}
two splat -defocsu -defocus -defocsu 1 mask.in
two splat -zzzz "" -zzzz 1 mask.in
two bleach -cutlin -cutline -cutlin 0 0 1 1 image.cont resist.in
two etch -delop -deloop -et 30 -delop rate.bin
two etch -deloopp -deloop -et 30 -deloopp rate.bin
two etch -mehtod -method -et 30 -mehtod fmm rate.bin
two etch2d -mthod -method -et 30 -mthod ray rate.bin
two measure -hol -hole -rel 50 -hol 0 0 curves.plot
two measure -zzzz "" -rel 50 -zzzz 0 0 curves.plot
two femwin -tagret -target -tagret 1 fem.dat
two pdraw -zzzz "" -zzzz curves.plot
two sample3D -delop -deloop -if mask.in -bf resist.in -et 30 -delop
two sample3D -hiden -hidden -if mask.in -bf resist.in -et 30 -hiden
two fem -delop -deloop -delop
two sample2D -methd -method -methd ray
two sample2D -zzzz "" -zzzz
# no argument at all: the usage itself
splat 2>err.txt >/dev/null
[ $? -eq 2 ] || fail "splat with no argument: expected exit 2"
grep -q '^usage: splat' err.txt || fail "splat with no argument prints no usage: $(head -n 2 err.txt)"
exit 0
