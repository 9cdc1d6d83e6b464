# sample2D reads the mask where the user keeps it: with examples/layout's
# mask.in (a relative "gds sram.gds" statement) run from another folder,
# the run succeeds and cut.2D is the cutline splat writes when it reads
# the same mask through sample3D's way (splat on mask.in in place, with a
# cutline statement of its own: byte-identical); a mistake in the mask is
# reported by splat against the user's file and line, then the driver's
# "splat failed; stopping" (two lines), exit 1; and a run
# beside a sample3D run's files leaves their dataplot.ps and image.cont
# untouched (sample2D draws profile2D.ps, splat's image goes to
# cutline.cont).
. "$TOP/tests/lib/common.sh"
built sample2D splat
E=$TOP/examples/layout
echo keep >dataplot.ps
echo keep >image.cont
sample2D -q -if "$E/mask.in" -cut -1 1.6 9 1.6 -npts 101 -bf "$E/resist.in" -et 5 >out.txt 2>&1 ||
	fail "sample2D on the layout example: $(tail -n 3 out.txt)"
for f in cut.2D rval.2D.binary profile.plot profile2D.ps cutline.cont; do
	[ -s $f ] || fail "no $f"
done
[ "$(cat dataplot.ps)" = keep ] || fail "sample2D overwrote dataplot.ps"
[ "$(cat image.cont)" = keep ] || fail "sample2D overwrote image.cont"
[ ! -e across.2D ] || fail "the input's own cutline was written too"
# the same cutline by splat on the mask as written (its own cutline there)
mkdir ref && cp "$E/mask.in" "$E/sram.gds" ref/
sed 's/^cutline .*/cutline -1 1.6 9 1.6 101 ref.2D/' "$E/mask.in" >ref/mask.in
(cd ref && splat -q mask.in) || fail "splat on the copied mask failed"
same ref/ref.2D cut.2D
# a bad statement: named in the user's file
mkdir bad && cp "$E/sram.gds" bad/
sed 's/^grid 61 73/grid 61/' "$E/mask.in" >bad/mask.in
sample2D -q -if bad/mask.in -cut 0 0 1 1 -bf "$E/resist.in" -et 5 >/dev/null 2>err.txt
[ $? -eq 1 ] || fail "a bad mask: expected exit 1"
[ "$(wc -l <err.txt)" -eq 2 ] || fail "a bad mask: not two lines: $(cat err.txt)"
head -n 1 err.txt | grep -q '^splat: bad/mask.in:11: ' || fail "a bad mask: $(head -n 1 err.txt)"
exit 0
