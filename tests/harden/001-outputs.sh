# Atomic outputs, against the rules of util.h:
# - an output that is not a regular file (a symbolic link to a device, a
#   FIFO) is written in place, never renamed over;
# - a program with several outputs (splat: image and cutlines) commits
#   none until all succeed;
# - SIGINT, SIGTERM, SIGHUP and SIGPIPE during etch remove its temporaries and the
#   exit status is 128+n.
. "$TOP/tests/lib/common.sh"
cat >in.txt <<'IN'
window -1 1 -1 1
rect -0.3 -0.3 0.3 0.3
grid 11 11
IN
# a link to a device stays a link (before: replaced by a regular file);
# /dev/zero, not /dev/null, so that a failure cannot harm the machine
[ -c /dev/zero ] || skip "/dev/zero is not a character device here"
ln -s /dev/zero zero.cont
splat -q -o zero.cont in.txt || fail "splat -o link-to-/dev/zero failed"
[ -L zero.cont ] || fail "the link to /dev/zero was replaced"
[ -c /dev/zero ] || fail "/dev/zero is no longer a device"
# a FIFO is written through, and stays a FIFO
mkfifo pipe.cont
timeout 20 cat pipe.cont >got.cont &
cat_pid=$!
splat -q -o pipe.cont in.txt || fail "splat -o FIFO failed"
wait $cat_pid || fail "reading the FIFO failed"
[ -p pipe.cont ] || fail "the FIFO was replaced"
splat -q -o direct.cont in.txt || fail "splat failed"
same got.cont direct.cont
ls | grep -q tmp && fail "temporaries left: $(ls)"

# several outputs: a cutline that cannot be written leaves the old image
echo old >image.cont
printf 'contour image.cont\ncutline -1 0 1 0 5 nodir/cut.2D\n' >>in.txt
expect_error splat -q in.txt
[ "$(cat image.cont)" = old ] || fail "splat replaced the image before failing on its cutline"
ls | grep -q tmp && fail "temporaries left: $(ls)"

# pdraw: a -svg that cannot be written leaves dataplot.ps as it was
printf '0 1 0 1 0 1\n1\n4\n0 0 0\n1 0 0\n0 1 1\n0 0 0\n' >t.3D
echo old >dataplot.ps
expect_error pdraw -noplot -svg nodir/x.svg t.3D
[ "$(cat dataplot.ps)" = old ] || fail "pdraw replaced dataplot.ps before failing on -svg"
pdraw -noplot -svg x.svg t.3D 2>/dev/null || fail "pdraw -svg failed"
[ -s x.svg ] && [ "$(cat dataplot.ps)" != old ] || fail "pdraw did not write both outputs"

# signals during etch: a slow run (many small steps), stopped after half a
# second (its temporaries are open from its first 0.05 s)
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
$MKRATE -o r.bin 6 6 6 0 1 0 1 0 1 0.01 || fail "mkrate"
for sig in INT TERM HUP PIPE; do
	rm -f curves.plot*
	timeout -s $sig --preserve-status 0.5 etch -q -et 1e6 -dt 1 r.bin
	st=$?
	case $sig in INT) want=130 ;; TERM) want=143 ;; HUP) want=129 ;; PIPE) want=141 ;; esac
	[ $st -eq $want ] || fail "etch after SIG$sig: exit $st, expected $want"
	ls | grep -q 'curves.*tmp' && fail "SIG$sig left temporaries: $(ls)"
done
exit 0
