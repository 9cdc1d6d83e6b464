# examples/calibrate runs end to end (fem makes the "measured" CDs from the
# hidden process, calib fits Mth and n of the start file to them) and the
# README's "Calibrate to measured CDs" table is its output: the table rows
# and the rms line of README.md equal table.txt, character for character
# (the simulations are deterministic, so any difference is a change to
# explain).  Also: the fitted values are within 5 % of the hidden ones.
. "$TOP/tests/lib/common.sh"
OUT=$PWD/ex JOBS=2 sh "$TOP/examples/calibrate/calibrate.sh" -q >ex.log 2>&1 ||
	fail "examples/calibrate failed: $(tail -n 3 ex.log)"
cat ex/table.txt
grep '^|\|^rms ' ex/table.txt >got.txt
awk '/^## Calibrate to measured CDs/ { f = 1; next } /^## / { f = 0 }
	f && (/^\|/ || /^rms /)' "$TOP/README.md" >readme.txt
[ -s readme.txt ] || fail "README.md has no table under \"## Calibrate to measured CDs\""
same got.txt readme.txt
awk -F'|' 'NR > 2 && NF > 5 { h = $3 + 0; v = $5 + 0; d = v - h; if (d < 0) d = -d
	if (!(d <= 0.05 * h)) { print "far: " $0; bad = 1 } } END { exit bad }' ex/table.txt ||
	fail "a fitted value is not within 5 % of the hidden one"
exit 0
