# fem's ranges and its cap on points: a step below the values' resolution
# (-1:1:1e-17 never advances; -1:1:1e-11 prints -1 twice at %.10g) is
# refused in one line, -big or not; more than 10000 points is refused with
# the count, without -big; with -big (or SAMPLE3D_BIG=1) 10100 points are
# written, as many measure.dat targets as points.  Each within 10 s (a
# fork per point took minutes for 10^4).  Against: the counts by hand.
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact
cp "$E/mask.in" mask.in
cp "$E/resist.in" resist.in
ok="-if mask.in -bf resist.in -et 10 -measure"
m="-rel 50 -hole 0 0"

refused() { # refused WHAT ARGS...: one line naming WHAT, exit 2, within 10 s
	what=$1
	shift
	timeout 10 fem "$@" -d out >/dev/null 2>err.txt
	st=$?
	[ $st -eq 2 ] || fail "$*: exit $st, expected 2: $(head -c 300 err.txt)"
	[ "$(wc -l <err.txt)" -eq 1 ] || fail "$*: expected one line: $(head -c 300 err.txt)"
	grep -q -- "$what" err.txt || fail "$*: expected '$what': $(cat err.txt)"
	[ ! -e out ] || fail "$*: the sweep directory was made"
}
refused "2e+17 points, more than 10000" $ok "$m" -dose 60 -focus -1:1:1e-17
refused "below the resolution" -big $ok "$m" -dose 60 -focus -1:1:1e-17
refused "below the resolution of the values (-1 twice)" -big $ok "$m" -dose 60 -focus -1:1:1e-11
refused "10001 points, more than 10000" $ok "$m" -dose 1:10001:1 -focus 0
refused "10100 points (101 foci x 100 doses), more than 10000" $ok "$m" -dose 1:100:1 -focus 0:1:0.01
refused "-focus: a list on one line expected" $ok "$m" -dose 60 -focus "0,1
2"

timeout 10 fem -q -n -big $ok "$m" -dose 1:100:1 -focus 0:1:0.01 -d big >/dev/null 2>err.txt ||
	fail "-big: $(cat err.txt)"
n=$(sed -n 's/^all://p' big/Makefile | wc -w)
[ "$n" -eq 10100 ] || fail "-big: $n points in the Makefile, expected 10100"
SAMPLE3D_BIG=1 timeout 10 fem -q -n $ok "$m" -dose 1:100:1 -focus 0:1:0.01 -d big2 >/dev/null 2>err.txt ||
	fail "SAMPLE3D_BIG=1: $(cat err.txt)"
sed -n 's/^all://p' big2/Makefile >all2.txt
sed -n 's/^all://p' big/Makefile >all1.txt
same all1.txt all2.txt
exit 0
