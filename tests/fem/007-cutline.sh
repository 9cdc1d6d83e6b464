# The mask's own outputs under a sweep: examples/contact/mask.in has
# "cutline ... cut.2D", which every focus's splat writes.  fem runs each
# focus's splat in its own folder, so each focus keeps its cutline (two foci
# at once under make -j 2 wrote one DIR/cut.2D before, one of them lost).
# Checked: f0/cut.2D and f1/cut.2D exist, are the cutlines of splat
# -defocus 0 and 1 run by hand (byte for byte), differ, and DIR/cut.2D does
# not exist.
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact
cp "$E/mask.in" mask.in
cp "$E/resist.in" resist.in
fem -q -if mask.in -bf resist.in -et 10 -dose 60 -focus 0,1 -measure "-rel 50 -hole 0 0" \
	-j 2 -d sweep 2>err.txt || fail "fem: $(cat err.txt)"
[ ! -e sweep/cut.2D ] || fail "sweep/cut.2D: written by every focus into one file"
for f in 0 1; do
	mkdir -p hand$f
	(cd hand$f && splat -q -defocus $f -o image.cont ../mask.in) || fail "splat -defocus $f"
	[ -s sweep/f$f/cut.2D ] || fail "sweep/f$f/cut.2D missing"
	same sweep/f$f/cut.2D hand$f/cut.2D
done
cmp -s sweep/f0/cut.2D sweep/f1/cut.2D && fail "the two foci's cutlines are the same"
exit 0
