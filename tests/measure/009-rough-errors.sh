# measure -ler, -psd, -lcdu and -holes on bad input: a usage error exits 2
# with a message and a line naming --help (-ler without -space or -line, -lcdu
# without -holes, -psd without -ler, two heights, -holes with a single
# feature or -plot); a feature whose edges cannot be followed (it reaches
# the box edge, it is absent at the point, it ends between lines) is one
# line "measure: ..." and exit 1, leaving no table and no PSD file.
. "$TOP/tests/lib/common.sh"
RS=$BUILD/tests/lib/roughsurf
[ -x "$RS" ] || fail "tests/lib/roughsurf is not built"
"$RS" line -rows 64 -truth l.txt -o l.plot || fail "roughsurf line failed"
"$RS" holes -nx 2 -ny 2 -truth h.txt -o h.plot || fail "roughsurf holes failed"

for args in "-rel 50 -ler -hole 0 0 l.plot" "-rel 50 -ler l.plot" "-rel 50 -lcdu -line 0 0 x l.plot" \
	"-rel 50 -holes h.plot" "-rel 50 -lcdu h.plot" "-rel 50 -psd p.plot -line 0 0 x l.plot" \
	"-rel 10,50 -ler -line 0 0 x l.plot" "-rel 10,50 -lcdu -holes h.plot" \
	"-rel 50 -holes -hole 0.5 0.5 -lcdu h.plot" "-rel 50 -lcdu -holes -plot p.plot h.plot" \
	"-rel 50 -ler -psd -line 0 0 x l.plot"; do
	# shellcheck disable=SC2086 # word splitting on purpose
	measure $args >out.txt 2>err.txt </dev/null
	st=$?
	[ $st -eq 2 ] || fail "measure $args: exit $st, expected 2: $(cat err.txt)"
	grep -qx 'measure: measure --help prints the usage' err.txt || fail "measure $args: no pointer to the usage"
	grep -q '^measure: ' err.txt || fail "measure $args: no message on stderr"
done
measure -rel 50 -ler l.plot 2>err.txt
grep -q "option -ler needs -space X Y x|y or -line X Y x|y" err.txt || fail "-ler alone: $(cat err.txt)"
measure -rel 50 -lcdu h.plot 2>err.txt
grep -q "option -lcdu needs -holes" err.txt || fail "-lcdu alone: $(cat err.txt)"

# the space right of the line runs to the box edge
echo old >keep.txt
expect_error measure -rel 50 -ler -space 0.6 0 x -o keep.txt -psd keep.plot l.plot
grep -q "reaches the box edge" err.txt || fail "space to the box edge: $(cat err.txt)"
[ "$(cat keep.txt)" = old ] || fail "a failed -ler run clobbered the table"
[ ! -e keep.plot ] || fail "a failed -ler run left a PSD file"
# no line at the point
expect_error measure -rel 50 -ler -line 0.6 0 x l.plot
grep -q "no line through (0.6, 0)" err.txt || fail "no line: $(cat err.txt)"
# a hole is a space along x that ends a little above and below its centre
expect_error measure -rel 50 -ler -space 0.5 0.5 x h.plot
grep -q "the space through (0.5, 0.5) is lost at y = " err.txt || fail "lost space: $(cat err.txt)"
[ -z "$(ls | grep -v '\.\(plot\|txt\)$')" ] || fail "temporaries left: $(ls)"
exit 0
