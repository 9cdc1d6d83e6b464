# The image stack (stack(5)) that splat writes for a resist statement:
#  - its layout: the header "stack planes N thickness T index n", then N
#    planes top first, each "depth z_k" (z_k = k T/(N-1)) and a whole
#    contour-file on the input's window and grid;
#  - the top plane is a plain splat run's image to the quadrature error
#    (1e-6; tests/splat/stack.c shows them identical at equal quadrature
#    orders), on the same window and grid; the deeper planes differ;
#  - without the statement the output is a plain contour-file (unchanged);
#  - write -> read -> write is byte-identical, and deterministic;
#  - cutlines carry one curve per plane;
#  - a reader of single images (conv) refuses a stack naming it; the
#    stack reader refuses malformed stacks with one line naming file:line
#    (wrong counts, depths out of order or not reaching the thickness,
#    a plane on another window or grid, NaN, truncation, trailing data);
#  - bad resist statements are one-line errors naming the line, and a
#    stack beyond the grid's limit (planes x nx x ny values) or whose
#    spectra would need more than 2 GB is refused with the estimate.
. "$TOP/tests/lib/common.sh"
PATH=$BUILD/tests/lib:$PATH
cat >base.in <<'IN'
window -1 1 -1 1
rect -0.4 -0.4 0.4 0.4
grid 9 7
IN
{ cat base.in; echo "resist index 1.6 planes 3 thickness 0.1"
  echo "cutline -1 0 1 0 11 cut.2D"; } >st.in
splat -q -o st.cont st.in || fail "splat with a resist statement"
sed -n 1p st.cont | grep -qx 'stack planes 3 thickness 0.1 index 1.6 wavelength 0.436' ||
	fail "header: $(sed -n 1p st.cont)"
[ "$(grep -c '^depth ' st.cont)" -eq 3 ] || fail "expected 3 depth lines"
grep '^depth ' st.cont | tr '\n' ' ' | grep -qx 'depth 0 depth 0.05 depth 0.1 ' ||
	fail "depths: $(grep '^depth ' st.cont | tr '\n' ' ')"
