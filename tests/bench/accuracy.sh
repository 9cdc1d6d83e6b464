#!/bin/sh
# tests/bench/accuracy.sh [BUILD] - the figures of docs/accuracy.md (and
# the README's summary of them): for each case, the CDs at 10, 50 and 90 %
# of the resist at the grid "sample3D -accuracy 1" chooses, for each
# engine (fast marching; the ray-string, delooped so that measure reads
# it), against a reference refined by "sample3D -method fmm -accuracy 0.2"
# (each cd's three-level estimate under 0.2 %, at most 8 times the inputs'
# grids; "not reached" says so and the finest level stands in).  Prints
# one line per case and engine: the grid, the three CDs, the largest
# estimated err (% of its cd), the largest error against the reference
# (%: |cd - ref| / ref, and in nm), the wall seconds and the CPU seconds
# (user + system of every program the run started; the runs are nice'd,
# ACCURACY_NICE, default 10); then the CDs of every level each run
# solved.  Asserts nothing (the times and the references'
# levels depend on the machine's load; tests/accuracy holds the
# estimator, tests/sample3D/040 the driver).
#
# Environment: ACCURACY_CASES, the cases (default all, cheapest first):
# car-arf contact-bake contact-nobake dense1.25-bake dense1.0-bake
# dense1.25-nobake dense1.0-nobake highna-m0.3 highna-p0.3 ca-lines
# clear-lines-2; ACCURACY_ENGINES (default "fmm ray");
# ACCURACY_CACHE=DIR keeps each run's directory there and reuses a
# finished one (a run is finished when DIR/CASE-RUN/status exists);
# ACCURACY_REF, the reference's -accuracy (default 0.2; none: no
# reference run, no "vs ref").
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
[ -x "$BUILD/bin/sample3D" ] || { echo "accuracy: $BUILD/bin/sample3D not built"; exit 1; }
PATH=$BUILD/bin:$PATH
E=$TOP/examples
if [ -n "${ACCURACY_CACHE:-}" ]; then
	mkdir -p "$ACCURACY_CACHE" && tmp=$(cd "$ACCURACY_CACHE" && pwd) || exit 1
else
	tmp=$(mktemp -d "${TMPDIR:-/tmp}/accbench.XXXXXX")
	trap 'rm -rf "$tmp"' EXIT INT TERM
fi

# dense SIZE: examples/contact's optics, a 4 um cell holding 2 x 2 square
# holes of SIZE um at 2.0 um pitch (the window repeats it: an endless
# array); the hole measured is the one at (1, 1)
dense() {
	sed '/^rect /d; /^window /d; /^cutline/d; /^grid /d; /^contour /d' "$E/contact/mask.in"
	echo "window -2 2 -2 2"
	echo "grid 41 41"
	echo "contour image.cont"
	awk -v s="$1" 'BEGIN { h = s / 2
		for (x = -1; x <= 1; x += 2) for (y = -1; y <= 1; y += 2) print "rect", x - h, y - h, x + h, y + h }'
}

# setcase NAME: writes $tmp/NAME.in (the mask) and sets resist, et, m
# (measure's arguments)
setcase() {
	defocus="" mask="" m="-rel 10,50,90 -hole 0 0" et=60
	case $1 in
	car-arf) mask=$E/car-arf-contact/mask.in resist=$E/car-arf-contact/resist.in et=20 ;;
	contact-bake) mask=$E/contact/mask.in resist=$E/contact/resist.in ;;
	contact-nobake) mask=$E/contact/mask.in resist=$E/contact/resist-nobake.in ;;
	dense1.25-bake|dense1.0-bake) resist=$E/contact/resist.in m="-rel 10,50,90 -hole 1 1" ;;
	dense1.25-nobake|dense1.0-nobake) resist=$E/contact/resist-nobake.in m="-rel 10,50,90 -hole 1 1" ;;
	highna-m0.3) mask=$E/contact-highna/mask.in resist=$E/contact-highna/resist.in defocus=-0.3 ;;
	highna-p0.3) mask=$E/contact-highna/mask.in resist=$E/contact-highna/resist.in defocus=0.3 ;;
	ca-lines) mask=$E/ca-lines/mask.in resist=$E/ca-lines/resist.in et=120 m="-rel 10,50,90 -line 0 0 x" ;;
	clear-lines-2) mask=$E/clear-lines-2/mask.in resist=$E/clear-lines-2/resist.in et=10 m="-rel 10,50,90 -line 0 0 x" ;;
	*) echo "accuracy: no case $1"; return 1 ;;
	esac
	case $1 in
	dense*) s=${1#dense}; dense "${s%-*}" >"$tmp/$1.in" ;;
	# the mask with the case's defocus (a statement of splat(5))
	*) { cat "$mask"; [ -z "$defocus" ] || echo "defocus $defocus"; } >"$tmp/$1.in" ;;
	esac
}

