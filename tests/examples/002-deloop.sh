# Every thesis example also runs with -deloop (passed by its run.sh through
# sample3D to etch) and every etch run ends with a loop-free mesh: its
# summary reports "0 crossings left" (etch(1): crossings of a segment
# through a triangle it does not touch, found by the deloop pass's own
# spatial index after the last pass).  The summary's count is that of the
# last print time's deloop, so the examples run with -last too: the sets
# before it are neither delooped nor drawn, and the final set is the same
# bytes.  Examples that develop by fast marching (-method fmm in their
# run.sh) have no mesh and are passed over; one whose run.sh passes
# -deloop itself (examples/contact-highna) is checked on its README run by
# 001-all.sh.
# The checks are tests/lib/examples.sh's; the longest examples (its
# EXAMPLES_OWN) are tests of their own, 006 and 007, so that the runner
# spreads them over the cores; this test takes every other 3D example.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/examples.sh"
for name in $(examples_rest); do
	example_deloop "$name"
done
exit 0
