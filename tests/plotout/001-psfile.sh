#!/bin/sh
# Every plot program names its PostScript file with -psfile (without it
# the walk-through kept only its last picture): for drawmask, contour,
# drawplot and pdraw, "-psfile NAME" writes NAME byte-identical to the
# dataplot.ps the same command writes without it, and leaves an existing
# dataplot.ps untouched; an empty name is a usage error (exit 2, the reason on the first line, then a
# line naming --help).
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact
printf '0 1 0 1\n1\n3\n0 0\n0.5 1\n1 0.25\n' >line.2D
printf '0 1 0 1 0 1\n1\n4\n0 0 0\n1 0 0\n0 1 1\n0 0 0\n' >tri.3D
splat -o image.cont "$E/mask.in" >/dev/null 2>&1 || fail "splat on the contact mask"
for cmd in "drawmask $E/mask.in" "contour image.cont" "drawplot line.2D" "pdraw -h tri.3D"; do
	prog=${cmd%% *} args=${cmd#* }
	rm -f dataplot.ps
	$prog -noplot $args 2>err.txt || fail "$cmd: $(cat err.txt)"
	mv dataplot.ps want.ps
	echo keep >dataplot.ps
	$prog -noplot -psfile "$prog.ps" $args 2>err.txt || fail "$prog -psfile: $(cat err.txt)"
	same want.ps "$prog.ps"
	[ "$(cat dataplot.ps)" = keep ] || fail "$prog -psfile touched dataplot.ps"
	$prog -noplot -psfile "" $args >/dev/null 2>err.txt
	[ $? -eq 2 ] || fail "$prog -psfile '': not a usage error"
	[ "$(head -n 1 err.txt)" = "$prog: -psfile needs a file name" ] ||
		fail "$prog -psfile '': $(head -n 1 err.txt)"
done
exit 0
