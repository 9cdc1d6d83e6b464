# The etch options the drivers pass through are one list (scripts/
# etchopts.sh, sourced by sample3D and fem from beside themselves):
#  - the etch-options lines of "sample3D --help" and "fem --help" are the
#    same text;
#  - every option those lines name is parsed by both drivers (the run then
#    stops later with a usage error, never "unknown option" for it), and
#    an option not in the list is refused as unknown;
#  - fem writes the options to its Makefile as parsed, values included
#    (-deloop's optional count, -etch's words);
#  - a driver copied without etchopts.sh stops with one line and exit 1.
. "$TOP/tests/lib/common.sh"
built sample3D fem
sample3D --help | sed -n '/etch options passed through/,$p' >s3.txt
fem --help | sed -n '/etch options passed through/,$p' >fem.txt
[ -s s3.txt ] || fail "sample3D --help lists no etch options"
same s3.txt fem.txt
opts=$(grep -o -- '-[a-z][a-z0-9]*' s3.txt | sort -u)
[ -n "$opts" ] || fail "no options in the list"
for o in $opts; do
	for d in sample3D fem; do
		# a flag leaves "1" over, itself an unknown option: only $o counts
		$d "$o" 1 >out.txt 2>&1
		[ $? -eq 2 ] || fail "$d $o 1: expected a usage error after parsing"
		! grep -Eq -- "unknown option $o(;|\$)" out.txt || fail "$d does not know $o: $(head -n 1 out.txt)"
	done
done
for d in sample3D fem; do
	$d -nosuchetchoption >out.txt 2>&1
	grep -q 'unknown option -nosuchetchoption' out.txt || fail "$d accepts an option not in the list"
done
E=$TOP/examples/contact
fem -q -n -d sweep -if "$E/mask.in" -bf "$E/resist.in" -et 10 -dose 80 -focus 0 \
	-measure "-rel 10 -hole 0 0" -deloop 3 -method fmm -refine 2 -no2d -etch "-tol 0.01" ||
	fail "fem -n with etch options failed"
grep -qx "ETCHOPTS = '-et' '10' '-deloop' '3' '-method' 'fmm' '-refine' '2' '-no2d' '-tol' '0.01'" sweep/Makefile ||
	fail "fem's ETCHOPTS: $(grep ETCHOPTS sweep/Makefile)"
mkdir alone
cp "$BUILD/bin/sample3D" "$BUILD/bin/fem" alone/
for d in sample3D fem; do
	"alone/$d" --help >/dev/null 2>err.txt
	[ $? -eq 1 ] || fail "$d without etchopts.sh: expected exit 1"
	[ "$(wc -l <err.txt)" -eq 1 ] && grep -q "^$d: cannot find etchopts.sh" err.txt ||
		fail "$d without etchopts.sh: $(cat err.txt)"
done
exit 0