[ "$(wc -l <st.cont)" -eq $((1 + 3 * (1 + 2 + 63))) ] || fail "wrong line count $(wc -l <st.cont)"
# plane 1 (lines 3..67) vs the plain image
splat -q -o plain.cont base.in
sed -i '/^#/d' plain.cont       # its labels line (contour(5)); a stack has none
sed -n 3,67p st.cont >top.cont
same_grid() { # the header lines equal, the values within 1e-6
	[ "$(head -2 "$1")" = "$(head -2 "$2")" ] || fail "$1, $2: headers differ"
	paste "$1" "$2" | awk 'NR > 2 { d = $1 - $2; if (d < 0) d = -d; if (d > 1e-6) { print NR ": " $0; exit 1 } }' ||
		fail "$1 and $2 differ by more than 1e-6"
}
same_grid top.cont plain.cont
sed -n 135,199p st.cont >bottom.cont
cmp -s bottom.cont plain.cont && fail "the bottom plane equals the top one"
head -1 plain.cont | grep -q '^-1 1 -1 1$' || fail "plain output changed: $(head -1 plain.cont)"
# round trip and determinism
fmtcat stack st.cont rt.cont || fail "fmtcat stack"
same st.cont rt.cont
fmtcat stack plain.cont rt2.cont || fail "fmtcat stack on a contour-file"
same plain.cont rt2.cont
splat -q -o again.cont st.in
same st.cont again.cont
# cutline: one curve per plane in one set
grep -v '^#' cut.2D | awk 'NR == 2 { if ($1 != 3) exit 1 }' || fail "cutline: $(sed -n 2p cut.2D) curves, expected 3"
# single-image readers name the stack
expect_file_error conv st.cont st.cont
grep -q 'image stack' err.txt || fail "conv's message does not say stack: $(cat err.txt)"
# malformed stacks
P='0 1 0 1\n2 2\n1 2 3 4\n'
Q='0 1 0 1\n2 2\n5 6 7 8\n'
n=0
bad() { # bad CONTENT(printf format): fmtcat stack refuses it
	n=$((n + 1))
	printf "$1" >bad$n.cont
	expect_file_error fmtcat bad$n.cont stack bad$n.cont out$n
	[ ! -e out$n ] || fail "case $n: output written"
	return 0
}
bad "stack planes 2 thickness 1 index 1.5\ndepth 0\n$P"
bad "stack planes 2 thickness 1 index 1.5\ndepth 0\n${P}depth 1\n${Q}depth 2\n$P"
bad "stack planes 2 thickness 1 index 1.5\ndepth 0.1\n${P}depth 1\n$Q"
bad "stack planes 2 thickness 1 index 1.5\ndepth 0\n${P}depth 0.5\n$Q"
bad "stack planes 2 thickness 1 index 1.5\ndepth 0\n${P}depth 1.5\n$Q"
bad "stack planes 3 thickness 1 index 1.5\ndepth 0\n${P}depth 0\n${Q}depth 1\n$Q"
bad "stack planes 2 thickness 1 index 1.5\ndepth 0\n${P}depth 1\n0 1 0 2\n2 2\n1 2 3 4\n"
bad "stack planes 2 thickness 1 index 1.5\ndepth 0\n${P}depth 1\n0 1 0 1\n2 1\n1 2\n"
bad "stack planes 2 thickness 1 index 1.5\ndepth 0\n${P}depth 1\n0 1 0 1\n2 2\n1 nan 3 4\n"
bad "stack planes 2 thickness 1 index 1.5\ndepth 0\n${P}depth 1\n0 1 0 1\n2 2\n1 2\n"
bad "stack planes 2 thickness 1 index 1.5\ndepth 0\n${P}1 1\n$Q"
bad "stack planes 1 thickness 1 index 1.5\ndepth 0\n$P"
bad "stack planes 100000000 thickness 1 index 1.5\ndepth 0\n$P"
bad "stack planes 2 thickness -1 index 1.5\ndepth 0\n$P"
bad "stack planes 2 thickness 1 index 0.5\ndepth 0\n$P"
bad "stack planes 2 thickness 1\ndepth 0\n$P"
bad "stack planes 2 planes 2 thickness 1 index 1.5\n"
bad "stack\n"
bad "stack planes 2 thickness nan index 1.5\n"
# the grid mismatch message names both
printf "stack planes 2 thickness 1 index 1.5\ndepth 0\n${P}depth 1\n0 2 0 1\n2 2\n1 2 3 4\n" >grid.cont
fmtcat stack grid.cont o 2>err.txt && fail "window mismatch accepted"
grep -q '0 2 0 1, 2x2.*0 1 0 1, 2x2' err.txt || fail "window mismatch message: $(cat err.txt)"
# bad resist statements
m=0
badin() { # badin TEXT: splat refuses it on line 4
	m=$((m + 1))
	{ cat base.in; echo "$1"; } >r$m.in
	expect_file_error splat r$m.in -q -o r$m.cont r$m.in
	grep -q "^splat: r$m.in:4: " err.txt || fail "resist case $m: $(cat err.txt)"
	[ ! -e r$m.cont ] || fail "resist case $m: output written"
	return 0
}
badin "resist thickness 1 index 1.6"
badin "resist thickness 1 index 1.6 planes 1"
badin "resist thickness 1 index 1.6 planes 2000"
badin "resist thickness 0 index 1.6 planes 3"
badin "resist thickness 1 index 0.9 planes 3"
badin "resist thickness 1 index nan planes 3"
badin "resist thickness 1 thickness 1 planes 3"
badin "resist thickness 1 index 1.6 dill 3"
badin "resist thickness 1 index 1.6 planes 3 extra"
# beyond the limits: refused with the estimate, nothing allocated
printf 'window 0 1 0 1\ngrid 10001 10001\nresist thickness 1 index 1.5 planes 3\n' >big.in
expect_file_error splat big.in -q -o big.cont big.in
grep -q 'GB' err.txt || fail "no size estimate: $(cat err.txt)"
printf 'window 0 300 0 300\nna 0.9\nwavelength 0.193\ngrid 3 3\nresist thickness 1 index 1.5 planes 1001\n' >big2.in
expect_error splat -q -o big2.cont big2.in
# refused by the spectra guard, or before it by splat's work estimate
# (splat(1), LIMITS): either way with the estimate in GB
grep -q 'GB' err.txt || fail "no estimate: $(cat err.txt)"
[ ! -e big2.cont ] || fail "output written beyond the limit"
# a later resist statement replaces an earlier one, as every statement
{ cat base.in; echo "resist thickness 1 index 1.6 planes 5"; echo "resist thickness 0.1 index 1.6 planes 3"; } >twice.in
splat -q -o twice.cont twice.in || fail "two resist statements"
same twice.cont st.cont
exit 0
