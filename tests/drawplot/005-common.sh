# The behaviour common to the four plot programs (pdraw, contour,
# drawplot, drawmask), each run on a small valid input with stdin from
# /dev/null under a 20 s timeout (nothing may wait for a terminal):
#   --help exits 0; a bad option gives the problem and a line naming
#   --help (two lines), exit 2;
#   dataplot.ps is written, -ps and POSTSCRIPT=OFF suppress it, -svg
#   writes SVG, -s 0.5 scales the page; without a display, one note;
#   a bad input leaves an existing dataplot.ps untouched (atomic output);
#   -print with no lpr on PATH is a one-line error; with a stand-in lpr
#   it receives -Pprinter (from -P, else $PRINTER) and dataplot.ps.
. "$TOP/tests/lib/common.sh"
printf '0 1 0 1 0 1\n1\n2\n0 0 0\n1 1 1\n' >in.3D
printf '0 1 0 1\n1\n2\n0 0\n1 1\n' >in.2D
awk 'BEGIN { print 0, 1, 0, 1; print 5, 5; for (j = 0; j < 5; j++) for (i = 0; i < 5; i++) print i * j }' >in.cont
printf 'window 0 4 0 4\nbackground dark\nrect 1 1 3 3\n' >mask.in
input() {
	case $1 in pdraw) echo in.3D ;; contour) echo in.cont ;; drawplot) echo in.2D ;; drawmask) echo mask.in ;; esac
}
mkdir -p fakebin
cat >fakebin/lpr <<'L'
#!/bin/sh
echo "$@" >lpr.args
L
chmod +x fakebin/lpr
for p in pdraw contour drawplot drawmask; do
	in=$(input $p)
	rm -f dataplot.ps
	timeout 20 $p --help </dev/null >help.txt 2>&1 || fail "$p --help"
	grep -q "^usage: $p" help.txt || fail "$p --help prints no usage"
	timeout 20 $p -bogus "$in" </dev/null >out.txt 2>err.txt
	[ $? -eq 2 ] || fail "$p -bogus: expected exit 2"
	grep -q "^$p: unknown option -bogus" err.txt || fail "$p -bogus: $(head -1 err.txt)"
	grep -qx "$p: $p --help prints the usage" err.txt || fail "$p -bogus: no pointer to the usage"
	[ "$(wc -l <err.txt)" -eq 2 ] || fail "$p -bogus: not two lines: $(cat err.txt)"
	timeout 20 $p "$in" </dev/null >out.txt 2>err.txt || fail "$p $in: $(cat err.txt)"
	[ -s dataplot.ps ] || fail "$p wrote no dataplot.ps"
	gs_check dataplot.ps
	[ "$(grep -c 'no X11 preview' err.txt)" -eq 1 ] || fail "$p: expected one note without a display: $(cat err.txt)"
	cp dataplot.ps keep.ps
	timeout 20 $p -noplot -s 0.5 -svg pic.svg "$in" </dev/null 2>err.txt || fail "$p -s -svg: $(cat err.txt)"
	[ ! -s err.txt ] || fail "$p -noplot printed: $(cat err.txt)"
	grep -q '0.5000 dup scale' dataplot.ps || fail "$p -s 0.5 did not scale"
	grep -q '<svg' pic.svg || fail "$p -svg wrote no SVG"
	rm -f dataplot.ps
	timeout 20 $p -noplot -ps "$in" </dev/null || fail "$p -ps"
	[ ! -e dataplot.ps ] || fail "$p -ps wrote dataplot.ps"
	POSTSCRIPT=OFF timeout 20 $p -noplot "$in" </dev/null || fail "$p with POSTSCRIPT=OFF"
	[ ! -e dataplot.ps ] || fail "$p wrote dataplot.ps with POSTSCRIPT=OFF"
	cp keep.ps dataplot.ps
	printf 'garbage\n' >bad.in
	expect_error $p -noplot bad.in
	same keep.ps dataplot.ps
	env PATH="$BUILD/bin" "$BUILD/bin/$p" -noplot -print "$in" </dev/null >out.txt 2>err.txt
	st=$?
	[ $st -eq 1 ] || fail "$p -print without lpr: exit $st"
	[ "$(wc -l <err.txt)" -eq 1 ] || fail "$p -print without lpr: $(cat err.txt)"
	grep -q "^$p: lpr" err.txt || fail "$p -print without lpr: $(cat err.txt)"
	rm -f lpr.args
	PATH=$PWD/fakebin:$PATH timeout 20 $p -noplot -print -Pmyprinter "$in" </dev/null ||
		fail "$p -print with a stand-in lpr"
	[ "$(cat lpr.args)" = "-Pmyprinter dataplot.ps" ] || fail "$p: lpr got $(cat lpr.args)"
	PRINTER=envprinter PATH=$PWD/fakebin:$PATH timeout 20 $p -noplot -print "$in" </dev/null ||
		fail "$p -print with \$PRINTER"
	[ "$(cat lpr.args)" = "-Penvprinter dataplot.ps" ] || fail "$p: lpr got $(cat lpr.args)"
done
exit 0
