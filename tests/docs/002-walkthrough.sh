#!/bin/sh
# The walk through the contact (docs/walkthrough.md) runs as written, twice in a row
# in one shell (once "mkdir /tmp/contact" failed the second
# time and $OLDPWD pointed elsewhere), leaving every picture it promises;
# and no man page's example calls a test tool (mkrate) or a build path.
. "$TOP/tests/lib/common.sh"
awk '/^## A walk through the contact example/ { on = 1 }
	on && /^```sh$/ { code = 1; next }
	code && /^```$/ { exit }
	code { print }' "$TOP/docs/walkthrough.md" >walk.sh
[ -s walk.sh ] || fail "no sh block in docs/walkthrough.md's walk-through"
grep -q /tmp/contact walk.sh || fail "the walk-through no longer works in /tmp/contact: update this test"
grep -q 'S=$T/build/bin' walk.sh || fail "the walk-through no longer takes the programs from \$T/build/bin: update this test"
# the build under test (build-asan, build-nox11, ...) stands for build/
sed -e "s|/tmp/contact|$PWD/contact|g" -e "s|S=\$T/build/bin|S=$BUILD/bin|" walk.sh >walk1.sh
cat walk1.sh walk1.sh >twice.sh
# run from the top of the tree, with the build's programs NOT on PATH
here=$PWD
(cd "$TOP" && unset T && PATH=/usr/bin:/bin sh -e "$here/twice.sh") >out.txt 2>&1 ||
	fail "the walk-through failed: $(tail -n 5 out.txt)"
for f in mask.ps solid.ps profile.ps cut.ps image.ps dataplot.ps curves.plot; do
	[ -s "contact/$f" ] || fail "the walk-through left no $f"
done
for page in "$TOP"/man/man1/*.1; do
	sed -n '/^\.SH EXAMPLES/,/^\.SH/p' "$page" | grep -q 'mkrate\|build/\|tests/' &&
		fail "$(basename "$page")'s examples use a test tool or a build path"
done
exit 0
