# sample3D -measure -accuracy: the CDs it reports hold the accuracy asked.
# A 1.25 um contact (examples/contact's optics and baked resist) on a
# small 3.2 um cell at a coarse 17 x 17 image grid and nz 60:
#  - -accuracy 6 prints a table with the column err, every err within 6 %
#    of its cd, and every cd within 6 % of a reference refined by hand to
#    4 times the inputs' grids (splat -grid 65 65, bleach -nz 237, fast
#    marching); the files left are those of the table (measure on
#    curves.plot gives its cds again), and the tables of the levels are in
#    accuracy/, from level -2 (5 x 5 x 16) on, whose table alone has no err;
#  - -accuracy 1 refines by axis: 65 x 65 x 119 (x-y 4 times the inputs'
#    resolution, z twice), no level past nz 119, every err within 1 % and
#    every cd within 1 % of the reference at 65 x 65 x 237;
#  - -accuracy check keeps the inputs' grid: its cds are byte for byte
#    those of -accuracy off (no estimate), and its err is measure's
#    three-level estimate from the levels below solved here by hand (9 x 9
#    x 31 at the spacing ratio 59/30, the smallest of 16/8 and 59/30, and
#    5 x 5 x 16 at 2 below it; tests/accuracy/001 checks the estimate
#    itself);
#  - with -if and -bf, -measure alone is -accuracy check: the same table
#    byte for byte, and the warning that an err is over 1 % (at this grid
#    the bottom cd moves 0.19 um when the grid is halved);
#  - without an engine option, -measure develops by fast marching: the
#    same curves.plot byte for byte as -method fmm;
#  - -accuracy without -measure, with -cf, or with a bad value (0, 100,
#    1x) is a usage error (status 2) naming the problem, before splat runs;
#    a bare -accuracy (1 %) leaves the next word to be an option.
. "$TOP/tests/lib/common.sh"
cat >mask.in <<'IN'
wavelength 0.436
na 0.28
sigma 0.5
background dark
window -1.6 1.6 -1.6 1.6
rect -0.625 -0.625 0.625 0.625
grid 17 17
contour image.cont
IN
sed 's/^grid nz.*/grid nz 60/' "$TOP/examples/contact/resist.in" >resist.in
M="-rel 10,50,90 -hole 0 0"
P=6

mkdir acc && cd acc
sample3D -q -if ../mask.in -bf ../resist.in -et 60 -last -measure "$M" -accuracy $P >table.txt ||
	fail "sample3D -accuracy $P: $(cat table.txt)"
head -n 1 table.txt | grep -q '^# z cd area dx dy err$' || fail "no err column: $(cat table.txt)"
awk -v p=$P '!/^#/ { n++; if (!($6 <= p / 100 * $2)) { print "err " $6 " over " p " % of cd " $2; bad = 1 } }
	END { exit bad || n != 3 }' table.txt || fail "err over $P %: $(cat table.txt)"
# shellcheck disable=SC2086 # M is a list of words on purpose
measure $M curves.plot | cut -d' ' -f1-5 >again.txt
grep -v '^#' table.txt | cut -d' ' -f1-5 >printed.txt
grep -v '^#' again.txt >again-rows.txt
same printed.txt again-rows.txt
[ "$(ls accuracy/*.dat | wc -l)" -ge 2 ] || fail "accuracy/ holds fewer than two levels: $(ls accuracy)"
head -n 1 accuracy/5x5x16.dat | grep -q err && fail "the coarsest level has an err column"
head -n 1 accuracy/9x9x31.dat | grep -q err || fail "level -1 has no err column"
cd ..

# the reference, 4 times the inputs' grids, by hand
splat -q -grid 65 65 -o ref.cont mask.in || fail "splat reference"
bleach -q -nz 237 -o ref.bin ref.cont resist.in || fail "bleach reference"
etch -q -et 60 -method fmm -last -no2d -o ref.plot ref.bin || fail "etch reference"
# shellcheck disable=SC2086 # M is a list of words on purpose
measure $M -o ref.txt ref.plot || fail "measure reference"
paste -d' ' ref.txt acc/table.txt | awk -v p=$P '!/^#/ { d = $2 - $7; if (d < 0) d = -d
	if (d > p / 100 * $2) { print "cd " $7 " at z " $1 ": reference " $2; bad = 1 } }
	END { exit bad }' || fail "a cd is off the reference by more than $P %"

# -accuracy 1 refines by axis: the x-y error (the edge of the hole, its
# 10 % cd moving 0.19 um from 9 x 9 to 17 x 17) is refined to 65 x 65 while
# z stops at nz 119, half what refining every axis together reaches there
# (237); each err within 1 % of its cd and each cd within 1 % of the
# reference at 65 x 65 x 237 (0.1 % apart: that reference's z is twice
# finer, its x-y the same)
mkdir axes && cd axes
sample3D -q -if ../mask.in -bf ../resist.in -et 60 -last -measure "$M" -accuracy 1 >table.txt ||
	fail "sample3D -accuracy 1: $(cat table.txt)"
