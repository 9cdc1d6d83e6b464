#!/bin/sh
# The thesis' study of 2D etching algorithms (chapters 3-7), remade with
# etch2d.  Writes, in $OUT (default out/ here), plot files drawn into
# PostScript by drawplot:
#   fig3.3-cells{25,100,200}.plot  Dill's cells from a seed, uniform rate,
#                                  0.1..1 s: the octagons of Figure 3.3
#   fig4.2-huygens{10,40}.plot     Huygens cells at 10 and 40 cells a step
#   fig6.4-string{0.1,0.02}.plot   the string from a seed, S_ideal 0.1, 0.02
#   fig7.7-raystring.plot          the ray-string from a seed
#   fig4.4*, fig4.5*               Huygens cells on the triangular rates
#   fig6.13, fig7.15b, fig7.19     rays, ray-string and delooping on them
#   fig6.20*, fig7.21*             rays, string, ray-string in the sinusoid
#   fig6.5-{string,string-fine,raystring,ray,fmm}.plot
#                                  from a V groove (groove.plot, -start):
#                                  the string's rounding at the bottom and
#                                  scissoring at the rims, the ray-string's
#                                  fan and delooping, the rays' swallowtails
#   fig23.bin                      the Figure 2.3 rate (splat, bleach -cutline)
#   fig3.4-{cell,string}.plot      cells (200 x 100) and string, 15..75 s
#   table10.1-<method>.plot        every method, 15 and 30 s
# The numbers (Table 10.1 remade, Table 3.1, Figure 3.3's overshoot) are
# printed by `make bench` (tests/bench/etch2d.sh).
# Usage: sh run.sh; runs splat, bleach, etch2d and drawplot from PATH,
# else from this tree's build.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
# the programs from PATH, else from this tree's build (make at the top of the tree)
command -v etch2d >/dev/null 2>&1 || PATH=$here/../../build/bin:$PATH
out=${OUT:-$here/out}
mkdir -p "$out" && cd "$out"
draw() { drawplot -noplot -e "$1" </dev/null >/dev/null && mv dataplot.ps "${1%.plot}.ps"; }
# a uniform 1 um/s over 2 x 1 um, the seed at the top centre
printf 'RVAL3D 1\n2 1 2 1\n-1 1 0 0 -1 0\nrate\n1 1\n1 1\n' >uniform.rate
for n in 25 100 200; do
	etch2d -method cell -seed 0 0 -cells $((2 * n)) $n -et 1 -pt 0.1 -o fig3.3-cells$n.plot uniform.rate
	draw fig3.3-cells$n.plot
done
for n in 10 40; do
	etch2d -method huygens -seed 0 0 -cells $((20 * n)) $((10 * n)) -dt 0.1 -et 1 -pt 0.1 \
		-o fig4.2-huygens$n.plot uniform.rate
	draw fig4.2-huygens$n.plot
done
for s in 0.1 0.02; do
	etch2d -method string -seed 0 0 -seg $s -et 1 -pt 0.1 -o fig6.4-string$s.plot uniform.rate
	draw fig6.4-string$s.plot
done
etch2d -method raystring -seed 0 0 -seg 0.05 -et 1 -pt 0.1 -o fig7.7-raystring.plot uniform.rate
draw fig7.7-raystring.plot
# Figures 6.5-6.6: from a grooved surface (-start), uniform rate, 0.5 s:
# a 90 degree V 0.3 um deep (its bottom a diverging corner, its 135
# degree rims converging ones).  The string at the thesis' S_ideal 0.2
# tapers the groove (rounding) and lets the rims lag (scissoring); at 0.05
# less so; the ray-string fans its rays at the bottom and deloops the
# rims; the rays alone keep the swallowtails; fmm is the exact offset
# curve to a node spacing (tests/etch2d/corners measures all of them).
printf -- '-1 1 -1 0\n1\n5\n-1 0\n-0.3 0\n0 -0.3\n0.3 0\n1 0\n' >groove.plot
etch2d -method string -seg 0.2 -start groove.plot -et 0.5 -pt 0.1 -o fig6.5-string.plot uniform.rate
etch2d -method string -seg 0.05 -start groove.plot -et 0.5 -pt 0.1 -o fig6.5-string-fine.plot uniform.rate
etch2d -method raystring -seg 0.2 -start groove.plot -et 0.5 -pt 0.1 -o fig6.5-raystring.plot uniform.rate
etch2d -method ray -seg 0.2 -start groove.plot -et 0.5 -pt 0.1 -o fig6.5-ray.plot uniform.rate
etch2d -method fmm -start groove.plot -et 0.5 -pt 0.1 -o fig6.5-fmm.plot uniform.rate
for f in string string-fine raystring ray fmm; do
	draw fig6.5-$f.plot
