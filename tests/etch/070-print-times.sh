#!/bin/sh
# etch -print-times: the print times, one a line, as etch and etch2d take
# them (src/lib/numerics/ptimes.c): every -pt and the end, a multiple of
# -pt within a relative 1e-12 below -et being the end itself (3 x 0.1 is
# 0.30000000000000004: three times, not four), only the end without -pt
# or with -pt beyond -et; no rate file read.  Against the lists written
# out by hand, exactly.  And the sets the programs write follow the same
# list: etch -method cell and etch2d write as many sets as -print-times
# prints, for -pt dividing -et and not; -print-times without -et is a
# usage error (status 2).
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
[ -x "$MKRATE" ] || fail "mkrate not built"
ptimes() { etch "$@" -print-times | tr '\n' ' '; }
[ "$(ptimes -et 60 -pt 20)" = "20 40 60 " ] || fail "-et 60 -pt 20: $(ptimes -et 60 -pt 20)"
[ "$(ptimes -et 50 -pt 20)" = "20 40 50 " ] || fail "-et 50 -pt 20: $(ptimes -et 50 -pt 20)"
[ "$(ptimes -et 0.3 -pt 0.1)" = "0.1 0.2 0.3 " ] || fail "-et 0.3 -pt 0.1: $(ptimes -et 0.3 -pt 0.1)"
[ "$(ptimes -et 1)" = "1 " ] || fail "-et 1: $(ptimes -et 1)"
[ "$(ptimes -et 1 -pt 5)" = "1 " ] || fail "-et 1 -pt 5: $(ptimes -et 1 -pt 5)"
etch -pt 1 -print-times >/dev/null 2>err.txt
[ $? -eq 2 ] || fail "-print-times without -et: not a usage error"
head -n 1 err.txt | grep -q "^etch: -et etchtime is required" || fail "$(head -n 1 err.txt)"

# the sets written: blank lines separate sets in a plot file
$MKRATE -o r3.bin 5 5 5 -1 1 -1 1 -1 0 1 || fail "mkrate 3D"
$MKRATE -o r2.bin 11 1 11 -1 1 0 0 -1 0 1 || fail "mkrate 2D"
sets() { awk '/^#/ { next } NF == 0 { n++ } END { print n + 1 }' "$1"; }
for tp in "0.3 0.1" "0.5 0.2" "1 0.25"; do
	set -- $tp
	want=$(etch -et $1 -pt $2 -print-times | wc -l)
	etch -q -method cell -seg 0.5 -et $1 -pt $2 r3.bin || fail "etch -et $1 -pt $2"
	[ "$(sets curves.plot)" -eq "$want" ] || fail "etch -et $1 -pt $2: $(sets curves.plot) sets, want $want"
	etch2d -et $1 -pt $2 -o e2.plot r2.bin || fail "etch2d -et $1 -pt $2"
	[ "$(sets e2.plot)" -eq "$want" ] || fail "etch2d -et $1 -pt $2: $(sets e2.plot) sets, want $want"
done
exit 0
