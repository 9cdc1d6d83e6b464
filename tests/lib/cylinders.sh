# tests/lib/cylinders.sh - sourced by the tests of measure -accuracy
# (tests/accuracy/), after common.sh: synthetic developed holes whose cds
# are known exactly, and a check of the err column measure writes.
#
# synth R SEED: a cylinder of radius R through a 0.7 um film as a
# curves.plot on standard output (tests/measure/synth.awk; a 256-sided
# polygon stands for the circle, so each cd is 1e-4 relative off 2 R).
synth() { awk -f "$TOP/tests/measure/synth.awk" -v kind=rev -v prof="$1 -0.7 $1 0 3 0" -v seed="$2"; }
# M: the measure options of every table (cd at 10, 50 and 90 % of the hole
# at the origin)
M="-rel 10,50,90 -hole 0 0"
# errs TABLE WANT WHAT: TABLE has measure's header with err and three
# rows, and every row's err is WANT within 0.5 %; fails naming WHAT
errs() {
	awk -v w="$2" 'NR == 1 { if ($0 != "# z cd area dx dy err") { print "header: " $0; bad = 1 }; next }
		/^#/ { next }
		{ n++; d = $6 - w; if (d < 0) d = -d
		  if (d > 0.005 * w + 1e-9) { print "err " $6 ", expected " w; bad = 1 } }
		END { if (n != 3) { print n " rows"; bad = 1 }; exit bad }' "$1" || fail "$3: $(cat "$1")"
}
