# conv: a known 3x2 grid gives the expected wire mesh and triangles
# (golden files written by hand from conv(L)'s description), -o and the
# default name input.3D, -old input, compressed input, and errors.
. "$TOP/tests/lib/common.sh"
printf '0 2 0 1\n3 2\n1 2 3\n4 5 6\n' >g.cont
conv g.cont || fail "conv failed"
[ -f g.cont.3D ] || fail "default output name g.cont.3D not used"
cat >mesh.expect <<'E'
0 2 0 1 1 6
5
3
0 0 1
1 0 2
2 0 3
3
0 1 4
1 1 5
2 1 6
2
0 0 1
0 1 4
2
1 0 2
1 1 5
2
2 0 3
2 1 6
E
same g.cont.3D mesh.expect

conv -t -o tri.3D g.cont || fail "conv -t failed"
cat >tri.expect <<'E'
0 2 0 1 1 6
4
4
0 0 1
1 0 2
1 1 5
0 0 1
4
0 0 1
1 1 5
0 1 4
0 0 1
4
1 0 2
2 0 3
2 1 6
1 0 2
4
1 0 2
2 1 6
1 1 5
1 0 2
E
same tri.3D tri.expect

# the output reads back as a pdraw file with the same content
PATH=$BUILD/tests/lib:$PATH fmtcat plot3 tri.3D tri2.3D || fail "conv output does not read back"
same tri.3D tri2.3D

# -old: 50x50 grid from xmin ymin xlength ylength
awk 'BEGIN { print "1 2 3 4"; for (i = 0; i < 2500; i++) print i % 50 }' >old.cont
conv -old -o old.3D old.cont || fail "conv -old failed"
head -n 1 old.3D | grep -qx '1 4 2 6 0 49' || fail "-old bounds wrong: $(head -n 1 old.3D)"
[ "$(sed -n 2p old.3D)" = 100 ] || fail "-old: expected 100 wire curves"

# compressed input
if command -v gzip >/dev/null; then
	gzip -c g.cont >z.cont.gz
	conv -o z.3D z.cont.gz || fail "conv on .gz failed"
	same z.3D mesh.expect
fi

# errors: bad option (a pointer to the usage, exit 2), missing input, malformed input
conv -x g.cont >/dev/null 2>err.txt; [ $? -eq 2 ] || fail "bad option: expected exit 2"
grep -q usage err.txt || fail "bad option: no usage"
conv >/dev/null 2>&1; [ $? -eq 2 ] || fail "no input: expected exit 2"
printf '0 2 0 1\n3 2\n1 2\n' >short.cont
expect_file_error conv short.cont short.cont
[ -e short.cont.3D ] && fail "an output was left for bad input"
conv --help | grep -q usage || fail "--help prints no usage"
exit 0
