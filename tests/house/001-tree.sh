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
layers="system numerics geometry drawing formats"
rank() { n=0; for l in $layers; do [ "$l" = "$1" ] && { echo $n; return; }; n=$((n + 1)); done; echo 99; }
bad=0
# 1. library layers
for f in src/lib/*/*.[ch]; do
	l=${f#src/lib/}; l=${l%%/*}; r=$(rank "$l")
	[ "$r" = 99 ] && { echo "unknown library layer: $f"; bad=1; continue; }
	for h in $(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$f"); do
		hf=$(ls src/lib/*/"$h" 2>/dev/null | head -n 1)
		[ -n "$hf" ] || { echo "$f includes $h, which is not in the library"; bad=1; continue; }
		hl=${hf#src/lib/}; hl=${hl%%/*}
		[ "$(rank "$hl")" -le "$r" ] || { echo "$f ($l) includes $h from the layer above ($hl)"; bad=1; }
	done
done
# 2. programs include only their own headers and the library's
for d in src/*/; do
	d=${d%/}; [ "$d" = src/lib ] && continue
	for f in $(find "$d" -name '*.[ch]'); do
		for h in $(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$f"); do
			[ -n "$(find "$d" -name "$h")" ] && continue
			[ -n "$(ls src/lib/*/"$h" 2>/dev/null)" ] && continue
			echo "$f includes $h, neither its program's nor the library's"; bad=1
		done
	done
done
# 3. no reference cycle inside a folder (the build's objects)
command -v nm >/dev/null 2>&1 || { echo "nm (binutils) is not installed" >&2; exit 77; }
for d in $(cd "$BUILD" && find src -name '*.o' | sed 's,/[^/]*$,,' | sort -u); do
	for o in "$BUILD/$d"/*.o; do
		b=${o##*/}; b=${b%.o}
		nm "$o" | awk -v f="$b" '$2 ~ /^[TDBR]$/ { print "D", $3, f } $1 == "U" { print "U", $2, f }'
	done | awk -v dir="$d" '
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
for f in $(find src -name '*.[ch]' ! -name num_pow10.h); do
	n=$(wc -l < "$f")
	[ "$n" -le 1000 ] || { echo "$f: $n lines (at most 1000)"; bad=1; }
	awk -v f="$f" '/^\{/ { s = FNR } /^\}/ && s { if (FNR - s - 1 > 150) { printf "%s:%d: a function of %d lines (at most 150)\n", f, s, FNR - s - 1; bad = 1 } s = 0 } END { exit bad }' "$f" || bad=1
done
[ "$bad" = 0 ] || fail "the tree breaks the rules above"
