#!/bin/sh
# tests/bench/estimate.sh [BUILD] - every program's work estimate (the
# seconds budget_check weighs against its hour, budget.h) beside the time
# the run then takes, for each program's main cost at a few sizes:
#   splat: the contact's image on grids of 1024^2 to 4096^2 points (the
#     image and its output), and arrays of contacts in 5 and 10 um windows
#     (the TCC pairs of -method hopkins, the source points of abbe);
#   bleach: the contact on 201^2 and 401^2 columns of 300 points with the
#     Gaussian bake, binary and -ascii output, and the chemically
#     amplified bake of examples/car-krf-lines on 51^2 and 101^2 columns;
#   etch: the ray-string engine on two rate grids and segment lengths,
#     fast marching on two rate grids;
#   measure: -force on 100 and 300 random triangles (the hole search);
#   contour -3D, conv -vtk, drawplot, pdraw (with and without -h): plot
#     files of growing size.
# Each runs on one core (SAMPLE3D_THREADS=1), since the estimate counts
# the seconds of one core, with SAMPLE3D_BIG=1 and SAMPLE3D_MEMORY=1 so
# that every budget_check prints its estimate ("about ... of work") and
# runs anyway; the estimates a run prints are summed.  Printed: the
# estimate, the CPU seconds (user + system), the wall seconds, and
# estimate / CPU (aim: between 0.5 and 2).  On a loaded machine the
# wall time is the CPU time stretched by the load; the CPU time is the
# figure the estimate aims at.  Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
B=$BUILD/bin
for p in splat bleach etch measure contour conv drawplot pdraw; do
	[ -x "$B/$p" ] || { echo "estimate: $B/$p not built"; exit 1; }
done
[ -x /usr/bin/time ] || { echo "estimate: /usr/bin/time missing"; exit 0; }
dir=$(mktemp -d "${TMPDIR:-/tmp}/estimatebench.XXXXXX")
trap 'rm -rf "$dir"' EXIT INT TERM
cd "$dir" || exit 1
E=$TOP/examples
export SAMPLE3D_THREADS=1 SAMPLE3D_BIG=1 SAMPLE3D_MEMORY=1 POSTSCRIPT=ON
unset DISPLAY

# run LABEL PROG ARGS...: runs it, prints the summed estimate beside the
# CPU and wall seconds
run() {
	label=$1
	shift
	/usr/bin/time -f "%e %U %S" -o t.txt "$@" </dev/null >/dev/null 2>err.txt ||
		{ echo "estimate: $label: failed: $(tail -n 1 err.txt)"; return; }
	# "about 1.5 s of work", "about 3.2 min of work", ... summed
	est=$(sed -n 's/.*: about \([0-9.e+-]*\) \([a-z]*\) of work.*/\1 \2/p' err.txt |
		awk '{ f = $2 == "min" ? 60 : $2 == "h" ? 3600 : $2 == "days" ? 86400 : 1
			s += $1 * f; n++ } END { if (n) printf "%.3g", s; else print "-" }')
	read -r wall user sys <t.txt
	awk -v l="$label" -v e="$est" -v w="$wall" -v u="$user" -v s="$sys" 'BEGIN {
		c = u + s
		r = e == "-" ? "-" : sprintf("%.2f", e / (c > 0.01 ? c : 0.01))
		printf "estimate: %-44s est %8s s  cpu %7.2f s  wall %7.2f s  est/cpu %s\n",
			l, e, c, w, r }'
}

# splat: the contact on large grids (the image and its output)
for g in 1024 2048 4096; do
	sed "s/^grid .*/grid $g $g/; /^contour/d; /^cutline/d" "$E/contact/mask.in" >m$g.in
	run "splat contact grid ${g}^2" "$B/splat" -o o.cont m$g.in
	rm -f o.cont
done
# splat: contact arrays (0.5 um contacts, 1 um pitch, NA 0.6, sigma 0.5)
# on a 101^2 grid: the orders' work
for L in 5 10; do
	awk -v L="$L" 'BEGIN { print "wavelength 0.365"; print "na 0.6"; print "sigma 0.5"
		print "background dark"; printf "window 0 %g 0 %g\n", L, L
		for (i = 0; i < L; i++) for (j = 0; j < L; j++)
			printf "rect %g %g %g %g\n", i + 0.25, j + 0.25, i + 0.75, j + 0.75
		print "grid 101 101" }' >a$L.in
	run "splat ${L}um array hopkins" "$B/splat" -method hopkins -o o.cont a$L.in
	run "splat ${L}um array abbe" "$B/splat" -method abbe -o o.cont a$L.in
