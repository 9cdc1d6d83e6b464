# Every thesis example in examples/ runs end to end through its README's
# command as printed, "sh run.sh" (sample3D: splat, bleach, etch, pdraw),
# and leaves, in every run
# directory, a non-empty curves.plot that reads back as a plot file with
# one set per print time, its curves.plot.2D, and a dataplot.ps that
# ghostscript renders (when installed).  Against: the files each run must
# leave (sample3D(1) FILES), and the print times in the run's own command.
# An example whose run.sh passes -deloop itself (examples/contact-highna)
# must also end every etch run loop-free, as 002-deloop.sh checks the
# others ("0 crossings left" in etch's summary), which spares 002 a second
# run of it.
# Every figure an example's README quotes about its result is that run's
# output at the README's precision (example_figures: the EUV examples' CDs,
# LER/LWR/correlation length, LCDU and counts, the ArF immersion example's
# contrasts and widths, contact-highna's CD table), read from the files
# the README run leaves, without another run.
# The checks are tests/lib/examples.sh's; the longest examples (its
# EXAMPLES_OWN) are tests of their own, 004 and 005, so that the runner
# spreads them over the cores; this test takes every other 3D example.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/examples.sh"
for name in $(examples_rest); do
	example_all "$name"
done
exit 0
