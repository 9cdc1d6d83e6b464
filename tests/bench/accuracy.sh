#!/bin/sh
# tests/bench/accuracy.sh [BUILD] - the figures of docs/accuracy.md: for
# each case, the CDs at 10, 50 and 90 % of the resist at the grid
# "sample3D -accuracy 1" chooses, for each engine (fast marching; the
# ray-string, delooped so that measure reads it), against a reference
# refined until it moves less than 0.2 % (sample3D -method fmm -accuracy
# 0.2: each level's CDs within 0.2 % of the level before, at most 8 times
# the inputs' grids; "not reached" says so).  The fast-marching choice is
# read off the reference's own levels (accuracy/*.dat: the first whose
# every err is within 1 % of its cd, which is what -accuracy 1 stops at),
# so the reference costs no second fast-marching run.  Prints one line per
# case and engine: the grid, the three CDs, the largest estimated err
# (% of its cd), the largest error against the reference (%), the wall
# time; then the CDs of every level each run solved.
# Asserts nothing.
#
# Environment: ACCURACY_CASES, the cases to run (default all, cheapest
# first): ca-lines clear-lines-2 contact-bake contact-nobake
# highna-m0.3 highna-p0.3 car-arf.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
[ -x "$BUILD/bin/sample3D" ] || { echo "accuracy: $BUILD/bin/sample3D not built"; exit 1; }
PATH=$BUILD/bin:$PATH
E=$TOP/examples
tmp=$(mktemp -d "${TMPDIR:-/tmp}/accbench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM

# case NAME: sets mask, resist, et, m (measure's arguments), defocus
setcase() {
	defocus=""
	case $1 in
	ca-lines) mask=$E/ca-lines/mask.in resist=$E/ca-lines/resist.in et=120 m="-rel 10,50,90 -line 0 0 x" ;;
	clear-lines-2) mask=$E/clear-lines-2/mask.in resist=$E/clear-lines-2/resist.in et=10 m="-rel 10,50,90 -line 0 0 x" ;;
	contact-bake) mask=$E/contact/mask.in resist=$E/contact/resist.in et=60 m="-rel 10,50,90 -hole 0 0" ;;
	contact-nobake) mask=$E/contact/mask.in resist=$E/contact/resist-nobake.in et=60 m="-rel 10,50,90 -hole 0 0" ;;
	highna-m0.3) mask=$E/contact-highna/mask.in resist=$E/contact-highna/resist.in et=60 m="-rel 10,50,90 -hole 0 0" defocus=-0.3 ;;
	highna-p0.3) mask=$E/contact-highna/mask.in resist=$E/contact-highna/resist.in et=60 m="-rel 10,50,90 -hole 0 0" defocus=0.3 ;;
	car-arf) mask=$E/car-arf-contact/mask.in resist=$E/car-arf-contact/resist.in et=20 m="-rel 10,50,90 -hole 0 0" ;;
	*) echo "accuracy: no case $1"; return 1 ;;
	esac
}

# run DIR ACCURACY ENGINE-OPTIONS...: sample3D -accuracy in DIR; prints
# the wall seconds; the table in DIR/table.txt, status in DIR/status
run() {
	d=$1 acc=$2
	shift 2
	mkdir -p "$d" && cd "$d" || return 1
	# the mask with the case's defocus (a statement of splat(5))
	{ cat "$mask"; [ -z "$defocus" ] || echo "defocus $defocus"; } >mask.in
	s=$(date +%s.%N)
	st=0
	sample3D -q -if mask.in -bf "$resist" -et "$et" -last -measure "$m" -accuracy "$acc" "$@" \
		>table.txt 2>err.txt || st=$?
	echo $st >status
	awk -v s="$s" -v e="$(date +%s.%N)" 'BEGIN { printf "%.0f\n", e - s }'
	cd "$tmp" || return 1
}

