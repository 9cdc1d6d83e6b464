# calibfit's handling of the resist file's numbered statements and of the
# measured-CD table, against hand-edited files:
#  - the K-th number of a statement counts numbers only, words skipped
#    (develop mack 0.1 0.0001 0.5 8: K 1 = 0.1, K 3 = 0.5; resist thickness
#    1 index 1.68 dill 0.55 0.06 0.012: K 5 = C = 0.012), exact strings;
#  - -write changes only those numbers: the output equals the input with
#    the two numbers replaced by sed, byte for byte (comments, spacing and
#    every other number kept);
#  - the probe points move one value by 1 % (backwards at the upper bound);
#  - refusals, one line each: a statement absent, too few numbers, a
#    repeated statement (layer), a start value outside LO:HI (exit 2), a
#    malformed -free (exit 2), measured tables with a bad row or a repeated
#    point; fem -points with -dose or a malformed point (exit 2); and
#    calib's own usage errors exit 2 before anything runs.
. "$TOP/tests/lib/common.sh"
cat >r.in <<'IN'
# a resist   with odd spacing
wavelength 0.365
resist thickness 1 index 1.68 dill 0.55 0.06 0.012   # Dill A B C
substrate 6.41 2.62
layer 0.1 1.5 0
layer 0.2 1.6 0
dose 80
develop mack 0.1 0.0001 0.5 8
grid nz 41
IN
F1="develop 3 0.3:0.7" F2="resist 5 0.005:0.03"
[ "$(calibfit -bf r.in -free "develop 1 0:1" -start)" = 0.1 ] || fail "develop K 1 is not 0.1"
[ "$(calibfit -bf r.in -free "$F1" -free "$F2" -start)" = "0.5,0.012" ] ||
	fail "develop K 3, resist K 5: expected 0.5,0.012, got $(calibfit -bf r.in -free "$F1" -free "$F2" -start)"
calibfit -bf r.in -free "$F1" -free "$F2" -write 0.4375,0.0123456789 -o w.in || fail "-write failed"
sed 's/dill 0.55 0.06 0.012 /dill 0.55 0.06 0.0123456789 /; s/mack 0.1 0.0001 0.5 8/mack 0.1 0.0001 0.4375 8/' r.in >want.in
same w.in want.in
[ "$(calibfit -bf w.in -free "$F1" -free "$F2" -start)" = "0.4375,0.0123456789" ] || fail "values do not read back"
calibfit -bf r.in -free "$F1" -free "resist 5 0.005:0.012" -probes 0.5,0.012 >probes.txt
printf '0.505,0.012\n0.5,0.01188\n' >want.txt
same probes.txt want.txt

expect_error calibfit -bf r.in -free "bake 1 0:1" -start
grep -q "no bake statement" err.txt || fail "absent statement: $(cat err.txt)"
expect_file_error calibfit r.in -bf r.in -free "develop 6 0:1" -start
grep -q "has 4 numbers, not 6" err.txt || fail "too few numbers: $(cat err.txt)"
expect_file_error calibfit r.in -bf r.in -free "layer 1 0:1" -start
expect_file_error calibfit r.in -bf r.in -free "develop 3 0.6:0.7" -start
[ "$(calibfit -bf r.in -free "develop 3 0.6:0.7" -start 2>/dev/null; echo $?)" = 2 ] ||
	fail "a start value outside its range: expected exit 2"
# usage errors: exit 2, the first line names the problem, then the usage
usage_error() { # usage_error PROG ARGS...
	"$@" >/dev/null 2>err.txt </dev/null
	st=$?
	[ $st -eq 2 ] || fail "$*: expected exit 2, got $st"
	head -n 1 err.txt | grep -q "^$1: " || fail "$*: message does not start '$1: ': $(head -n 1 err.txt)"
}
for spec in "develop 3" "develop 0 0:1" "develop 3 1:0" "develop x 0:1" "develop 3 0:1 extra"; do
	usage_error calibfit -bf r.in -free "$spec" -start
	grep -q "expected \"STATEMENT K LO:HI\"" err.txt || fail "-free \"$spec\": $(head -n 1 err.txt)"
done
usage_error calibfit -bf r.in -free "$F1" -free "develop 3 0.4:0.6" -start
grep -q "already free" err.txt || fail "the same number freed twice: $(head -n 1 err.txt)"
# a value that bleach refuses (Mth must be below 1) is not written
expect_error calibfit -bf r.in -free "develop 3 0:2" -write 1.5 -o bad.in
[ ! -e bad.in ] || fail "a refused resist file was written"

printf '# focus dose cd\n0 80 0.5\n-0.3 80 0.45 extra fields\n\n' >m.dat
[ "$(calibfit -points -data m.dat)" = "-0.3:80,0:80" ] || fail "-points: $(calibfit -points -data m.dat)"
printf '0 80 0.5\n0 80.0 0.6\n' >dup.dat
expect_error calibfit -points -data dup.dat
grep -q "given twice" err.txt || fail "repeated point: $(cat err.txt)"
printf '0 80\n' >short.dat
expect_file_error calibfit short.dat -points -data short.dat
printf '0 -80 0.5\n' >neg.dat
expect_file_error calibfit neg.dat -points -data neg.dat
printf '0 80 nan\n' >nan.dat
expect_file_error calibfit nan.dat -points -data nan.dat

# fem -points: refused with -dose or -focus, or with a point that is not
# focus:dose (exit 2, nothing made)
cp "$TOP/examples/contact/resist.in" c.in
cp "$TOP/examples/contact/mask.in" mask.in
for pts in "0:80 -dose 80" "0,80" "0:x" "0:80:90"; do
	# shellcheck disable=SC2086
	usage_error fem -if mask.in -bf c.in -et 60 -measure "-rel 5 -hole 0 0" -points $pts -d fout
	[ ! -e fout ] || fail "fem -points $pts: made its directory"
done
# calib: usage errors exit 2, one line, before anything runs
ok="-if mask.in -bf r.in -et 60 -data m.dat -measure"
for args in "$ok -rel,5" "-if mask.in -bf r.in -et 60 -data m.dat -measure -rel -free x" \
	"$ok x -free" "$ok x -free a -zz"; do
	# shellcheck disable=SC2086
	usage_error calib $args -d out
	[ ! -e out ] || fail "calib $args: made its directory"
done
expect_error calib $ok "-rel 5 -hole 0 0" -free "develop 3 0.6:0.7" -d out
[ ! -e out/runs ] || ! ls out/runs/* >/dev/null 2>&1 || fail "a refused fit ran simulations"
exit 0
