# Every command the README prints runs as printed: its first block's make
# targets exist (make -n, which runs nothing: the tests cannot run make
# check inside make check), and every other sh block runs without an error
# from the top of the tree with the build's programs NOT on PATH, twice in
# a row in one shell (a second run must not trip over the first one's
# files), leaving the files the README says each driver leaves.
. "$TOP/tests/lib/common.sh"
awk '/^```sh$/ { n++; code = 1; next } code && /^```$/ { code = 0; next }
	code { print > ("block" n ".sh") }' "$TOP/README.md"
[ -s block1.sh ] || fail "the README has no sh block"
targets=$(awk '/^make / { print $2 }' block1.sh)
[ -n "$targets" ] || fail "the README's first block names no make target"
# shellcheck disable=SC2086 # a list of targets
make -n -C "$TOP" BUILD="$BUILD" $targets >make.txt 2>&1 || fail "make -n $targets: $(tail -n 3 make.txt)"
[ -s block2.sh ] || fail "the README has no block of driver commands"
for b in block[2-9].sh; do
	grep -q /tmp/sample3d "$b" || fail "$b no longer works in /tmp/sample3d: update this test"
	grep -q 'B=$T/build/bin' "$b" || fail "$b no longer takes the programs from \$T/build/bin: update this test"
	# the build under test (build-asan, ...) stands for build/
	sed -e "s|/tmp/sample3d|$PWD/sample3d|g" -e "s|B=\$T/build/bin|B=$BUILD/bin|" "$b" >one.sh
	cat one.sh one.sh >twice.sh
	here=$PWD
	# bounded here (the runner's bound would kill this test with its
	# log empty), so that a hang says where it was
	(cd "$TOP" && unset T && PATH=/usr/bin:/bin exec timeout 400 sh -e "$here/twice.sh") >out.txt 2>&1 ||
		fail "$b failed (exit $?; 124: still running after 400 s): $(tail -n 5 out.txt)"
done
for f in image.cont rval.3D.binary curves.plot profile.ps cut.ps image.ps profile.plot profile2D.ps dataplot.ps \
	fem/fem.dat fem/bossung.ps fem/window.ps; do
	[ -s "sample3d/$f" ] || fail "the README's drivers left no $f"
done
grep -q '^# cleared yes$' out.txt || fail "sample3D -measure printed no table: $(tail -n 5 out.txt)"
exit 0
