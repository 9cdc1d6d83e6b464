# The plot programs estimate memory and time from a plot file's size
# before reading it (plot_budget: without it pdraw grew to 18.7 GB on a
# 13 GB curves.plot before it was killed).  With the memory limit made
# small (SAMPLE3D_MEMORY=100000 bytes, budget.h) a 600 kB file of 4000
# triangles is beyond it: every reader refuses at once with one line
# naming the file, the estimate and the way to run it anyway (-big,
# SAMPLE3D_BIG), and writes nothing; with -big or SAMPLE3D_BIG=1 it
# draws.  The estimate counts the numbers from the density of the file's
# first 64 kB: within 5 % of the 48000 numbers the file holds (40000 in
# the 2D file).  Without
# the limit the same files draw with no message, and a 2 TB sparse file
# (64 kB of triangles, then a hole) is refused on any machine.
. "$TOP/tests/lib/common.sh"
unset SAMPLE3D_BIG SAMPLE3D_MEMORY
awk 'BEGIN { print "0 1 0 1 0 1"; print 4000     # a strip of a tilted plane
	for (i = 0; i < 4000; i++) { a = i / 4000; b = (i + 1) / 4000; print 4
		printf "%.17g 0 %.17g\n%.17g 0 %.17g\n%.17g 1 %.17g\n%.17g 0 %.17g\n", a, a / 4, b, b / 4, a, a / 4, a, a / 4 } }' >tri.3D
awk 'BEGIN { print "0 1 0 1"; print 1; print 20000
	for (i = 0; i < 20000; i++) printf "%.17g %.17g\n", i / 20000, i / 19999 }' >line.2D
refused() { # PROG FILE NUMBERS ARGS...: refused, estimate of about NUMBERS
	_p=$1 _f=$2 _n=$3
	shift 3
	rm -f dataplot.ps out.vtp
	SAMPLE3D_MEMORY=100000 expect_error "$_p" "$@"
	grep -q "^$_p: $_f: [0-9.e+]* plot numbers (.*B of text) need about .* of work and .*B of memory, beyond the limits (1 h of work, the 100 kB of memory SAMPLE3D_MEMORY allows): use -big or SAMPLE3D_BIG=1" err.txt ||
		fail "$_p $*: not the estimate's refusal: $(cat err.txt)"
	_e=$(sed 's/.*: \([0-9.e+]*\) plot numbers.*/\1/' err.txt)
	close "$_e" "$_n" "$(awk -v n="$_n" 'BEGIN { print n * 0.05 }')" "$_p $*: numbers estimated"
	[ ! -e dataplot.ps ] && [ ! -e out.vtp ] || fail "$_p $*: wrote output though refused"
}
refused pdraw tri.3D 48000 -noplot -h tri.3D
refused pdraw tri.3D 48000 -noplot tri.3D
refused contour tri.3D 48000 -noplot -cstep 0.1 -3D tri.3D
refused conv tri.3D 48000 -vtk -o out.vtp tri.3D
refused drawplot line.2D 40000 -noplot line.2D
grep -q 'with the other files' err.txt && fail "one file said 'with the other files'"
# two files: the total, named after the larger (line.2D, 0.76 MB)
[ "$(wc -c <line.2D)" -gt "$(wc -c <tri.3D)" ] || fail "line.2D is not the larger file"
SAMPLE3D_MEMORY=100000 pdraw -noplot tri.3D line.2D </dev/null >/dev/null 2>err.txt
grep -q '^pdraw: line.2D: with the other files, [0-9.e+]* plot numbers (1.36 MB of text)' err.txt ||
	fail "two files: $(cat err.txt)"
# -big and SAMPLE3D_BIG=1 run anyway, with a one-line note
for big in -big env; do
	rm -f dataplot.ps
	if [ $big = env ]; then
		SAMPLE3D_MEMORY=100000 SAMPLE3D_BIG=1 pdraw -noplot -h tri.3D </dev/null >/dev/null 2>err.txt
	else
		SAMPLE3D_MEMORY=100000 pdraw -noplot -h -big tri.3D </dev/null >/dev/null 2>err.txt
	fi || fail "pdraw $big: $(cat err.txt)"
	[ -s dataplot.ps ] || fail "pdraw $big: no plot"
	grep -q '^pdraw: tri.3D: .*-big: running anyway' err.txt || fail "pdraw $big: no note: $(cat err.txt)"
done
for c in "drawplot -noplot -big line.2D" "contour -noplot -cstep 0.1 -3D -big tri.3D" \
	 "conv -vtk -big -o out.vtp tri.3D"; do
	SAMPLE3D_MEMORY=100000 $c </dev/null >/dev/null 2>err.txt || fail "$c: $(cat err.txt)"
done
# within the limits: drawn with no message
for c in "pdraw -noplot -h tri.3D" "drawplot -noplot line.2D" \
	 "contour -noplot -cstep 0.1 -3D tri.3D" "conv -vtk -o out.vtp tri.3D"; do
	$c </dev/null >/dev/null 2>err.txt || fail "$c: $(cat err.txt)"
	[ ! -s err.txt ] || fail "$c: a message within the limits: $(cat err.txt)"
done
# the plot programs without a plot file to read take no -big
drawmask -noplot -big x.gds </dev/null >/dev/null 2>err.txt
[ $? -eq 2 ] || fail "drawmask -big: not a usage error"
# a sparse 2 TB file is beyond any machine (its estimate, never its text)
head -c 65536 tri.3D >huge.3D
if truncate -s 2T huge.3D 2>/dev/null; then
	expect_error pdraw -noplot -h huge.3D
	grep -q '^pdraw: huge.3D: .*(2.2 TB of text) need about .*-big' err.txt ||
		fail "2 TB: not the estimate's refusal: $(cat err.txt)"
fi
exit 0
