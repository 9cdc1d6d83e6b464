# The walk through the contact (docs/walkthrough.md) ends with measure's table for the
# developed contact (examples/contact, 60 s, printed every 20 s, delooped,
# as the walk runs it): the table there must be what measure prints, number by
# number within 1e-4 relative (plotdiff), so the page stays true when
# the engines change.
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact
sample3D -q -if "$E/mask.in" -bf "$E/resist.in" -et 60 -pt 20 -deloop >/dev/null 2>err.txt ||
	fail "sample3D: $(cat err.txt)"
measure -rel 10,50,90 -hole 0 0 curves.plot >now.txt || fail "measure"
awk '/^measure -rel 10,50,90 -hole 0 0 curves.plot$/ { on = 1; next } on && /^```/ { exit } on' \
	"$TOP/docs/walkthrough.md" >readme.txt
[ -s readme.txt ] || fail "docs/walkthrough.md has no measure table in its walk"
plotdiff -rtol 1e-4 readme.txt now.txt >diff.txt 2>&1 ||
	fail "docs/walkthrough.md's table is not what measure prints now: $(cat diff.txt); now: $(cat now.txt)"
exit 0
