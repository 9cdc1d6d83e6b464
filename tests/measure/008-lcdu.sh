# measure -lcdu -holes on exact synthetic hole arrays (tests/lib/roughsurf
# holes: regular 64- or 128-gons of known circumradius on a 0.5 um grid,
# planar faces, the outer holes cut in half by the box edge):
#   - every hole inside the box is found and no cut one is counted
#     (# holes exactly, one row per hole);
#   - each hole's centroid within 1e-4 um of its centre and its cd
#     within 0.05 % of the polygon's equivalent diameter sqrt(4 A / pi)
#     (the midpoint rule across 400 lines errs about 1e-4 of the area);
#   - # lcdu within 0.5 % of 3 x the sample sigma (n - 1) of the exact
#     CDs, computed in awk;
#   - rows of increasing y, each by increasing x;
#   - a hole's cd as -hole X Y measures it (0.05 %);
#   - the same bytes with 1, 2 and 3 threads, and through -o.
. "$TOP/tests/lib/common.sh"
RS=$BUILD/tests/lib/roughsurf
[ -x "$RS" ] || fail "tests/lib/roughsurf is not built"

# check OUT TRUTH WHAT
check() {
	n=$(wc -l <"$2")
	[ "$(awk '/^# holes / { print $3 }' "$1")" = "$n" ] || fail "$3: # holes is not $n: $(tail -2 "$1")"
	[ "$(grep -vc '^#' "$1")" = "$n" ] || fail "$3: not $n rows: $(cat "$1")"
	head -1 "$1" | grep -qx '# x y cd' || fail "$3: no '# x y cd' head: $(head -1 "$1")"
	awk 'NR == FNR { x[FNR] = $1; y[FNR] = $2; cd[FNR] = $4; n = FNR; next }
		/^#/ { next }
		{ best = 1e9
		  for (i = 1; i <= n; i++) { d = (x[i] - $1)^2 + (y[i] - $2)^2; if (d < best) { best = d; b = i } }
		  if (sqrt(best) > 1e-4) { print "hole at " $1 " " $2 ": no centre within 1e-4 um"; exit 1 }
		  if (seen[b]++) { print "hole " x[b] " " y[b] " listed twice"; exit 1 }
		  e = $3 / cd[b] - 1; if (e < 0) e = -e
		  if (e > 5e-4) { print "hole " x[b] " " y[b] ": cd " $3 ", expected " cd[b]; exit 1 } }' \
		"$2" "$1" || fail "$3: $(cat "$1")"
	exp=$(awk '{ s += $4; ss += $4 * $4; n++ } END { m = s / n; printf "%.9g", 3 * sqrt((ss - n * m * m) / (n - 1)) }' "$2")
	got=$(awk '/^# lcdu / { print $3 }' "$1")
	awk -v a="$got" -v b="$exp" 'BEGIN { d = a / b - 1; if (d < 0) d = -d; exit !(d <= 0.005) }' ||
		fail "$3: lcdu $got, expected $exp within 0.5 %"
	# rows of increasing y (to well within a pitch), each by increasing x
	awk '/^#/ { next } n++ && ($2 < y - 0.1 || ($2 < y + 0.1 && $1 <= x)) { exit 1 } { x = $1; y = $2 }' "$1" ||
		fail "$3: holes not in rows of increasing y, each by x: $(cat "$1")"
}

"$RS" holes -truth h.txt -o h.plot || fail "roughsurf holes failed"
measure -rel 50 -lcdu -holes h.plot >h.out || fail "measure -lcdu: $(cat h.out)"
check h.out h.txt "8 x 8 array, 64-gons"
[ "$(wc -l <h.txt)" = 49 ] || fail "roughsurf wrote $(wc -l <h.txt) holes inside the box, expected 49"

"$RS" holes -nx 5 -ny 3 -sides 128 -r 0.12 -dr 0.05 -seed 4 -truth g.txt -o g.plot ||
	fail "roughsurf holes 5 x 3 failed"
measure -at -0.25 -lcdu -holes -o g.out g.plot || fail "measure -lcdu -o"
check g.out g.txt "5 x 3 array, 128-gons"
for t in 1 2 3; do
	SAMPLE3D_THREADS=$t measure -rel 50 -lcdu -holes g.plot >t$t.out || fail "measure with $t threads"
done
same g.out t1.out
same t1.out t2.out
same t1.out t3.out

# one hole by -hole: the same cd
read -r hx hy _ hcd <<EOF
$(sed -n 5p g.txt)
EOF
measure -rel 50 -hole "$hx" "$hy" g.plot >one.out || fail "measure -hole"
awk -v c="$hcd" '!/^#/ { d = $2 / c - 1; if (d < 0) d = -d; exit !(d <= 5e-4) }' one.out ||
	fail "-hole $hx $hy: cd $(awk '!/^#/ { print $2 }' one.out), expected $hcd"
exit 0