# run CASE RUN ACCURACY ENGINE-OPTIONS...: sample3D -accuracy in
# $tmp/CASE-RUN (table.txt, err.txt, status "exit seconds"), unless there
prun() {
	c=$1 r=$2 acc=$3
	shift 3
	d=$tmp/$c-$r
	[ -s "$d/status" ] && return 0
	rm -rf "$d" && mkdir -p "$d" && cd "$d" || return 1
	s=$(date +%s)
	times >times0
	st=0
	nice -n "${ACCURACY_NICE:-10}" sample3D -q -if "$tmp/$c.in" -bf "$resist" -et "$et" -last \
		-measure "$m" -accuracy "$acc" "$@" >table.txt 2>err.txt || st=$?
	times >times1
	echo "$st $(($(date +%s) - s)) $(awk -v a="$(cputime times0)" -v b="$(cputime times1)" 'BEGIN { printf "%.1f", b - a }')" >status
	# the level tables stay; the large files go
	rm -f rval.3D* curves.plot* image.cont image.stack ./*.ps mxyz.solid.3D
	cd "$tmp" || return 1
}

# cputime FILE: the user and system CPU seconds of the shell's finished
# children in FILE, the output of the shell's times (run in the shell
# itself: a command substitution's subshell has no children of its own)
cputime() {
	awk 'NR == 2 { n = split($1 " " $2, f, " "); t = 0
		for (i = 1; i <= n; i++) { split(f[i], a, "m"); sub(/s$/, "", a[2]); t += 60 * a[1] + a[2] }
		printf "%.2f\n", t }' "$1"
}

# cds TABLE: "cd10 cd50 cd90"
cds() { awk '!/^#/ { printf "%s%s", n++ ? " " : "", $2 } END { print "" }' "$1"; }
# vsref TABLE REF: the largest |cd - ref| / ref, percent, and |cd - ref| in nm
vsref() {
	paste -d' ' "$1" "$2" | awk -v nc="$(head -n 1 "$1" | awk '{ print NF - 1 }')" '!/^#/ {
		a = $2; b = $(nc + 2); d = a - b; if (d < 0) d = -d
		if (b > 0 && 100 * d / b > m) m = 100 * d / b; if (d > n) n = d }
		END { printf "%.2f %.1f\n", m, 1000 * n }'
}
# maxerr TABLE: the err column's largest value over its cd, percent
maxerr() { awk '!/^#/ && $2 > 0 { e = 100 * $NF / $2; if (e > m) m = e } END { printf "%.2f\n", m }' "$1"; }
# last DIR: the table of the finest level DIR solved (not a group's
# estimate, NXxNYxNZ.xy.dat or .z.dat)
last() { ls "$1"/accuracy/*.dat 2>/dev/null | awk -F/ '{ g = $NF; sub(/\.dat$/, "", g); if (g ~ /\./) next; split(g, n, "x")
	v = n[1] * n[2] * n[3]; if (v > best) { best = v; f = $0 } } END { print f }'; }
grid() { basename "$1" .dat; }
note() { # note DIR: what the status says
	case $(cut -d' ' -f1 "$1/status") in
	0) ;;
	*) printf ' (%s)' "$(grep -v ': warning' "$1/err.txt" | tail -n 1 | sed 's/^sample3D: //' | cut -c1-60)" ;;
	esac
}

printf '%-16s %-4s %-12s %-30s %7s %13s %6s %7s\n' case run grid "cd 10/50/90 % (um)" "err(%)" "vs ref % nm" s "cpu s"
for c in ${ACCURACY_CASES:-car-arf contact-bake contact-nobake dense1.25-bake dense1.0-bake dense1.25-nobake dense1.0-nobake highna-m0.3 highna-p0.3 ca-lines clear-lines-2}; do
	setcase "$c" || continue
	rt=""
	if [ "${ACCURACY_REF:-0.2}" != none ]; then
		prun "$c" ref "${ACCURACY_REF:-0.2}" -method fmm
		rd=$tmp/$c-ref
		rt=$(last "$rd")
		if [ -z "$rt" ]; then
			echo "$c ref: failed: $(tail -n 1 "$rd/err.txt")"
			continue
		fi
		printf '%-16s %-4s %-12s %-30s %7s %13s %6s %7s%s\n' "$c" ref "$(grid "$rt")" "$(cds "$rt")" \
			"$(maxerr "$rt")" - "$(cut -d' ' -f2 "$rd/status")" "$(cut -d' ' -f3 "$rd/status")" "$(note "$rd")"
	fi
	for e in ${ACCURACY_ENGINES:-fmm ray}; do
		case $e in fmm) eo="-method fmm" ;; *) eo="-method ray -deloop" ;; esac
		# shellcheck disable=SC2086 # eo is a list of words on purpose
		prun "$c" "$e" 1 $eo
		d=$tmp/$c-$e
		t=$d/table.txt
		[ -s "$t" ] || t=$(last "$d")
		if [ -z "$t" ]; then
			echo "$c $e: failed: $(tail -n 1 "$d/err.txt")"
			continue
		fi
		printf '%-16s %-4s %-12s %-30s %7s %13s %6s %7s%s\n' "$c" "$e" "$(grid "$(last "$d")")" "$(cds "$t")" \
			"$(maxerr "$t")" "$([ -n "$rt" ] && vsref "$t" "$rt" || echo -)" "$(cut -d' ' -f2 "$d/status")" \
			"$(cut -d' ' -f3 "$d/status")" "$(note "$d")"
	done
	# every level of every run
	for r in ref ${ACCURACY_ENGINES:-fmm ray}; do
		ls "$tmp/$c-$r"/accuracy/*.dat 2>/dev/null | awk -F/ '{ g = $NF; sub(/\.dat$/, "", g); if (g ~ /\./) next; split(g, n, "x")
			print n[1] * n[2] * n[3], $0 }' | sort -n | while read -r _ t; do
			printf '%-16s %-4s %-12s %-30s %7s\n' "$c" "$r:" "$(grid "$t")" "$(cds "$t")" \
				"$(head -n 1 "$t" | grep -q ' err$' && maxerr "$t")"
		done
	done
	[ -n "${ACCURACY_CACHE:-}" ] || rm -rf "${tmp:?}/$c-ref" "${tmp:?}/$c-fmm" "${tmp:?}/$c-ray"
done
