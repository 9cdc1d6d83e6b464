#!/bin/sh
# tests/bench/stack.sh [BUILD] - the cost of the image inside the resist:
# splat writing an 11-plane image stack against the single
# image, for the 1.25 um contact of examples/contact (51 x 51, NA 0.28,
# 0.7 um of resist of index 1.68) and the 10 um x 10 um cell of
# tests/bench/splat.sh (201 x 201, sigma 0.5, also with defocus and coma);
# and bleach on the contact from the stack against the single image, for
# each bake (the aim: within 1.5x).  Best of 3 samples of CPU
# time (the machine is shared), each of several runs for the short ones.
# Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
bin=$BUILD/bin
[ -x "$bin/splat" ] && [ -x "$bin/bleach" ] || { echo "stack: splat or bleach not built"; exit 1; }
dir=$(mktemp -d "${TMPDIR:-/tmp}/stackbench.XXXXXX")
trap 'rm -rf "$dir"' EXIT INT TERM
cd "$dir" || exit 1
resist='resist thickness 0.7 index 1.68 planes 11'
cp "$TOP/examples/contact/mask.in" contact.in
{ cat contact.in; echo "$resist"; } >contact-stack.in
cell='window 0 10 0 10
sigma 0.5
rect 1 1 3 8
rect 4 1 5 9
rect 6 2 9 3
rect 6 5 9 9 0.5 180
grid 201 201'
printf '%s\n' "$cell" >cell.in
printf '%s\n%s\n' "$cell" "$resist" >cell-stack.in
printf '%s\ndefocus 1\ncoma 0.4 field 1 0\n' "$cell" >cell-aberr.in
printf '%s\ndefocus 1\ncoma 0.4 field 1 0\n%s\n' "$cell" "$resist" >cell-aberr-stack.in
best() { # best N CMD...: best of 3 of the CPU time (user + system) of N
	 # runs of CMD, per run, seconds (wall time without /usr/bin/time)
	n=$1
	shift
	b=
	for r in 1 2 3; do
		if [ -x /usr/bin/time ]; then
			/usr/bin/time -f "%U %S" -o t.txt sh -c 'n=$1; shift; i=0
				while [ $i -lt $n ]; do "$@" || exit 1; i=$((i + 1)); done' sh "$n" "$@" ||
				return 1
			d=$(awk -v n="$n" '{ print ($1 + $2) / n }' t.txt)
		else
			t0=$(date +%s.%N)
			"$@" || return 1
			t1=$(date +%s.%N)
			d=$(awk -v a="$t0" -v c="$t1" 'BEGIN { print c - a }')
		fi
		b=$(awk -v d="$d" -v m="$b" 'BEGIN { if (m != "" && m < d) d = m; print d }')
	done
	echo "$b"
}
for c in contact cell cell-aberr; do
	n=1
	[ $c = contact ] && n=20
	t1=$(best $n "$bin/splat" -q -o one.cont $c.in) || { echo "splat $c failed"; exit 1; }
	tn=$(best $n "$bin/splat" -q -o $c.stack $c-stack.in) || { echo "splat $c-stack failed"; exit 1; }
	awk -v c="$c" -v a="$t1" -v b="$tn" 'BEGIN {
		printf "splat %-11s image %7.3f s, 11-plane stack %7.3f s (%.2fx)\n", c, a, b, b / a }'
	[ $c = contact ] && cp one.cont contact.cont
done
sed 's/^bake diffusion/bake3d diffusion/' "$TOP/examples/contact/resist.in" >resist3d.in
cp "$TOP/examples/contact/resist.in" resistz.in
cp "$TOP/examples/contact/resist-nobake.in" resist0.in
for r in resist3d:bake3d resistz:"bake in z" resist0:"no bake"; do
	f=${r%%:*} label=${r#*:}
	t1=$(best 5 "$bin/bleach" -q -o a.bin contact.cont $f.in) || { echo "bleach failed"; exit 1; }
	tn=$(best 5 "$bin/bleach" -q -o b.bin contact.stack $f.in) || { echo "bleach on the stack failed"; exit 1; }
	awk -v l="$label" -v a="$t1" -v b="$tn" 'BEGIN {
		printf "bleach contact 51x51x300, %-11s image %6.3f s, stack %6.3f s (%.2fx)\n", l, a, b, b / a }'
done
