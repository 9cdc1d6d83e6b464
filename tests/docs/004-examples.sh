# Every example README's commands run as printed: each command in
# backquotes that starts with "sh " runs, exactly as written, from the
# example's folder after the README's set-up (make at the top of the tree),
# with the build's programs NOT on PATH (the scripts find the tree's
# build), and exits 0 leaving files in the out/ folder it names (a command
# that remakes a committed input, "sh make-mask.sh 40 >mask.in", the same
# bytes as the committed file).  The
# examples are copied beside a link build -> the build under test, so the
# source tree gets no out/ folders.  A README of a folder with a script
# must print its command and say to run make first; a command with a
# placeholder ("[SIZE]", array40: minutes and gigabytes, timed by make
# bench) is only checked to name a script that exists.
. "$TOP/tests/lib/common.sh"
built sample3D sample2D etch2d
mkdir -p tree/examples
ln -s "$BUILD" tree/build
# every example folder (they share examples/resists), without any out/
for d in "$TOP"/examples/*/; do
	name=$(basename "$d")
	mkdir "tree/examples/$name"
	for f in "$d"*; do
		[ "$(basename "$f")" = out ] || cp -R "$f" "tree/examples/$name/"
	done
done
n=0
for readme in "$TOP"/examples/*/README; do
	d=$(dirname "$readme")
	name=$(basename "$d")
	ls "$d"/*.sh >/dev/null 2>&1 || continue      # inputs only (resists)
	grep -o '`sh [^`]*`' "$readme" | tr -d '`' >cmds.txt
	[ -s cmds.txt ] || fail "examples/$name/README prints no command to run"
	grep -q 'After `make` at the top of the tree' "$readme" ||
		fail "examples/$name/README does not say to run make first"
	while IFS= read -r cmd; do
		script=$(printf '%s\n' "$cmd" | awk '{ print $2 }')
		[ -f "$d/$script" ] || fail "examples/$name/README: $cmd names no script there"
		case $cmd in *'['*) continue ;; esac
		(cd "tree/examples/$name" && PATH=/usr/bin:/bin sh -c "$cmd") >"$name.log" 2>&1 ||
			fail "examples/$name: \"$cmd\" failed: $(tail -n 3 "$name.log")"
		case $cmd in
		*'>'*)  # it remakes a committed input: the same bytes
			made=${cmd##*>}
			same "tree/examples/$name/$made" "$d/$made" ;;
		*)
			[ -n "$(find "tree/examples/$name/out" -type f 2>/dev/null | head -n 1)" ] ||
				fail "examples/$name: \"$cmd\" left nothing in out/" ;;
		esac
		n=$((n + 1))
	done <cmds.txt
done
[ $n -ge 20 ] || fail "only $n example commands ran"
exit 0
