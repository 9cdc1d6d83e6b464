# The drawing back end: a page with every primitive (tests/lib/drawdemo.c)
# renders in ghostscript without an error, portrait, scaled and landscape;
# output is deterministic (two runs byte-identical, no date); the PS has
# two DSC pages; the SVG is one document with balanced groups and escaped
# text.  A black line drawn at a known place lands on the expected pixels.
. "$TOP/tests/lib/common.sh"
D=$BUILD/tests/lib/drawdemo
$D a.ps a.svg || fail "drawdemo failed"
$D b.ps b.svg || fail "drawdemo failed"
same a.ps b.ps
same a.svg b.svg
grep -q '^%%Pages: 2$' a.ps || fail "PS does not announce 2 pages"
[ "$(grep -c '^%%Page: ' a.ps)" -eq 2 ] || fail "PS does not hold 2 pages"
grep -qi 'creationdate' a.ps && fail "PS carries a date"
[ "$(grep -c '<g' a.svg)" -eq "$(grep -c '</g>' a.svg)" ] || fail "SVG groups unbalanced"
grep -q '&lt;b&gt; &amp; &quot;c&quot;' a.svg || fail "SVG text not escaped"
tail -n 1 a.svg | grep -qx '</svg>' || fail "SVG not closed"
need gs
gs_check a.ps
$D s.ps s.svg 0.5 && gs_check s.ps
$D l.ps l.svg 0.8 landscape && gs_check l.ps
# page 2 has a black line from (72,72) to (540,72) points: at 72 dpi the
# pixel row 792-72 = 720 from the top is dark at x = 300, and white well
# above it
gs -q -dSAFER -dBATCH -dNOPAUSE -sPAPERSIZE=letter -dFIXEDMEDIA -sDEVICE=pgmraw -r72 -dFirstPage=2 -dLastPage=2 \
	-sOutputFile=p2.pgm a.ps </dev/null || fail "gs could not render page 2"
pix() { # pix X Y: gray value at column X, row Y of p2.pgm (P5, 612x792, maxval 255)
	tail -c $((612 * 792)) p2.pgm | dd bs=1 skip=$(($2 * 612 + $1)) count=1 2>/dev/null | od -An -tu1 | tr -d ' '
}
[ "$(pix 300 720)" -lt 128 ] || [ "$(pix 300 719)" -lt 128 ] || fail "the line is not at row 720 (gray $(pix 300 720))"
[ "$(pix 300 600)" -gt 200 ] || fail "pixel (300,600) should be white"
exit 0
