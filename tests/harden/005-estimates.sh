# The work estimates of bleach and etch count the costs per operation
# their man pages state (bleach(1): 0.065 microseconds of one core a rate
# point with the binary output, 0.155 with -ascii; etch(1): 0.12
# microseconds a triangle and time step of the ray-string engine), checked
# on runs refused before any work: 10^13 rate points are 7.5 and 18 days
# (the estimate's two digits), and the 3 10^7 steps of a rate of 10^6 um/s
# times the triangles the message names are the hours it prints, within
# 10 % (the message's two digits and the rate file's reading).  How close
# the constants are to the time runs take is tests/bench/estimate.sh's
# (make bench), not a test's: this one holds the man pages and the code
# together.
. "$TOP/tests/lib/common.sh"
built bleach etch
unset SAMPLE3D_BIG SAMPLE3D_MEMORY
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
grep -q '^bleach: in.txt:6: 1e+13 rate points need about 7.5 days of work' err.txt ||
	fail "binary output: not 0.065 us a point: $(cat err.txt)"
expect_file_error bleach in.txt -q -ascii clear.cont in.txt
grep -q '^bleach: in.txt:6: 1e+13 rate points need about 18 days of work' err.txt ||
	fail "-ascii: not 0.155 us a point: $(cat err.txt)"
grep -q 'about 0.065 microseconds of one core a rate point' "$TOP/man/man1/bleach.1" &&
	grep -q '^with the binary output (0.155 with$' "$TOP/man/man1/bleach.1" ||
	fail "bleach(1) no longer states 0.065 and 0.155 microseconds a point"

# etch: the time steps times the triangles at 0.12 us
expect_error etch -q -et 1 -o out.plot "$TOP/tests/fuzz/regress/rate-rate-1e6.txt"
set -- $(sed -n 's/.*: \([0-9.e+]*\) time steps of a mesh of \([0-9.e+]*\) triangles need about \([0-9.]*\) h of work.*/\1 \2 \3/p' err.txt)
[ $# -eq 3 ] || fail "etch: no steps, triangles and hours in: $(cat err.txt)"
awk -v s="$1" -v t="$2" -v h="$3" 'BEGIN { e = s * t * 0.12e-6 / 3600; exit !(h > 0.9 * e && h < 1.1 * e) }' ||
	fail "etch: $1 steps of $2 triangles at 0.12 us are not $3 h"
grep -q '^microseconds a triangle and step and 0.07 a point' "$TOP/man/man1/etch.1" &&
	grep -q 'an hour of one core (about 0.12$' "$TOP/man/man1/etch.1" ||
	fail "etch(1) no longer states 0.12 microseconds a triangle and step"
[ ! -e out.plot ] || fail "a refused run left out.plot"
:
