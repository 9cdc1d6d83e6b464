# The shape of the tree, as HACKING.md states it:
# - the library's layers (src/lib/<layer>/) include only headers of their own
#   layer or of layers below: system < numerics < geometry < drawing < formats;
# - a program folder includes only its own headers and the library's;
# - no cycle of symbol references between the object files of one folder
#   (file A uses a symbol that B defines, and B, through any chain, one of A's),
#   read off the build's objects with nm, so calls through a shared header count;
# - no source file over 1,000 lines (generated tables apart) and no function
#   over 150 lines (from the opening "{" at the start of a line to its "}").
# Against: the rules themselves; exact.
. "$SRCDIR/tests/lib/common.sh"
cd "$SRCDIR" || exit 1
# Each check is one awk (one nm per folder) over every file, not a few
# processes a file or an include: the rules are the same.
# every file of the library, src/lib/LAYER/NAME, one a line: where an
# include's NAME is (the first layer in name order, as a glob lists them)
libfiles=$(ls -d src/lib/*/*)
bad=0
# 1. library layers
# shellcheck disable=SC2046 # the file lists
awk -v libs="$libfiles" -v layers="system numerics geometry drawing formats" '
BEGIN {
	n = split(layers, L, " "); for (i = 1; i <= n; i++) rank[L[i]] = i - 1
	n = split(libs, F, "\n")
	for (i = 1; i <= n; i++) { k = split(F[i], a, "/"); if (!(a[k] in where)) where[a[k]] = a[3] }
}
FNR == 1 { split(FILENAME, a, "/"); l = a[3]; r = (l in rank) ? rank[l] : 99
	if (r == 99) print "unknown library layer: " FILENAME
	if (r == 99) bad = 1 }
r != 99 && /^#include "[^"]*"/ {
	h = $0; sub(/^#include "/, "", h); sub(/".*/, "", h)
	if (!(h in where)) { print FILENAME " includes " h ", which is not in the library"; bad = 1; next }
	hr = (where[h] in rank) ? rank[where[h]] : 99
	if (hr > r) { print FILENAME " (" l ") includes " h " from the layer above (" where[h] ")"; bad = 1 }
}
END { exit bad }' src/lib/*/*.[ch] || bad=1
# 2. programs include only their own headers and the library's
for d in src/*/; do
	d=${d%/}; [ "$d" = src/lib ] && continue
	# shellcheck disable=SC2046 # the file list
	awk -v own="$(find "$d")" -v libs="$libfiles" '
	BEGIN {
		n = split(own, F, "\n"); for (i = 1; i <= n; i++) { k = split(F[i], a, "/"); ok[a[k]] }
		n = split(libs, F, "\n"); for (i = 1; i <= n; i++) { k = split(F[i], a, "/"); ok[a[k]] }
	}
	/^#include "[^"]*"/ {
		h = $0; sub(/^#include "/, "", h); sub(/".*/, "", h)
		if (!(h in ok)) { print FILENAME " includes " h ", neither its program'"'"'s nor the library'"'"'s"; bad = 1 }
	}
	END { exit bad }' $(find "$d" -name '*.[ch]') </dev/null || bad=1
done
# 3. no reference cycle inside a folder (the build's objects)
command -v nm >/dev/null 2>&1 || { echo "nm (binutils) is not installed" >&2; exit 77; }
for d in $(cd "$BUILD" && find src -name '*.o' | sed 's,/[^/]*$,,' | sort -u); do
	# nm -A: "DIR/FILE.o:VALUE TYPE NAME", "DIR/FILE.o:    U NAME"
	nm -A "$BUILD/$d"/*.o | awk '{ f = $1; sub(/\.o:.*$/, "", f); sub(/^.*\//, "", f) }
		$2 ~ /^[TDBR]$/ { print "D", $3, f } $2 == "U" { print "U", $3, f }' | awk -v dir="$d" '
	$1 == "D" { def[$2] = $3 }
	$1 == "U" { use[++n] = $2; user[n] = $3 }
	END {
		for (i = 1; i <= n; i++)
			if ((use[i] in def) && def[use[i]] != user[i])
				edge[user[i] SUBSEP def[use[i]]] = 1
		for (e in edge) { split(e, p, SUBSEP); nodes[p[1]]; nodes[p[2]] }
		# Warshall closure; a node that reaches itself is on a cycle
		for (e in edge) reach[e] = 1
		for (k in nodes) for (i in nodes) if ((i SUBSEP k) in reach)
			for (j in nodes) if ((k SUBSEP j) in reach) reach[i SUBSEP j] = 1
		for (i in nodes) if ((i SUBSEP i) in reach) { printf "%s: %s.o is on a reference cycle:", dir, i
			for (j in nodes) if (j != i && ((i SUBSEP j) in reach) && ((j SUBSEP i) in reach)) printf " %s", j
			print ""; bad = 1 }
		exit bad
	}' || bad=1
done
# 4. file and function lengths
# shellcheck disable=SC2046 # the file list
awk 'FNR == 1 { if (prev != "" && lines > 1000) { printf "%s: %d lines (at most 1000)\n", prev, lines; bad = 1 }
		prev = FILENAME; s = 0 }
	{ lines = FNR }
	/^\{/ { s = FNR }
	/^\}/ && s { if (FNR - s - 1 > 150) { printf "%s:%d: a function of %d lines (at most 150)\n", FILENAME, s, FNR - s - 1; bad = 1 } s = 0 }
	END { if (prev != "" && lines > 1000) { printf "%s: %d lines (at most 1000)\n", prev, lines; bad = 1 }
		exit bad }' $(find src -name '*.[ch]' ! -name num_pow10.h) || bad=1
[ "$bad" = 0 ] || fail "the tree breaks the rules above"
