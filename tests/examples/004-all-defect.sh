# examples/defect runs end to end (its README's command as printed) as
# 001-all.sh checks it
# (tests/lib/examples.sh, example_all): one of the longest examples, a
# test of its own so that the runner can run it beside the others.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/examples.sh"
example_all defect
exit 0
