#!/bin/sh
# etch -last writes only the final set (a long run would otherwise write a set
# per print time with no way to skip them): for the ray-string and the
# fast-marching engines, curves.plot, curves.plot.2D and the cut of
# "-pt 0.25 -last" are byte for byte the last set of the same run without
# -last (sets are separated by one blank line); -last with the cell
# methods is a usage error.
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
$MKRATE -o rate.bin 21 21 11 -1 1 -1 1 -0.5 0 '0.1 + 0.8 * exp(-(x^2 + y^2) / 0.2)' ||
	fail "mkrate"
# (the '#' labels line heads the file, not a set: plot3d(5); -last keeps it)
lastset() { awk '/^#/ { next } NF == 0 { n = 0; delete l; next } { l[++n] = $0 } END { for (i = 1; i <= n; i++) print l[i] }' "$1"; }
for m in ray fmm; do
	etch -q -method $m -et 1 -pt 0.25 -cut y 0 rate.bin || fail "etch -method $m"
	for f in curves.plot curves.plot.2D curves.cut; do
		{ grep '^#' $f; lastset $f; } >$m-$f.want
	done
	[ "$(grep -c '^$' curves.plot)" -eq 3 ] || fail "$m: expected 4 sets without -last"
	etch -q -method $m -et 1 -pt 0.25 -cut y 0 -last rate.bin || fail "etch -method $m -last"
	[ "$(grep -c '^$' curves.plot)" -eq 0 ] || fail "$m -last: more than one set"
	for f in curves.plot curves.plot.2D curves.cut; do
		same $m-$f.want $f
	done
done
etch -method cell -et 1 -last rate.bin >/dev/null 2>err.txt && fail "-last -method cell accepted"
[ "$(head -n 1 err.txt)" = "etch: -last goes with -method ray or fmm" ] || fail "$(head -n 1 err.txt)"
exit 0
