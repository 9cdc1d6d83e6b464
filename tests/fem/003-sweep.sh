# The sweep engine for real: a 2 focus x 2 dose matrix of a small contact
# (21x21 image, 60 z planes, 60 s: every point clears, cd 0.74 and 1.01
# um at 80 and 100 mJ/cm2) run by make -j2.
#  - uninterrupted: fem.dat has the 4 rows in (focus, dose) order, bossung.ps
#    renders and its title names the CD height (-rel 10), the points' rate
#    files and curves.plot are gone (no -keep),
#    and a second run redoes nothing;
#  - interrupted: an etch stand-in lets the first two points through and
#    holds the others (-j 1, so that held stages do not take the slots the
#    first points' measure needs); the sweep is killed (SIGTERM to its process group)
#    once those two are measured, and resumed with the real etch: the two
#    finished points are not redone, no temporary is left, and fem.dat is
#    byte-identical to the uninterrupted run's;
#  - a failing point (an etch that fails for one point): fem goes on with the
#    others (make -k), prints "fem: focus F dose D: etch: <etch's message>",
#    exits non-zero, and fem.dat holds the other three;
#  - -keep keeps the intermediate files; -n writes the Makefile only.
. "$TOP/tests/lib/common.sh"
built measure
need setsid
E=$TOP/examples/contact
cat >mask.in <<'M'
wavelength 0.436
na 0.28
sigma 0.5
window -1.5 1.5 -1.5 1.5
grid 21 21
background dark
rect -0.6 -0.6 0.6 0.6
M
sed 's/^grid .*/grid nz 60/' "$E/resist.in" >resist.in
set -- -if "$PWD/mask.in" -bf "$PWD/resist.in" -et 60 -dose 80,100 -focus -0.5,0.5 \
	-measure "-rel 10 -hole 0 0" -q -j 2

fem "$@" -d full || fail "uninterrupted sweep failed"
[ "$(grep -vc '^#' full/fem.dat)" -eq 4 ] || fail "fem.dat should hold 4 points: $(cat full/fem.dat)"
awk '!/^#/ && !($3 > 0.5 && $5 == 1) { exit 1 }' full/fem.dat || fail "every point should clear with cd > 0.5 um"
awk 'NR > 1 { print $1, $2 }' full/fem.dat | tr '\n' ' ' | grep -qx -- '-0.5 80 -0.5 100 0.5 80 0.5 100 ' ||
	fail "fem.dat rows out of order: $(cat full/fem.dat)"
[ -z "$(find full -name rate -o -name curves.plot)" ] || fail "intermediate files left without -keep"
[ -s full/bossung.ps ] && [ -s full/bossung.svg ] || fail "bossung.ps/.svg missing"
grep -qF 'focus \(um\)' full/bossung.ps || fail "bossung.ps: no focus axis label"
grep -qF "(Bossung curves: CD at 10 % of the resist's height against focus)" full/bossung.ps ||
	fail "bossung.ps: the title does not name the CD's height (-rel 10)"
if command -v gs >/dev/null 2>&1; then gs_check full/bossung.ps; fi
# a point redone gets a new file: its inode (written to a temporary, then
# renamed) or its mtime (nanoseconds) changes; no sleep for a clock tick
snap() { find "$1" -name measure.dat -printf '%i %T@ %p\n' | sort -k3; }
snap full >before.txt
fem "$@" -d full || fail "rerun failed"
snap full >after.txt
cmp -s before.txt after.txt || fail "a rerun redid finished points: $(diff before.txt after.txt | head -n 4)"

# interrupted and resumed
mkdir bin
cp "$BUILD/bin/fem" "$BUILD/bin/etchopts.sh" bin/
for p in splat bleach femwin drawplot measure; do ln -s "$(command -v $p)" bin/$p; done
cat >bin/etch <<X
#!/bin/sh
# lets two runs through, then holds every other until killed (fem's
# check of the options, without -o, always passes)
case "\$*" in *" -o "*) ;; *) exec "$(command -v etch)" "\$@" ;; esac
mkdir "$PWD/calls" 2>/dev/null
n=\$(ls "$PWD/calls" | wc -l)
touch "$PWD/calls/\$\$"
if [ "\$n" -ge 2 ]; then touch "$PWD/held"; exec sleep 100; fi
exec "$(command -v etch)" "\$@"
X
chmod +x bin/etch
setsid sh bin/fem "$@" -d part -j 1 >part.log 2>&1 &
pid=$!
i=0
while [ "$(find part -name measure.dat 2>/dev/null | wc -l)" -lt 2 ] || [ ! -e held ]; do
	i=$((i + 1))
	[ $i -lt 300 ] || { env kill -s TERM -- -$pid; fail "the first two points did not finish in 30 s"; }
	sleep 0.1
done
env kill -s TERM -- -$pid
wait $pid && fail "the killed sweep reported success"
[ "$(find part -name measure.dat | wc -l)" -eq 2 ] || fail "expected 2 finished points before the resume"
[ ! -e part/fem.dat ] || fail "fem.dat made by the killed sweep"
snap part >before.txt
fem "$@" -d part || fail "resumed sweep failed"
[ "$(snap part | grep -cxF -f before.txt)" -eq 2 ] || fail "the resume redid finished points"
[ -z "$(find part -name '*.tmp*')" ] || fail "temporaries left: $(find part -name '*.tmp*')"
same part/fem.dat full/fem.dat

# a failing point
cat >bin/etch <<X
#!/bin/sh
case "\$*" in *f0.5/d100/*) echo "etch: injected failure" >&2; exit 1 ;; esac
exec "$(command -v etch)" "\$@"
X
sh bin/fem "$@" -d fail 2>err.txt && fail "a failing point should make fem fail"
grep -q '^fem: focus 0.5 dose 100: etch: etch: injected failure$' err.txt ||
	fail "the failing stage's message is missing: $(cat err.txt)"
[ "$(grep -vc '^#' fail/fem.dat)" -eq 3 ] || fail "fem.dat should hold the 3 other points"
grep -v '^0.5 100 ' full/fem.dat >three.dat
same fail/fem.dat three.dat

# -keep, -n
fem "$@" -d keep -keep -dose 80 -focus 0 || fail "-keep sweep failed"
[ -s keep/f0/d80/rate ] && [ -s keep/f0/d80/curves.plot ] || fail "-keep lost the intermediate files"
fem "$@" -d dry -n || fail "-n failed"
[ -s dry/Makefile ] && [ ! -e dry/f-0.5 ] || fail "-n ran something"
exit 0
