# Every format: write -> read -> write gives byte-identical files (golden:
# the first write), and the values survive (checked against the input by
# hand-written expectations).  Also: "-" reads stdin, .gz input is read
# through gzip, ASCII -> binary -> ASCII rate files round-trip exactly.
. "$TOP/tests/lib/common.sh"
F=$BUILD/tests/lib/fmtcat
MK=$BUILD/tests/lib/mkrate

# contour-file, odd layout, counts written as 3.0
printf '0 2\t-1 1\n3.0 2\n0.1 0.2\n0.30000000000000004 1e-3 -0 5\n' >c.in
$F contour c.in c1 && $F contour c1 c2 || fail "contour round trip failed"
same c1 c2
printf '0 2 -1 1\n3 2\n0.1\n0.2\n0.30000000000000004\n0.001\n0\n5\n' >c.expect
same c1 c.expect

# old contour format: 50x50 values
awk 'BEGIN { print "0 0 5 5"; for (i = 0; i < 2500; i++) print i / 7 }' >old.in
$F contour-old old.in o1 && $F contour-old o1 o2 || fail "old contour round trip failed"
same o1 o2
$F contour-old old.in - | head -n 1 | grep -qx '0 0 5 5' || fail "old header not kept"

# 3D plot file: two sets, commas, 4.0 counts, blank-line separation
cat >p3.in <<'E'
0, 1, 0, 1, -1, 0
2
4.0
0 0 0
1 0 0
1 1 -1
0 0 0
2
0.5 0.5 -0.5
0.25 0.25 -0.25

-1 1 -1 1 -1 1
1
1
0 0 0
E
$F plot3 p3.in p1 && $F plot3 p1 p2 || fail "plot3 round trip failed"
same p1 p2
[ "$(grep -c '^$' p1)" -eq 1 ] || fail "plot3: the two sets are not separated by one blank line"
[ "$(sed -n 3p p1)" = 4 ] || fail "plot3: count 4.0 not written as 4"

# 2D plot file, as image.cont of contour -c writes it
printf 'xmin, xmax, ymin, ymax\n' >/dev/null
printf '0, 1, 0, 1\n1\n3\n0 0\n0.5 0.5\n1 1\n' >p2.in
$F plot2 p2.in q1 && $F plot2 q1 q2 || fail "plot2 round trip failed"
same q1 q2
# stdin and gzip
$F plot2 - q3 <p2.in || fail "plot2 from stdin failed"
same q1 q3
if command -v gzip >/dev/null; then
	gzip -c p2.in >p2.in.gz
	$F plot2 p2.in.gz q4 || fail "plot2 from .gz failed"
	same q1 q4
fi

# options-file
cat >o.in <<'E'
# a comment
label "Resist profile"   # trailing comment
GRID On
scale 0.5
xticks 7
joinlevel HIGH
E
$F options o.in op1 && $F options op1 op2 || fail "options round trip failed"
same op1 op2
printf 'label "Resist profile"\ngrid on\nscale 0.5\nxticks 7\njoinlevel high\n' >o.expect
same op1 o.expect

# rate files: ASCII -> binary -> ASCII, and binary -> binary
$MK -ascii -M 'x*y' -o r.asc 4 3 5 -1 1 -0.5 0.5 -0.7 0 'exp(-x^2)*(1.05-cos(2*pi*z/0.13))' ||
	fail "mkrate failed"
$F rate r.asc r.bin && $F rate-ascii r.bin r2.asc && $F rate r2.asc r2.bin || fail "rate conversions failed"
same r.asc r2.asc
same r.bin r2.bin
head -c 8 r.bin | od -c | head -1 | grep -q 'R   V   A   L   3   D  \\n' || fail "binary magic missing"
# the same values in ASCII from mkrate binary output
$MK -M 'x*y' -o r3.bin 4 3 5 -1 1 -0.5 0.5 -0.7 0 'exp(-x^2)*(1.05-cos(2*pi*z/0.13))'
same r.bin r3.bin
exit 0
