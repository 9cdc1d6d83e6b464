#!/bin/sh
# make-mask.sh SIZE - prints the splat input of a SIZE x SIZE um window of
# 0.5 um contacts on a 1 um pitch (i-line, NA 0.6, sigma 0.5, a 0.05 um
# grid), the large-mask case.  mask.in is "make-mask.sh 40",
# mask20.in "make-mask.sh 20".
set -eu
size=${1:?usage: make-mask.sh SIZE (um, an even integer)}
awk -v s="$size" 'BEGIN {
	h = s / 2
	printf "# %g x %g um contact array: 0.5 um contacts on a 1 um pitch (%d of them),\n", s, s, s * s
	print "# i-line, NA 0.6, sigma 0.5; a 0.05 um grid.  Made by make-mask.sh " s "."
	print "wavelength 0.365"
	print "na 0.6"
	print "sigma 0.5"
	print "background dark"
	printf "window %g %g %g %g\n", -h, h, -h, h
	for (j = 0; j < s; j++)
		for (i = 0; i < s; i++) {
			x = -h + i + 0.5; y = -h + j + 0.5
			printf "rect %g %g %g %g\n", x - 0.25, y - 0.25, x + 0.25, y + 0.25
		}
	printf "grid %d %d\n", s * 20 + 1, s * 20 + 1
	print "contour image.cont"
}'
