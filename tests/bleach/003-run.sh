# Every resist file shipped in examples/ (the thesis' resists and each
# example directory's resist*.in) runs on a clear field, and:
#  - the output is deterministic: two runs give byte-identical files;
#  - the binary and ASCII rate files hold the same numbers (the binary one
#    converted by the library's reader/writer equals bleach -ascii);
#  - the file carries the arrays "rate" and "M", nz planes from -thickness
#    to 0, M in [0, 1], rates positive;
#  - without -q there is one progress line per stage on stderr, with -q
#    none;  -o names the output;
#  - "grid nx 5 ny 7" resamples the image to a 5 x 7 grid over the same
#    window, and a uniform image stays uniform;
#  - "standingwaves off" changes M (Beer-Lambert has no swing), and its
#    M falls monotonically with depth on a clear field.
. "$TOP/tests/lib/common.sh"
printf -- '-1 1 -1 1\n2 2\n1 1 1 1\n' >clear.cont
count=0
for f in "$TOP"/examples/resists/*.in "$TOP"/examples/*/resist*.in; do
	[ -f "$f" ] || continue
	count=$((count + 1))
	bleach -q -o a.bin clear.cont "$f" 2>err.txt || fail "$f: $(cat err.txt)"
	[ ! -s err.txt ] || fail "$f: -q printed: $(cat err.txt)"
	bleach -q -ascii -o a.txt clear.cont "$f" || fail "$f -ascii"
	"$BUILD/tests/lib/fmtcat" rate-ascii a.bin b.txt || fail "$f: fmtcat"
	same a.txt b.txt
	awk -v f="$f" '
		NR == 2 { nz = $3; na = $4; if (na != 2) { print f ": " na " arrays"; bad = 1 } }
		NR == 3 { if ($6 != 0 || $5 >= 0) { print f ": z bounds " $5 " " $6; bad = 1 } }
		/^rate$/ { arr = "rate"; next }
		/^M$/ { arr = "M"; seen = 1; next }
		NR > 3 && arr == "rate" { for (i = 1; i <= NF; i++) if (!($i > 0)) { print f ": rate " $i; bad = 1; exit } }
		NR > 3 && arr == "M" { for (i = 1; i <= NF; i++) if (!($i >= 0 && $i <= 1)) { print f ": M " $i; bad = 1; exit } }
		END { if (!seen) { print f ": no M array"; bad = 1 } exit bad }' a.txt || fail "$f: bad rate file"
done
[ $count -ge 20 ] || fail "only $count resist files found"
# determinism and progress lines, on a real 2D image with a 3D bake
awk 'BEGIN { n = 21; print "-1 1 -1 1"; print n, n
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		x = -1 + 2 * i / (n - 1); y = -1 + 2 * j / (n - 1)
		printf "%.12g\n", 0.05 + 0.9 * exp(-(x * x + y * y) / 0.3) } }' >spot.cont
sed 's/^bake diffusion/bake3d diffusion/; s/^grid .*/grid nz 80/' "$TOP/examples/resists/shipley1470.in" >s.in
bleach spot.cont s.in 2>progress.txt || fail "spot run"
cp rval.3D.binary first.bin
bleach -q spot.cont s.in
same first.bin rval.3D.binary
n=$(grep -c '^bleach: ' progress.txt)
[ "$n" -ge 5 ] || fail "expected a progress line per stage, got $n: $(cat progress.txt)"
grep -q 'bake' progress.txt || fail "no bake progress line"
# resampling
{ cat s.in; echo "grid nx 5 ny 7 nz 40"; } | grep -v '^grid nz' >r.in
bleach -q -ascii -o r.txt spot.cont r.in || fail "grid nx ny run"
sed -n 2p r.txt | grep -q '^5 7 40 2$' || fail "grid nx 5 ny 7: header $(sed -n 2p r.txt)"
sed -n 3p r.txt | grep -q '^-1 1 -1 1 ' || fail "resampled window: $(sed -n 3p r.txt)"
# standing waves off: M monotonic in depth, and different from on
sed 's/^grid .*/grid nz 80/; /^bake/d' "$TOP/examples/resists/olinhunt6512.in" >on.in
{ cat on.in; echo "standingwaves off"; } >off.in
bleach -q -ascii -o on.txt clear.cont on.in || fail "standing waves on"
bleach -q -ascii -o off.txt clear.cont off.in || fail "standing waves off"
cmp -s on.txt off.txt && fail "standingwaves off changes nothing"
# planes run from the substrate (k = 0) up; the top is the most exposed,
# so M must fall with k
awk '/^M$/ { m = 1; next } m && NF == 2 { n++; if (n % 2 == 1) { if (seen && $1 > prev + 1e-12) { print "M rises towards the top: " prev " -> " $1; exit 1 } prev = $1; seen = 1 } }' off.txt ||
	fail "Beer-Lambert M not monotonic"
echo "$count resist files run"
exit 0
