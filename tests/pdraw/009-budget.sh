# The plot programs estimate memory and time from a plot file's size
# before reading it (plot_budget, issue 15: pdraw grew to 18.7 GB on a
# 13 GB curves.plot before it was killed): a file whose estimate is beyond
# the machine's memory is refused at once with one line naming the file,
# the estimate and the way to run it anyway (-big, SAMPLE3D_BIG), and
# nothing is written.  The file is sparse: 64 kB of triangles, then a
# hole to 2 TB, so the estimate (numbers from the density of the first
# 64 kB, times the size) is far beyond any test machine, and a program
# that read it instead of refusing would not finish.  Also: a file
# within the limits still draws with and without -big, and -big is
# accepted by every program that has it.
. "$TOP/tests/lib/common.sh"
unset SAMPLE3D_BIG
awk 'BEGIN { print "0 1 0 1 0 1"; print 4000     # a strip of a tilted plane
	for (i = 0; i < 4000; i++) { a = i / 4000; b = (i + 1) / 4000; print 4
		printf "%.17g 0 %.17g\n%.17g 0 %.17g\n%.17g 1 %.17g\n%.17g 0 %.17g\n", a, a / 4, b, b / 4, a, a / 4, a, a / 4 } }' >tri.3D
head -c 65536 tri.3D >huge.3D
truncate -s 2T huge.3D 2>/dev/null || skip "no sparse 2 TB file here"
awk 'BEGIN { print "0 1 0 1"; print 1; print 2000
	for (i = 0; i < 2000; i++) printf "%.17g %.17g\n", i / 2000, i / 1999 }' >line.2D
head -c 65536 line.2D >huge.2D
truncate -s 2T huge.2D || fail "truncate worked once, not twice"
refused() { # PROG FILE ARGS...
	_p=$1 _f=$2
	shift 2
	rm -f dataplot.ps out.vtp
	expect_error "$_p" "$@"
	grep -q "^$_p: $_f: .*plot numbers (2.2 TB of text) need about .* of work and .*B of memory.*-big.*SAMPLE3D_BIG=1" err.txt ||
		fail "$_p $*: not the estimate's refusal: $(cat err.txt)"
	[ ! -e dataplot.ps ] && [ ! -e out.vtp ] || fail "$_p $*: wrote output though refused"
}
refused pdraw huge.3D -noplot -h huge.3D
refused pdraw huge.3D -noplot huge.3D
refused pdraw huge.3D -noplot tri.3D huge.3D
refused contour huge.3D -noplot -3D huge.3D
refused conv huge.3D -vtk -o out.vtp huge.3D
refused drawplot huge.2D -noplot huge.2D
# the estimate counts numbers: 2 TB of triangles is about 1e11 of them
grep -q 'with the other files, ' err.txt && fail "one file said 'with the other files'"
pdraw -noplot -h tri.3D huge.3D </dev/null >/dev/null 2>err.txt
grep -q '^pdraw: huge.3D: with the other files, [0-9.]*e+1[01] plot numbers' err.txt ||
	fail "two files: not the total estimate of about 1e11 numbers: $(cat err.txt)"
# within the limits: drawn, -big or not, and no message
for b in "" -big; do
	rm -f dataplot.ps
	pdraw -noplot -h $b tri.3D </dev/null >/dev/null 2>err.txt || fail "pdraw -h $b tri.3D: $(cat err.txt)"
	[ -s dataplot.ps ] && [ ! -s err.txt ] || fail "pdraw -h $b tri.3D: no plot or a message: $(cat err.txt)"
	drawplot -noplot $b line.2D </dev/null >/dev/null 2>err.txt || fail "drawplot $b: $(cat err.txt)"
	contour -noplot -cstep 0.1 -3D $b tri.3D </dev/null >/dev/null 2>err.txt || fail "contour -3D $b: $(cat err.txt)"
	conv -vtk $b -o out.vtp tri.3D </dev/null >/dev/null 2>err.txt || fail "conv -vtk $b: $(cat err.txt)"
done
# the plot programs without a plot file to read take no -big
drawmask -noplot -big x.gds </dev/null >/dev/null 2>err.txt
[ $? -eq 2 ] || fail "drawmask -big: not a usage error"
exit 0
