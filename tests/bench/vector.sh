#!/bin/sh
# tests/bench/vector.sh [BUILD] - the cost of splat's vector imaging
# (imaging vector, through the film of splat -bf) against the scalar image
# stack of the same grid, source and planes: the target is at most 3x.
# Each case is timed four ways: vector unpolarised (five FFT fields a
# source point and plane), vector TE (three), the scalar stack by the
# same source points (-method abbe) and the scalar stack as splat chooses
# it (-method auto, the exact Hopkins sum where it is quicker).  Cases:
# 45 nm lines at NA 1.35 in water (annular, 21 planes), a 60 nm contact
# at NA 1.2 in water (quadrupole, 21 planes, 41 x 41), an attenuated PSM
# at NA 0.93 dry on a BARC (sigma 0.7), and the 0.5 um contact at i-line
# NA 0.6 in 1 um of resist on silicon (41 planes, 41 x 41).  Best of 3
# samples of CPU time on one thread (the machine is shared), each of 20
# runs for the short cases.  Asserts nothing.
set -u
TOP=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-${BUILD:-build}}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
bin=$BUILD/bin
[ -x "$bin/splat" ] || { echo "vector: splat not built"; exit 1; }
dir=$(mktemp -d "${TMPDIR:-/tmp}/vectorbench.XXXXXX")
trap 'rm -rf "$dir"' EXIT INT TERM
cd "$dir" || exit 1
film() { # ambient, wavelength, resist thickness, layer line, substrate
	printf 'wavelength %s\nambient %s\nresist thickness %s index 1.7 dill 0 1.1 0.03\n%s\n' \
		"$2" "$1" "$3" "$4"
	printf 'substrate %s\ndose 30\ndevelop mack 0.1 0.0001 0.5 5\n' "$5"
}
film 1.44 0.193 0.1 'layer 0.078 1.82 0.34' '0.88 2.78' >wet.res
film 1 0.193 0.1 'layer 0.078 1.82 0.34' '0.88 2.78' >dry.res
film 1 0.365 1 '' '6.41 2.62' >iline.res
cat >lines.in <<'IN'
wavelength 0.193
immersion 1.44
na 1.35
annular 0.7 0.9
resist thickness 0.1 index 1.7 planes 21
window 0 0.09 -0.045 0.045
background clear
rect 0.0225 -0.045 0.0675 0.045 0 0
grid 19 19
IN
cat >contact.in <<'IN'
wavelength 0.193
immersion 1.44
na 1.2
quadrupole 0.6 0.2
resist thickness 0.1 index 1.7 planes 21
window -0.1 0.1 -0.1 0.1
background dark
rect -0.03 -0.03 0.03 0.03
grid 41 41
IN
cat >psm.in <<'IN'
wavelength 0.193
na 0.93
sigma 0.7
resist thickness 0.1 index 1.7 planes 21
window 0 0.26 -0.13 0.13
background 0.245 180
rect 0 -0.13 0.13 0.13
grid 27 27
IN
cat >iline.in <<'IN'
wavelength 0.365
na 0.6
sigma 0.5
resist thickness 1 index 1.7 planes 41
window -1.2 1.2 -1.2 1.2
background dark
rect -0.25 -0.25 0.25 0.25
grid 41 41
IN
best() { # best N CMD...: best of 3 of the CPU time (user + system) of N
	 # runs of CMD, per run, seconds
	n=$1
	shift
	b=
	for r in 1 2 3; do
		/usr/bin/time -f "%U %S" -o t.txt sh -c 'n=$1; shift; i=0
			while [ $i -lt $n ]; do "$@" 2>/dev/null || exit 1; i=$((i + 1)); done' \
			sh "$n" "$@" || return 1
		d=$(awk -v n="$n" '{ print ($1 + $2) / n }' t.txt)
		b=$(awk -v d="$d" -v m="$b" 'BEGIN { if (m != "" && m < d) d = m; print d }')
	done
	echo "$b"
}
echo "vector: CPU seconds, one thread; ratio = vector / scalar stack by the same source points"
printf '%-8s %9s %9s %9s %9s %10s %8s\n' case unpol te abbe auto unpol/abbe te/abbe
for c in lines:wet contact:wet psm:dry iline:iline; do
	name=${c%%:*}
	res=${c#*:}.res
	{ cat $name.in; echo "imaging vector"; } >v.in
	{ cat $name.in; echo "imaging vector"; echo "polarization te"; } >te.in
	n=20
	[ $name = iline ] && n=1
	tu=$(best $n "$bin/splat" -q -threads 1 -bf $res -o v.stack v.in) || { echo "$name vector failed"; exit 1; }
	tt=$(best $n "$bin/splat" -q -threads 1 -bf $res -o v.stack te.in) || { echo "$name te failed"; exit 1; }
	ta=$(best $n "$bin/splat" -q -threads 1 -method abbe -o s.stack $name.in) || { echo "$name abbe failed"; exit 1; }
	th=$(best $n "$bin/splat" -q -threads 1 -o s.stack $name.in) || { echo "$name scalar failed"; exit 1; }
	awk -v c="$name" -v u="$tu" -v t="$tt" -v a="$ta" -v h="$th" 'BEGIN {
		ru = 0; rt = 0
		if (a > 0) { ru = u / a; rt = t / a }
		printf "%-8s %9.4f %9.4f %9.4f %9.4f %10.2f %8.2f\n", c, u, t, a, h, ru, rt }'
done