# cds TABLE: "cd10 cd50 cd90"
cds() { awk '!/^#/ { printf "%s%s", n++ ? " " : "", $2 } END { print "" }' "$1"; }
# errmax TABLE REF: the largest |cd - ref| / ref, percent
errmax() {
	paste -d' ' "$1" "$2" | awk -v nc="$(head -n 1 "$1" | awk '{ print NF - 1 }')" '!/^#/ {
		a = $2; b = $(nc + 2); if (b > 0) { d = 100 * (a - b) / b; if (d < 0) d = -d; if (d > m) m = d } }
		END { printf "%.2f\n", m }'
}
# maxerr TABLE: the err column's largest value over its cd, percent
maxerr() { awk '!/^#/ && $2 > 0 { e = 100 * $NF / $2; if (e > m) m = e } END { printf "%.2f\n", m }' "$1"; }
# first1 DIR: DIR/accuracy's first level table whose every err is within 1 %
first1() {
	for t in $(ls -tr "$1"/accuracy/*.dat); do
		head -n 1 "$t" | grep -q ' err$' || continue
		awk '!/^#/ && $NF > 0.01 * $2 { bad = 1 } END { exit bad }' "$t" && { echo "$t"; return; }
	done
}
grid() { basename "$1" .dat; }

printf '%-15s %-8s %-12s %-28s %8s %8s %6s\n' case engine grid "cd 10/50/90 % (um)" "err(%)" "vs ref" "s"
for c in ${ACCURACY_CASES:-ca-lines clear-lines-2 contact-bake contact-nobake highna-m0.3 highna-p0.3 car-arf}; do
	setcase "$c" || continue
	t=$(run "$tmp/$c-ref" 0.2 -method fmm)
	ref=$tmp/$c-ref/table.txt
	rt=$(ls -t "$tmp/$c-ref"/accuracy/*.dat 2>/dev/null | head -n 1)
	if [ ! -s "$ref" ]; then
		echo "accuracy: $c: the reference failed: $(tail -n 1 "$tmp/$c-ref/err.txt")"
		continue
	fi
	note=""
	[ "$(cat "$tmp/$c-ref/status")" = 0 ] || note=" (0.2 % not reached)"
	printf '%-15s %-8s %-12s %-28s %8s %8s %6s%s\n' "$c" ref "$(grid "$rt")" "$(cds "$ref")" \
		"$(maxerr "$ref")" - "$t" "$note"
	f=$(first1 "$tmp/$c-ref")
	if [ -n "$f" ]; then
		printf '%-15s %-8s %-12s %-28s %8s %8s %6s\n' "$c" fmm "$(grid "$f")" "$(cds "$f")" \
			"$(maxerr "$f")" "$(errmax "$f" "$ref")" -
	else
		echo "$c fmm: 1 % not reached within the reference's levels"
	fi
	t=$(run "$tmp/$c-ray" 1 -method ray -deloop)
	rr=$tmp/$c-ray/table.txt
	if [ -s "$rr" ]; then
		note=""
		[ "$(cat "$tmp/$c-ray/status")" = 0 ] || note=" (1 % not reached)"
		printf '%-15s %-8s %-12s %-28s %8s %8s %6s%s\n' "$c" ray "$(grid "$(ls -t "$tmp/$c-ray"/accuracy/*.dat | head -n 1)")" \
			"$(cds "$rr")" "$(maxerr "$rr")" "$(errmax "$rr" "$ref")" "$t" "$note"
	else
		echo "$c ray: failed: $(tail -n 1 "$tmp/$c-ray/err.txt")"
	fi
	# every level of both runs (docs/accuracy.md's tables of levels)
	for r in ref ray; do
		for t in $(ls -tr "$tmp/$c-$r"/accuracy/*.dat 2>/dev/null); do
			printf '%-15s %-8s %-12s %-28s\n' "$c" "$r-level" "$(grid "$t")" "$(cds "$t")"
		done
	done
	rm -rf "${tmp:?}/$c-ref" "${tmp:?}/$c-ray"
done
