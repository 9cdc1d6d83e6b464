#!/bin/sh
# etch -deloop from the command line (thesis Figure 8.13 through the
# program, not the library):
#   - repeated -seed grows one sphere per seed; with -deloop the summary
#     reports the loops removed (at least one per sphere, the count the
#     library test tests/etch/deloop.c finds) and no crossing left;
#   - -deloop n delooping every n steps as well as at the print time
#     (10 steps: -deloop 8 after steps 8 and 10, as the thesis did, 2
#     passes; -deloop 2 after steps 2, 4, 6, 8, 10, 5 passes; -deloop
#     alone 1 pass, at the end);
#   - the output is deterministic: two runs are byte-identical;
#   - bad uses are usage errors (exit 2, the problem and a line naming --help):
#     -deloop 0, 17 seeds, a seed outside the box; a seed with two numbers
#     is one too.
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
$MKRATE -o two.bin 31 41 31 -1.5 1.5 -1.5 2.5 -1.5 1.5 1 || fail "mkrate"
set -- -et 1 -dt 0.1 -seg 0.1 -seed 0 0 0 -seed 0 1 0 -check
etch "$@" -deloop 8 -o a.plot two.bin 2>a.err || fail "etch -deloop failed: $(tail -n 3 a.err)"
grep -q "^etch: deloop: 2 passes removed [0-9]* loops" a.err || fail "no deloop summary: $(cat a.err)"
loops=$(sed -n 's/^etch: deloop: [0-9]* passes removed \([0-9]*\) loops.*/\1/p' a.err)
[ "$loops" -ge 2 ] || fail "only $loops loops removed"
grep -q "; 0 crossings left" a.err || fail "crossings left: $(grep deloop: a.err)"
etch "$@" -deloop 8 -q -o b.plot two.bin || fail "second run failed"
same a.plot b.plot
same a.plot.2D b.plot.2D
etch "$@" -deloop 2 -o c.plot two.bin 2>c.err || fail "etch -deloop 2 failed: $(tail -n 3 c.err)"
grep -q "^etch: deloop: 5 passes" c.err || fail "-deloop 2: expected 5 passes: $(grep deloop: c.err)"
grep -q "; 0 crossings left" c.err || fail "-deloop 2: crossings left: $(grep deloop: c.err)"
etch "$@" -deloop -o e.plot two.bin 2>e.err || fail "etch -deloop failed: $(tail -n 3 e.err)"
grep -q "^etch: deloop: 1 passes" e.err || fail "-deloop: expected 1 pass: $(grep deloop: e.err)"
# without -deloop the spheres keep their loops (the nodes inside the other sphere)
etch "$@" -q -o d.plot two.bin || fail "etch without -deloop failed"
inside() {
	awk 'NF == 3 { r1 = sqrt($1^2 + $2^2 + $3^2); r2 = sqrt($1^2 + ($2 - 1)^2 + $3^2)
		if (r1 < 0.99 || r2 < 0.99) n++ } END { print n + 0 }' "$1"
}
[ "$(inside d.plot)" -gt 0 ] || fail "no loop to remove without -deloop"
[ "$(inside a.plot)" -eq 0 ] || fail "$(inside a.plot) nodes inside a sphere after -deloop"
usage_error() {
	etch "$@" </dev/null >/dev/null 2>err.txt
	st=$?
	[ $st -eq 2 ] || fail "etch $*: exit $st, expected 2: $(head -c 300 err.txt)"
	grep -qx "etch: etch --help prints the usage" err.txt || fail "etch $*: no pointer to the usage: $(head -c 300 err.txt)"
}
usage_error -et 1 -deloop 0 two.bin
seeds=""
for i in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17; do seeds="$seeds -seed 0 0 0"; done
usage_error -et 1 $seeds two.bin
usage_error -et 1 -seed 0 0 0 -seed 0 9 0 two.bin
usage_error -et 1 -seed 0 0 two.bin
exit 0