done

# bleach: the contact's image on 201^2 and 401^2 columns, 300 points each
for g in 201 401; do
	sed "s/^grid .*/grid $g $g/; /^contour/d; /^cutline/d" "$E/contact/mask.in" >c$g.in
	"$B/splat" -q -o i$g.cont c$g.in 2>/dev/null || { echo "estimate: splat failed"; exit 1; }
	run "bleach contact ${g}^2x300 binary" "$B/bleach" -o r.bin i$g.cont "$E/contact/resist.in"
	rm -f r.bin
done
run "bleach contact 201^2x300 -ascii" "$B/bleach" -ascii -o r.txt i201.cont "$E/contact/resist.in"
rm -f r.txt
# the chemically amplified bake
K=$E/car-krf-lines
for g in 51 101; do
	sed "s/^grid .*/grid $g $g/; /^contour/d; /^cutline/d" "$K/mask.in" >k$g.in
	"$B/splat" -q -o k$g.cont k$g.in 2>/dev/null || { echo "estimate: splat failed"; exit 1; }
	run "bleach car-krf-lines ${g}^2 (CA bake)" "$B/bleach" -o k.bin k$g.cont "$K/resist.in"
	rm -f k.bin
done

# etch: the contact's rate on 51^2 columns of 300 points and 201^2 of 150
"$B/splat" -q -o i51.cont "$E/contact/mask.in" 2>/dev/null &&
	"$B/bleach" -q -o r51.bin i51.cont "$E/contact/resist.in" 2>/dev/null &&
	"$B/bleach" -q -nz 150 -o r201.bin i201.cont "$E/contact/resist.in" 2>/dev/null ||
	{ echo "estimate: the rate files failed"; exit 1; }
run "etch ray 51^2 -et 60" "$B/etch" -et 60 -o e.plot r51.bin
run "etch ray 51^2 -et 60 -seg 0.03" "$B/etch" -et 60 -seg 0.03 -o e.plot r51.bin
run "etch ray 201^2x150 -et 60 -seg 0.02 -dt 0.1" "$B/etch" -et 60 -seg 0.02 -dt 0.1 -o e.plot r201.bin
run "etch fmm 51^2 -et 60" "$B/etch" -et 60 -method fmm -o f51.plot r51.bin
run "etch fmm 201^2x150 -et 60" "$B/etch" -et 60 -method fmm -o f201.plot r201.bin

# measure -force on 100 and 300 random triangles in the unit box (the
# hole search through a surface crossing itself everywhere, the fuzzers'
# reproducers)
for n in 100 300; do
	run "measure -force hole, $n random triangles" "$B/measure" -force -rel 50 -hole 0.5 0.5 \
		-o m.dat "$TOP/tests/fuzz/regress/plot3d-measure-force-$n-random.3D"
done

# the plot programs: grids as images, 3D surfaces and 2D curves
grid() {
	awk -v n="$1" 'BEGIN { print -1, 1, -1, 1; print n, n
		for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
			x = -1 + 2 * i / (n - 1); y = -1 + 2 * j / (n - 1)
			printf "%.6g\n", sin(3 * x) * cos(2 * y) + x * x } }'
}
curves() {
	awk -v n="$1" 'BEGIN { print 0, 1, -1, 1; print 10
		for (c = 0; c < 10; c++) { print n
			for (i = 0; i < n; i++) print i / (n - 1), sin(20 * i / (n - 1) + c) * (1 - c / 20) } }'
}
for n in 201 501 1001; do
	grid $n >g$n.cont
	"$B/conv" -t -o g$n.3D g$n.cont 2>/dev/null ||
		{ echo "estimate: conv -t failed"; exit 1; }
	run "contour -3D ${n}^2 grid as triangles" "$B/contour" -3D -noplot g$n.3D
	run "conv -vtk ${n}^2 grid as triangles" "$B/conv" -vtk -o g.vtp g$n.3D
	run "pdraw ${n}^2 grid as triangles" "$B/pdraw" -noplot g$n.3D
done
grid 101 >g101.cont && "$B/conv" -t -o g101.3D g101.cont 2>/dev/null ||
	{ echo "estimate: conv -t failed"; exit 1; }
for n in 101 201; do
	run "pdraw -h ${n}^2 grid as triangles" "$B/pdraw" -h -noplot g$n.3D
done
for n in 10000 100000 1000000; do
	curves $n >c$n.2D
	run "drawplot 10 curves of $n points" "$B/drawplot" -noplot c$n.2D
done
exit 0
