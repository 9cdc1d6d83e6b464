# splat's polygon, clip and window auto statements (man/man5/splat.5):
# malformed ones fail with one line naming the file and line, and no
# output; clip on clips a polygon to the window; a polygon given in
# either orientation, with a repeated closing vertex, images the same.
. "$TOP/tests/lib/common.sh"
n=0
bad() {   # bad LINE TEXT [PATTERN]: the input must fail naming that line
	n=$((n + 1))
	printf '%s\n' "$2" >bad$n.in
	expect_file_error splat bad$n.in -q -o out$n.cont bad$n.in
	grep -q "^splat: bad$n.in:$1: " err.txt || fail "case $n: wrong line: $(cat err.txt)"
	[ -z "${3:-}" ] || grep -q "$3" err.txt || fail "case $n: message lacks '$3': $(cat err.txt)"
	[ ! -e out$n.cont ] || fail "case $n: output written despite the error"
}
w='window -2 2 -2 2'
bad 2 "$w
polygon 0 0 1 0" "at least 3"
bad 2 "$w
polygon 0 0 1 0 1"
bad 2 "$w
polygon 0 0 1 0 0.5 nan"
bad 2 "$w
polygon 0 0 1 0 2 0" "zero area"
bad 2 "$w
polygon 0 0 1 1 1 0 0 1" "not simple"
bad 3 "$w
grid 5 5
polygon -1 -1 1 -1 1 1 0 -1.5 -1 1" "not simple"
bad 2 "$w
polygon 0 0 1 0 1 1 t 2 0" "transmission"
bad 2 "$w
polygon 0 0 1 0 1 1 t 1"
bad 2 "$w
polygon 0 0 3 0 1 1" "outside the window"
bad 1 "polygon 0 0 3 0 1 1
$w" "outside the window"
bad 2 "$w
clip maybe"
bad 1 "window auto margin -1"
bad 1 "window auto 3"
bad 1 "window auto" "no shape"
bad 2 "$w
gds x.gds" "expected"
bad 2 "$w
gds x.gds layer 70000" "layer"
bad 2 "$w
gds x.gds layer 1/x"
bad 2 "$w
gds x.gds cell A" "no layer"
bad 2 "$w
gds missing.gds layer 1" "missing.gds"

# clip on: a triangle reaching out of the window images as its clipped part
printf '%s\n' "$w" "grid 9 9" "clip on" "polygon -1 -1 3 -1 -1 3 t 1 0" >c1.in
printf '%s\n' "$w" "grid 9 9" "polygon -1 -1 2 -1 2 0 0 2 -1 2" >c2.in
splat -q -o c1.cont c1.in || fail "clip on: splat failed"
splat -q -o c2.cont c2.in || fail "clipped polygon: splat failed"
same c1.cont c2.cont
# orientation and a closing vertex repeated: the same image
printf '%s\n' "$w" "grid 9 9" "polygon -1 -1 1 -1 0 1.5" >o1.in
printf '%s\n' "$w" "grid 9 9" "polygon 0 1.5 1 -1 -1 -1 0 1.5" >o2.in
splat -q -o o1.cont o1.in && splat -q -o o2.cont o2.in || fail "orientation: splat failed"
same o1.cont o2.cont
exit 0
