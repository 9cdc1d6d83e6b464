# Every example README's commands run as printed: each README of a folder
# with a script prints its commands ("sh ..." in backquotes), says to run
# make first, and names only scripts that exist there; a command with a
# placeholder ("[SIZE]", array40: minutes and gigabytes, timed by make
# bench) is only checked to name a script.  A command that remakes a
# committed input ("sh make-mask.sh 40 >mask.in") runs here and must give
# the same bytes as the committed file (tests/lib/examples.sh,
# example_readme).  Every other command is run exactly as written, once per
# make check, by the test that checks its outputs: every 3D example by
# tests/examples/001-all.sh, 004 or 005, the 2D ones by 003-2d.sh,
# examples/calibrate by tests/calib/003-example.sh (example_readme: from a
# copy of the example's folder, the build's programs NOT on PATH, exit 0,
# files left in out/).  Checked here: each such README is in the list those
# tests run (examples_readme_run), and each of those tests calls
# example_readme.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/examples.sh"
examples_readme_run | sort >covered.txt
for t in examples/001-all.sh examples/003-2d.sh examples/004-all-defect.sh \
	examples/005-all-corner-defect.sh calib/003-example.sh; do
	grep -q '^[^#]*example_\(readme\|all\) ' "$TOP/tests/$t" ||
		fail "tests/$t no longer runs its examples' README commands (example_readme)"
done
n=0 ran=0
for readme in "$TOP"/examples/*/README; do
	d=$(dirname "$readme")
	name=$(basename "$d")
	ls "$d"/*.sh >/dev/null 2>&1 || continue      # inputs only (resists)
	grep -o '`sh [^`]*`' "$readme" | tr -d '`' >cmds.txt
	[ -s cmds.txt ] || fail "examples/$name/README prints no command to run"
	grep -q 'After `make` at the top of the tree' "$readme" ||
		fail "examples/$name/README does not say to run make first"
	remake=""
	while IFS= read -r cmd; do
		script=$(printf '%s\n' "$cmd" | awk '{ print $2 }')
		[ -f "$d/$script" ] || fail "examples/$name/README: $cmd names no script there"
		case $cmd in
		*'['*) ;;
		*'>'*) remake=yes ;;
		*)
			grep -qx "$name" covered.txt ||
				fail "examples/$name/README: \"$cmd\" is run by no test (tests/lib/examples.sh)"
			n=$((n + 1)) ;;
		esac
	done <cmds.txt
	# a README no other test runs has only remakes and placeholders: its
	# remakes run here
	if [ -n "$remake" ] && ! grep -qx "$name" covered.txt; then
		example_readme "$name"
		ran=$((ran + 1))
	fi
done
[ $n -ge 20 ] || fail "only $n example commands are run"
[ $ran -gt 0 ] || fail "no README remakes a committed input: update this test"
exit 0
