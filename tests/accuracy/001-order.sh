# measure -accuracy with -coarse and -coarser: the order of convergence is
# observed from three solves and the estimate refused outside the
# asymptotic range.  Checked on synthetic cylinders whose cds are known
# exactly (tests/measure/synth.awk; a 256-sided polygon stands for the
# circle, so each cd is 1e-4 relative off the circle's): radii
# 0.30 + c h^p at h = 1, r, r q (this solve, -coarse, -coarser) make a
# cd error of exactly 2 c at h = 1, and the expected err is that times the
# safety factor 1.25 of a three-solve estimate, within 0.5 % (the
# polygon's 1e-4 over changes of a few percent):
#   - p = 1 and p = 2 (r = q = 2): err = 1.25 * 2 c = 0.025 um;
#   - p = 1 at r = 3, q = 2 (unequal ratios, -ratio 3 -ratio2 2): 0.025 um;
#   - p = 3 observed (above 2: the coarser change not yet asymptotic):
#     order 1 used, err = 1.25 |e2| = 1.25 * 0.014 um;
#   - a damped oscillation (radii 0.30, 0.31, 0.295): err = |e2| = 0.02 um,
#     trusted (status 0 with -accuracy 5);
#   - changes that grow (0.30, 0.31, 0.305) or shrink at order 0.2: refused
#     (status 3 with -accuracy 5, where the order-0.5 estimate is over
#     a tenth of 5 %; accuracy/003 checks the small changes that are
#     not), a note naming the height and
#     "not in the asymptotic range" on standard error, err the estimate at
#     order 0.5, |e2| / (sqrt 2 - 1); -accuracy check writes the same
#     table with status 0 and the note;
#   - three equal solves: err 0, trusted;
#   - two solves with -order 2 (radii 0.31, 0.34): err = |e2| / 3 = 0.02
#     (no safety factor: the order is given);
#   - -coarser without -accuracy, -ratio2 or -order out of range: usage
#     errors.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/cylinders.sh"
# tables RF RC RCC: fine.plot and the tables c.tab, cc.tab of three cylinders
tables() {
	synth "$1" 1 >fine.plot
	synth "$2" 2 >c.plot
	synth "$3" 3 >cc.plot
	# shellcheck disable=SC2086 # M is a list of words on purpose
	measure $M -o c.tab c.plot && measure $M -o cc.tab cc.plot || fail "measure the coarse solves"
}
# est P [measure options]: measure -accuracy P with both tables into e.tab; sets st
est() {
	p=$1
	shift
	st=0
	# shellcheck disable=SC2086 # M is a list of words on purpose
	measure $M -accuracy "$p" -coarse c.tab -coarser cc.tab "$@" -o e.tab fine.plot 2>err.txt || st=$?
}

tables 0.31 0.32 0.34
est 5
[ $st -eq 0 ] || fail "order 1: status $st: $(cat err.txt)"
[ ! -s err.txt ] || fail "order 1: a note: $(cat err.txt)"
errs e.tab 0.025 "order 1"
tables 0.31 0.34 0.46
est 5
[ $st -eq 0 ] || fail "order 2: status $st: $(cat err.txt)"
errs e.tab 0.025 "order 2"
tables 0.31 0.33 0.36
est 5 -ratio 3 -ratio2 2
[ $st -eq 0 ] || fail "order 1, r 3, q 2: status $st: $(cat err.txt)"
errs e.tab 0.025 "order 1 at ratios 3 and 2"
# order 3: cd changes 2 * 0.007 and 2 * 0.056 um; order 1 used: 1.25 * 0.014
tables 0.301 0.308 0.364
est 5
[ $st -eq 0 ] || fail "order 3: status $st: $(cat err.txt)"
errs e.tab "$(awk 'BEGIN { print 1.25 * 0.014 }')" "order 3, used as 1"
tables 0.30 0.31 0.295
est 5
[ $st -eq 0 ] || fail "damped oscillation: status $st: $(cat err.txt)"
errs e.tab 0.02 "damped oscillation"

refused() { # refused WHAT E2: status 3 at -accuracy 5, the note, err E2 / (sqrt 2 - 1)
	est 5
	[ $st -eq 3 ] || fail "$1: status $st, expected 3 (refused): $(cat err.txt)"
	[ "$(grep -c 'not in the asymptotic range' err.txt)" -eq 3 ] || fail "$1: no note per row: $(cat err.txt)"
	grep -q '^measure: fine.plot: at z = -0.63 ' err.txt || fail "$1: the note names no height: $(cat err.txt)"
	errs e.tab "$(awk -v e="$2" 'BEGIN { print e / (sqrt(2) - 1) }')" "$1"
	cp e.tab p.tab
	est check
	[ $st -eq 0 ] || fail "$1: -accuracy check status $st"
	grep -q 'not in the asymptotic range' err.txt || fail "$1: check gives no note"
	same e.tab p.tab
}
tables 0.30 0.31 0.305
refused "growing oscillation" 0.02
# order 0.2: radii 0.30 + 0.01 h^0.2
tables 0.31 "$(awk 'BEGIN { print 0.30 + 0.01 * 2 ^ 0.2 }')" "$(awk 'BEGIN { print 0.30 + 0.01 * 4 ^ 0.2 }')"
refused "order 0.2" "$(awk 'BEGIN { print 0.02 * (2 ^ 0.2 - 1) }')"

tables 0.30 0.30 0.30
est 1
[ $st -eq 0 ] || fail "three equal solves: status $st: $(cat err.txt)"
awk '!/^#/ && $6 != 0 { exit 1 }' e.tab || fail "three equal solves: err not 0: $(cat e.tab)"

tables 0.31 0.34 0.46
# shellcheck disable=SC2086 # M is a list of words on purpose
measure $M -accuracy 5 -coarse c.tab -order 2 -o e.tab fine.plot || fail "-order 2: status $?"
errs e.tab 0.02 "two solves, -order 2"

for args in "-coarser cc.tab" "-accuracy 1 -coarse c.tab -order 0.4" "-accuracy 1 -coarse c.tab -order 3" "-accuracy 1 -coarse c.tab -coarser cc.tab -ratio2 1" \
	"-accuracy 1 -coarse c.tab -coarser cc.tab -ratio2 x"; do
	st=0
	# shellcheck disable=SC2086 # the words on purpose
	measure $M $args fine.plot >/dev/null 2>&1 || st=$?
	[ $st -eq 2 ] || fail "measure $args: exit $st, expected 2"
done
exit 0