done
# analytic rates (ASCII rval(5), ny = 1): the triangles of [4.1], [4.2]
# and [7.9] on |x| < 0.5, and the sinusoid [7.10] of Figure 6.20
rate() {   # rate NX NZ X0 X1 Z0 Z1 AWK-EXPRESSION-IN-x-z
	awk -v nx="$1" -v nz="$2" -v x0="$3" -v x1="$4" -v z0="$5" -v z1="$6" 'BEGIN {
		print "RVAL3D 1"; print nx, 1, nz, 1; print x0, x1, 0, 0, z0, z1; print "rate"
		for (k = 0; k < nz; k++) { line = ""
			for (i = 0; i < nx; i++) { x = x0 + (x1 - x0) * i / (nx - 1); z = z0 + (z1 - z0) * k / (nz - 1)
				line = line (i ? " " : "") sprintf("%.17g", '"$7"') }
			print line } }'
}
rate 101 2 -0.5 0.5 -1 0 '2 * (x < 0 ? -x : x)' >tri.rate
rate 101 2 -0.5 0.5 -1 0 '2 * (x < 0 ? -x : x) + 0.2' >tri02.rate
rate 101 201 -1 1 -1 0 'exp(-4 * x * x) * (1.05 - cos(8 * 3.141592653589793 * z))' >sine.rate
# Figures 4.4-4.5: Huygens cells on the triangles, 10/40 and 12/48 cells a step
etch2d -method huygens -cells 100 100 -dt 0.1 -et 1 -pt 0.1 -o fig4.4a-huygens.plot tri.rate
etch2d -method huygens -cells 400 400 -dt 0.1 -et 1 -pt 0.1 -o fig4.4b-huygens.plot tri.rate
etch2d -method huygens -cells 100 100 -dt 0.1 -et 1 -pt 0.1 -o fig4.5a-huygens.plot tri02.rate
etch2d -method huygens -cells 400 400 -dt 0.1 -et 1 -pt 0.1 -o fig4.5b-huygens.plot tri02.rate
# Figure 6.13: rays spreading in the triangle (ray-scarce centre);
# Figure 7.15b: the ray-string with flattening; Figure 7.19: delooping
etch2d -method ray -seg 0.05 -et 1 -pt 0.1 -o fig6.13-ray.plot tri.rate
etch2d -method raystring -seg 0.05 -et 1 -pt 0.1 -o fig7.15b-raystring.plot tri.rate
etch2d -method raystring -seg 0.05 -et 1 -pt 0.1 -stats -o fig7.19-raystring.plot tri02.rate
# Figures 6.20-6.21 and 7.21: rays looping in the sinusoid, the string and
# the ray-string on it (dt 0.1 and, without vector checking, 0.5)
etch2d -method ray -seg 0.04 -et 3 -pt 0.5 -o fig6.20-ray.plot sine.rate
etch2d -method string -seg 0.04 -et 3 -pt 0.5 -o fig6.20-string.plot sine.rate
etch2d -method raystring -seg 0.04 -et 3 -pt 0.5 -o fig7.21-raystring.plot sine.rate
etch2d -method raystring -seg 0.04 -dt 0.5 -rl 2 -et 3 -pt 0.5 -o fig7.21-raystring-dt0.5-norl.plot sine.rate
for f in fig4.4a-huygens fig4.4b-huygens fig4.5a-huygens fig4.5b-huygens fig6.13-ray \
	fig7.15b-raystring fig7.19-raystring fig6.20-ray fig6.20-string fig7.21-raystring \
	fig7.21-raystring-dt0.5-norl; do
	draw $f.plot
done
# the Figure 2.3 rate: splat's 1.25 um isolated space, cut across, on
# the Kodak 820 of Figure 2.2
splat -q "$here/space.in"
bleach -q -cutline -o fig23.bin space.2D "$here/../resists/kodak820-fig22.in"
etch2d -method cell -cells 200 100 -et 75 -pt 15 -o fig3.4-cell.plot fig23.bin
etch2d -method string -dt 0.092 -et 75 -pt 15 -o fig3.4-string.plot fig23.bin
draw fig3.4-cell.plot
draw fig3.4-string.plot
for m in raystring string ray cell huygens fmm; do
	etch2d -method $m -et 30 -pt 15 -stats -o table10.1-$m.plot fig23.bin
	draw table10.1-$m.plot
done
