# Output does not depend on the thread count, for the threaded parts of
# etch: the fast-marching surfaces (one print time per
# thread, then formatted in parallel) and the deloop pass's crossing
# search (ranges of segments, each with its own list, sorted at the end).
#   - etch -method fmm on a 3 um cell of a 0.9 um line in a clear field
#     (31 x 31 x 60, four print times, so 1, 2 and 3 threads split them
#     differently), compact and -dense;
#   - etch -deloop on Figure 8.13's two seeds (tests/bench/deloop.sh's
#     case at S_ideal 0.1: 14600 segments, split at 4096), delooped at
#     0.8 and 1 s;
# with 1, 2 and 3 threads (and SAMPLE3D_THREADS=2), byte for byte.
. "$TOP/tests/lib/common.sh"
MK=$BUILD/tests/lib/mkrate
[ -x "$MK" ] || fail "$MK not built"
cat >mask.in <<'M'
wavelength 0.436
na 0.28
sigma 0.5
background clear
window -1.5 1.5 -1.5 1.5
rect -0.45 -1 0.45 1 0 0
grid 31 31
contour image.cont
M
splat -q -o image.cont mask.in || fail "splat"
sed 's/^grid nz .*/grid nz 60/' "$TOP/examples/clear-lines-2/resist.in" >resist.in
bleach -q -o r.bin image.cont resist.in || fail "bleach"
for t in 1 2 3; do
	etch -q -threads $t -et 20 -pt 5 -method fmm -o f$t.plot r.bin || fail "etch -method fmm -threads $t"
	etch -q -threads $t -et 20 -pt 5 -method fmm -dense -no2d -o d$t.plot r.bin ||
		fail "etch -method fmm -dense -threads $t"
done
SAMPLE3D_THREADS=2 etch -q -et 20 -pt 5 -method fmm -o fenv.plot r.bin || fail "etch -method fmm, SAMPLE3D_THREADS=2"
for f in f2 f3 fenv; do
	same f1.plot $f.plot
	same f1.plot.2D $f.plot.2D
done
same d1.plot d2.plot
same d1.plot d3.plot
"$MK" -o two.bin 31 41 31 -1.5 1.5 -1.5 2.5 -1.5 1.5 1 >/dev/null || fail "mkrate"
for t in 1 2 3; do
	etch -threads $t -et 1 -dt 0.1 -pt 0.8 -seg 0.1 -seed 0 0 0 -seed 0 1 0 -deloop -no2d \
		-o s$t.plot two.bin 2>s$t.log >/dev/null || fail "etch -deloop -threads $t"
done
grep -q 'removed [1-9][0-9]* loops' s1.log || fail "no loop removed: $(grep deloop: s1.log)"
segs=$(awk '/final mesh/ { for (i = 1; i <= NF; i++) if ($i == "segments,") print $(i - 1) }' s1.log)
[ "${segs:-0}" -gt 8192 ] || fail "only ${segs:-0} segments: the search is not split among threads"
same s1.plot s2.plot
same s1.plot s3.plot
exit 0
