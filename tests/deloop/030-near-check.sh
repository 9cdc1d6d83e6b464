# After a deloop pass's first search, the next passes search
# only near what the pass changed (src/etch/deloop.c).  With -check every
# such search is compared with a full search, bit for bit, and etch dies
# on a difference.  Here: the unbaked contact (examples/contact), 60 s,
# delooped at 20, 40, 60 s (5 loops, 9444 triangles removed), run with
# -check: it must succeed, and its output must equal the run without
# -check (the check changes nothing).  A near search that loses one
# crossing makes this run die ("found 8 crossings, the full search 9").
. "$TOP/tests/lib/common.sh"
splat -q "$TOP/examples/contact/mask.in" || fail "splat fails"
bleach -q image.cont "$TOP/examples/contact/resist-nobake.in" || fail "bleach fails"
etch -et 60 -pt 20 -deloop -q -o a.plot rval.3D.binary || fail "etch -deloop fails"
etch -et 60 -pt 20 -deloop -check -o b.plot rval.3D.binary 2>b.err ||
	fail "etch -deloop -check fails: $(tail -n 1 b.err)"
grep -q "^etch: deloop: 3 passes removed [1-9][0-9]* loops" b.err ||
	fail "no loop removed: $(grep deloop: b.err)"
same a.plot b.plot
exit 0
