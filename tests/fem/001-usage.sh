# fem: bad input is refused before anything runs - an empty dose or focus
# range, a zero step, a list out of order, an unreadable input file, -target
# without -tol, measure arguments that measure refuses (tried on the probe
# surface), measure's own -o, a missing program: each gives one line
# "fem: ..." on stderr (a usage error a second one, "fem: fem --help prints
# the usage"), a non-zero exit, and no sweep directory.
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact
cp "$E/mask.in" mask.in
cp "$E/resist.in" resist.in
ok="-if mask.in -bf resist.in -et 10 -measure"
m="-rel 10 -hole 0 0"

fem --help | grep -q '^usage: fem' || fail "--help"
fem -zz >/dev/null 2>&1; [ $? -eq 2 ] || fail "unknown option: expected exit 2"

refused() { # refused WHAT ARGS...: one line, non-zero, no DIR
	what=$1
	shift
	rm -rf out
	fem "$@" -d out </dev/null >/dev/null 2>err.txt
	st=$?
	[ $st -ne 0 ] && [ $st -lt 90 ] || fail "fem $*: exit $st"
	head -n 1 err.txt | grep -q '^fem: ' || fail "fem $*: $(head -n 1 err.txt)"
	case $(wc -l <err.txt) in
	1) ;;
	2) [ "$(tail -n 1 err.txt)" = "fem: fem --help prints the usage" ] ||
		fail "fem $*: second line $(tail -n 1 err.txt)" ;;
	*) fail "fem $*: more than two lines: $(cat err.txt)" ;;
	esac
	[ ! -e out ] || fail "$what: the sweep directory was made"
	grep -q "$what" err.txt || fail "expected a message about '$what': $(cat err.txt)"
}
refused "no dose in that range" $ok "$m" -dose 80:60:10 -focus 0,0.5
refused "no focus in that range" $ok "$m" -dose 60,80 -focus 0.5:0:0.1
refused "step must be positive" $ok "$m" -dose 60:80:0 -focus 0
refused "ascending order" $ok "$m" -dose 80,60 -focus 0
refused "doses must be positive" $ok "$m" -dose -5,60 -focus 0
refused "not a number" $ok "$m" -dose 60,eighty -focus 0
refused "go together" $ok "$m" -dose 60,80 -focus 0 -target 1
refused "drop -o" $ok "$m -o x.dat" -dose 60,80 -focus 0
refused "nosuch.in" -if nosuch.in -bf resist.in -et 10 -measure "$m" -dose 60 -focus 0

# a program missing: fem finds the programs beside itself, then on PATH
SAVED_PATH=$PATH
mkdir bin
cp "$BUILD/bin/fem" "$BUILD/bin/etchopts.sh" bin/
for p in splat bleach etch femwin drawplot; do ln -s "$(command -v $p)" bin/$p; done
PATH=$PWD/bin:/usr/bin:/bin
export PATH
if ! command -v measure >/dev/null 2>&1; then
	refused "cannot find the program measure" $ok "$m" -dose 60 -focus 0
fi
PATH=$BUILD/bin:$SAVED_PATH
# the rest checks measure's arguments through the build's own measure
built measure
printf 'wavelength 0.436\nbogus 1\n' >bad.in
refused "bad.in:2:" -if bad.in -bf resist.in -et 10 -measure "$m" -dose 60 -focus 0
refused "etch refuses" $ok "$m" -dose 60 -focus 0 -seg -1
refused "measure refuses" $ok "-rel 10 -hole 0 0 -nosuchoption" -dose 60 -focus 0
refused "measure refuses" $ok "-rel 10 -hole 99 99" -dose 60 -focus 0
exit 0
