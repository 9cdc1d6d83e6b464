# fem -seeds K: K stochastic runs a point, differing only by bleach -seed
# 1..K, on examples/euv-lines' lines (a 33 x 41 x 21 grid), at 30 and 60
# mJ/cm2.  Checked against the seeds' own measure tables, summed here by
# awk: fem.dat's cd is the mean of the seeds that printed, stoch.dat holds
# that mean, 3 sample standard deviations and the failures (a seed whose
# line is absent at the height or whose space did not clear), to 1e-9
# um; the seeds' CDs differ (the noise is there); fem -collect remakes the
# same stoch.dat; -seeds 0 or x, and -seeds on a resist without the
# stochastic statement, are refused before anything runs (exit 2, no
# sweep directory).
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/euv-lines
sed 's/^window .*/window -0.016 0.016 -0.02 0.02/; s/-0.1 -0.008 0.1/-0.02 -0.008 0.02/; s/ -0.1 0.016 0.1/ -0.02 0.016 0.02/' \
	"$E/mask.in" >mask.in
sed 's/^grid .*/grid nx 33 ny 41 nz 21/' "$E/resist.in" >resist.in
m="-force -rel 50 -line 0 0 x"
fem -q -if mask.in -bf resist.in -et 20 -method fmm -measure "$m" -dose 30,60 -focus 0 \
	-seeds 3 -j 2 -d sw >log.txt 2>&1 || fail "fem -seeds 3 fails: $(tail -n 3 log.txt)"
[ -s sw/stoch.dat ] || fail "no stoch.dat"
head -n 1 sw/stoch.dat | grep -q '^# focus dose cd cd_3sigma failures seeds$' ||
	fail "stoch.dat header: $(head -n 1 sw/stoch.dat)"
for d in 30 60; do
	for s in 1 2 3; do
		t=sw/f0/d$d/s$s/measure.dat
		[ -s "$t" ] || fail "no $t"
		awk '/^# cleared/ { c = ($3 == "yes") } !/^#/ && !n { cd = $2; n = 1 } END { print cd, c }' "$t"
	done >seeds$d.txt
	want=$(awk -v d=$d '{ if ($1 > 0 && $2) { s += $1; s2 += $1 * $1; k++ } else f++ }
		END { m = k ? s / k : 0; sd = k > 1 ? sqrt((s2 - k * m * m) / (k - 1)) : 0
		      printf "%.12g %.12g %d\n", m, 3 * sd, f + 0 }' seeds$d.txt)
	got=$(awk -v d=$d '!/^#/ && $2 == d { print $3, $4, $5, $6 }' sw/stoch.dat)
	set -- $want
	wm=$1 w3=$2 wf=$3
	set -- $got
	[ "${4:-}" = 3 ] || fail "dose $d: seeds ${4:-none} in stoch.dat, expected 3"
	[ "$3" = "$wf" ] || fail "dose $d: failures $3, expected $wf"
	close "$1" "$wm" 1e-9 "dose $d mean cd"
	close "$2" "$w3" 1e-9 "dose $d cd 3 sigma"
	fcd=$(awk -v d=$d '!/^#/ && $2 == d { print $3 }' sw/fem.dat)
	close "$fcd" "$wm" 1e-9 "dose $d: fem.dat's cd"
	echo "dose $d: seeds $(tr '\n' ' ' <seeds$d.txt)-> mean $1, 3 sigma $2, failures $3"
done
awk '{ print $1 }' seeds30.txt | sort -u | wc -l | grep -q '^3$' ||
	fail "the three seeds at 30 mJ/cm2 give CDs $(tr '\n' ' ' <seeds30.txt): not all different"
cp sw/stoch.dat stoch1.dat
fem -q -collect -d sw >/dev/null 2>&1 || fail "fem -collect fails"
same sw/stoch.dat stoch1.dat

refused() { # refused WHAT ARGS...: one line, exit 2, no DIR
	what=$1
	shift
	rm -rf out
	fem "$@" -d out </dev/null >/dev/null 2>err.txt
	[ $? -eq 2 ] || fail "$what: expected exit 2"
	[ "$(wc -l <err.txt)" -eq 1 ] || fail "$what: not one line: $(cat err.txt)"
	[ ! -e out ] || fail "$what: the sweep directory was made"
	grep -q "$what" err.txt || fail "expected a message about '$what': $(cat err.txt)"
}
ok="-if mask.in -bf resist.in -et 20 -method fmm -dose 30 -focus 0"
refused "whole number from 1 to 1000" $ok -measure "$m" -seeds 0
refused "whole number from 1 to 1000" $ok -measure "$m" -seeds x
sed '/^stochastic/d' resist.in >plain.in
refused "no stochastic statement" -if mask.in -bf plain.in -et 20 -dose 30 -focus 0 -measure "$m" -seeds 2
exit 0