same table.txt accuracy/65x65x119.dat
ls accuracy/*.dat | awk -F/ '{ split($NF, g, /[x.]/); if (g[3] > 119) { print $NF; bad = 1 } } END { exit bad }' ||
	fail "-accuracy 1 refined z past nz 119"
awk '!/^#/ { n++; if (!($6 <= 0.01 * $2)) { print "err " $6 " over 1 % of cd " $2; bad = 1 } }
	END { exit bad || n != 3 }' table.txt || fail "err over 1 %: $(cat table.txt)"
paste -d' ' ../ref.txt table.txt | awk '!/^#/ { d = $2 - $7; if (d < 0) d = -d
	if (d > 0.01 * $2) { print "cd " $7 " at z " $1 ": reference " $2; bad = 1 } }
	END { exit bad }' || fail "-accuracy 1: a cd is off the reference by more than 1 %"
cd ..

# -accuracy check: the inputs' grid, err from the two levels below
mkdir chk plain dflt && cd plain
sample3D -q -if ../mask.in -bf ../resist.in -et 60 -last -measure "$M" -accuracy off >table.txt ||
	fail "sample3D -measure -accuracy off"
head -n 1 table.txt | grep -q err && fail "-accuracy off: an err column"
cd ../chk
sample3D -q -if ../mask.in -bf ../resist.in -et 60 -last -measure "$M" -accuracy check >table.txt \
	2>err.txt || fail "sample3D -accuracy check"
cut -d' ' -f1-5 table.txt | grep -v '^#' >cds.txt
grep -v '^#' ../plain/table.txt >plain.txt
same cds.txt plain.txt
cd ../dflt
sample3D -q -if ../mask.in -bf ../resist.in -et 60 -last -measure "$M" >table.txt 2>err.txt ||
	fail "sample3D -measure (the default estimate)"
same table.txt ../chk/table.txt
grep -q '^sample3D: warning: .*over 1 %' err.txt || fail "no warning at 6 % err: $(cat err.txt)"
cd ..
for g in "9 31" "5 16"; do
	set -- $g
	splat -q -grid $1 $1 -o low$1.cont mask.in && bleach -q -nz $2 -o low$1.bin low$1.cont resist.in &&
		etch -q -et 60 -method fmm -last -no2d -o low$1.plot low$1.bin || fail "level $1 x $1 x $2 by hand"
	# shellcheck disable=SC2086 # M is a list of words on purpose
	measure $M -o low$1.txt low$1.plot
done
# shellcheck disable=SC2086 # M is a list of words on purpose
measure $M -accuracy check -coarse low9.txt -ratio "$(awk 'BEGIN { printf "%.10g", 59 / 30 }')" \
	-coarser low5.txt -ratio2 2 -o want.txt chk/curves.plot 2>/dev/null || fail "measure the estimate by hand"
same want.txt chk/table.txt

# the default engine with -measure is fast marching
mkdir fmm && cd fmm
sample3D -q -if ../mask.in -bf ../resist.in -et 60 -last -method fmm -measure "$M" >/dev/null ||
	fail "sample3D -method fmm"
same curves.plot ../plain/curves.plot
cd ..

# usage errors, before any stage runs
for acc in "" 0 100 1x 1 check; do
	mkdir u && cd u
	st=0
	if [ "$acc" = 1 ] || [ "$acc" = check ]; then
		# a good value without -measure
		sample3D -q -if ../mask.in -bf ../resist.in -et 60 -accuracy $acc >/dev/null 2>err.txt || st=$?
	else
		sample3D -q -if ../mask.in -bf ../resist.in -et 60 -measure "$M" -accuracy $acc \
			-x >/dev/null 2>err.txt || st=$?
	fi
	[ $st -eq 2 ] || fail "sample3D -accuracy '$acc': exit $st, expected 2"
	case $acc in 1|check) grep -q "needs -measure" err.txt ;; "") grep -q "unknown option -x" err.txt ;;
	*) grep -q "expected a percentage" err.txt ;; esac || fail "-accuracy '$acc': $(head -n 1 err.txt)"
	[ ! -e image.cont ] || fail "sample3D $args: splat ran"
	cd .. && rm -rf u
done
splat -q mask.in
st=0
sample3D -q -cf image.cont -bf resist.in -et 60 -measure "$M" -accuracy 2 >/dev/null 2>&1 || st=$?
[ $st -eq 2 ] || fail "-accuracy with -cf: exit $st, expected 2"
exit 0
