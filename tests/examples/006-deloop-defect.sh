# examples/defect runs with -deloop loop-free, as 002-deloop.sh checks it
# (tests/lib/examples.sh, example_deloop: -deloop -last, the
# final set delooped): one of the longest examples, a
# test of its own so that the runner can run it beside the others.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/examples.sh"
example_deloop defect
exit 0
