# The size of bleach's grid is limited by its estimate, not by a fixed
# cap: a grid beyond the machine's memory is refused
# before any work with one line naming the grid statement's line, the
# number of rate points, the time and memory it would take, and the way
# to run it anyway (-big, SAMPLE3D_BIG); nothing is written.  (The old
# cap refused every grid above 2^26 points with "at most 67108864" and
# no estimate.)  The grids that now run - 2^26 points in seconds, 192 M
# points in 1.6 GB - are tests/bench/large.sh's and bleach.sh's: too big
# for make check.
. "$TOP/tests/lib/common.sh"
unset SAMPLE3D_BIG
printf '0 1 0 1\n2 2\n1 1 1 1\n' >clear.cont
cat >in.txt <<'IN'
wavelength 0.436
resist thickness 0.70 index 1.68 dill 0.64 0.040 0.010
substrate 4.73 0.14
dose 240
develop kim 0.062 0.0001 8.5
grid nx 100000 ny 100000 nz 1000
IN
expect_file_error bleach in.txt -q clear.cont in.txt
grep -q '^bleach: in.txt:6: 1e+13 rate points need about .* of work and .*B of memory.*-big' err.txt ||
	fail "no estimate in: $(cat err.txt)"
grep -q 'SAMPLE3D_BIG' err.txt || fail "SAMPLE3D_BIG not named: $(cat err.txt)"
[ ! -e rval.3D.binary ] || fail "a refused grid left rval.3D.binary"
:
