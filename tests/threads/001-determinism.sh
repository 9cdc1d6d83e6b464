# Output does not depend on the thread count (GUIDE: threads and
# determinism): the 1.25 um contact of examples/contact (51 x 51 x 300,
# 3D bake) through bleach with 1, 2 and 3 threads, and its rate file
# through etch (ray strings, prints at 10, 20, 30 s, with a cut) with 1,
# 2 and 3 threads; every output compared byte for byte.  The thread count
# comes from -threads and, for one run of each, from SAMPLE3D_THREADS;
# a bad SAMPLE3D_THREADS or -threads 0 is refused.  The work is split at
# 64 columns (bleach), 256 nodes and 512 triangles (etch), so these runs
# are really split.
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact
splat -q "$E/mask.in" || fail "splat failed"
img=image.cont
sed 's/^bake diffusion/bake3d diffusion/' "$E/resist.in" >resist3d.in
for t in 1 2 3; do
	bleach -q -threads $t -o r$t.bin "$img" resist3d.in || fail "bleach -threads $t failed"
	bleach -q -threads $t -ascii -o r$t.txt "$img" resist3d.in || fail "bleach -threads $t -ascii failed"
done
SAMPLE3D_THREADS=3 bleach -q -o renv.bin "$img" resist3d.in || fail "bleach with SAMPLE3D_THREADS=3 failed"
for f in r2.bin r3.bin renv.bin; do same r1.bin $f; done
for f in r2.txt r3.txt; do same r1.txt $f; done
for t in 1 2 3; do
	etch -q -threads $t -et 30 -pt 10 -cut x 0 -o c$t.plot r1.bin || fail "etch -threads $t failed"
done
SAMPLE3D_THREADS=2 etch -q -et 30 -pt 10 -cut x 0 -o cenv.plot r1.bin || fail "etch with SAMPLE3D_THREADS=2 failed"
for f in c2 c3 cenv; do
	same c1.plot $f.plot
	same c1.plot.2D $f.plot.2D
	same c1.cut $f.cut
done
[ "$(grep -c '' c1.plot)" -gt 10000 ] || fail "etch output too small to be split among threads"
SAMPLE3D_THREADS=zero etch -q -et 1 r1.bin 2>err.txt && fail "SAMPLE3D_THREADS=zero accepted"
grep -q 'SAMPLE3D_THREADS' err.txt || fail "bad SAMPLE3D_THREADS: $(cat err.txt)"
etch -q -threads 0 -et 1 r1.bin 2>err.txt && fail "-threads 0 accepted"
exit 0
