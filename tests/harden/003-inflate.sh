# Inputs larger inside than outside, refused before they are read whole:
# a 2 GB sparse file named as a GDSII layout (zeros: a record of length 0) and
# one whose HEADER is followed by zeros are refused at their first bad
# record within 5 s (they were read whole first); a layout compressed
# with gzip is counted as it inflates and refused past SAMPLE3D_MEMORY
# naming the statement; and the memory limit of a refusal follows the
# address-space limit (ulimit -v) when that is below the machine's.
# Against: the records written by hand, the limits set here.
. "$TOP/tests/lib/common.sh"
dd if=/dev/zero of=zero.gds bs=1 count=0 seek=2G 2>/dev/null || fail "cannot make a sparse file"
printf '\000\006\000\002\002\130' >head.gds
dd if=/dev/zero of=head.gds bs=1 count=0 seek=2G 2>/dev/null
printf 'wavelength 0.365\nna 0.5\nwindow -2 2 -2 2\ngds zero.gds layer 1\n' >z.in
printf 'wavelength 0.365\nna 0.5\nwindow -2 2 -2 2\ngds head.gds layer 1\n' >h.in
start=$(date +%s)
expect_error splat -q -o z.cont z.in
grep -q "^splat: z.in:4: zero.gds: byte 0: bad record length 0" err.txt || fail "zero.gds: $(cat err.txt)"
expect_error splat -q -o h.cont h.in
grep -q "^splat: h.in:4: head.gds: byte 6: bad record length 0" err.txt || fail "head.gds: $(cat err.txt)"
[ $(($(date +%s) - start)) -le 5 ] || fail "the sparse files took more than 5 s: read whole?"

"$BUILD/tests/lib/mkgds" grid 200 0.02 0.01 g.gds || fail "mkgds"
gzip -c g.gds >g.gds.gz
printf 'wavelength 0.365\nna 0.5\nwindow -2 2 -2 2\ngds g.gds.gz layer 1\n' >g.in
export SAMPLE3D_MEMORY=1e6
expect_error splat -q -o g.cont g.in
unset SAMPLE3D_MEMORY
grep -q "^splat: g.in:4: g.gds.gz: decompresses or streams to more than 1 MB.* use -big" err.txt ||
	fail "g.gds.gz: $(cat err.txt)"
splat -q -o g.cont g.in 2>err.txt || fail "g.gds.gz within the limit: $(cat err.txt)"

# a window of 2000 um at NA 0.99: refused; under ulimit -v the limit named
printf 'wavelength 0.365\nna 0.99\nwindow -1000 1000 -1000 1000\nrect 0 0 1 1\n' >w.in
# (not in a sanitizer build: its shadow memory needs more address space
# than any such limit allows, so the program cannot start under one)
if nm "$BUILD/bin/splat" 2>/dev/null | grep -q __asan_init; then
	echo "ulimit -v check left out: a sanitizer build"
else
	(ulimit -v 3000000 && splat -q -o w.cont w.in) 2>err.txt && fail "the 2000 um window ran"
	grep -q "the 3.07 GB of memory the address-space limit (ulimit -v) allows" err.txt ||
		fail "ulimit -v: $(cat err.txt)"
fi
exit 0
