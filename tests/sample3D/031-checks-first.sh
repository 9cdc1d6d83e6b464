#!/bin/sh
# sample3D checks every stage's options before it runs any, and runs the
# programs beside itself before any on PATH (a bad option once cost a splat
# and a bleach run, and an installed splat once ran instead of the build's).
# 1. "-et 30s" (and an unknown etch option through -etch) fail with one
#    line, exit 2, and leave existing image.cont and rval.3D.binary
#    untouched (nothing runs).
# 2. With PATH holding only the system directories and a decoy "splat"
#    first in PATH that fails, sample3D called by its path still runs the
#    build's splat, bleach and etch and succeeds.
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact
S3=$BUILD/bin/sample3D
echo old >image.cont
echo old >rval.3D.binary
for bad in "-et 30s" "-et 30 -etch -bogus"; do
	# shellcheck disable=SC2086
	$S3 -if "$E/mask.in" -bf "$E/resist.in" $bad >out.txt 2>err.txt </dev/null
	st=$?
	[ $st -eq 2 ] || fail "sample3D $bad: exit $st, expected 2: $(cat err.txt)"
	[ "$(wc -l <err.txt)" -eq 1 ] || fail "sample3D $bad: not one line: $(cat err.txt)"
	[ "$(cat image.cont)" = old ] || fail "sample3D $bad ran splat before refusing"
	[ "$(cat rval.3D.binary)" = old ] || fail "sample3D $bad ran bleach before refusing"
done
rm -f image.cont rval.3D.binary
mkdir decoy
printf '#!/bin/sh\necho "decoy splat ran" >&2\nexit 3\n' >decoy/splat
chmod +x decoy/splat
PATH=$PWD/decoy:/usr/bin:/bin "$S3" -q -if "$E/mask.in" -bf "$E/resist.in" -et 5 \
	>out.txt 2>err.txt </dev/null || fail "sample3D with a decoy splat on PATH: $(cat err.txt)"
[ -s curves.plot ] || fail "no curves.plot"
! grep -q decoy err.txt || fail "the decoy splat ran"
exit 0
