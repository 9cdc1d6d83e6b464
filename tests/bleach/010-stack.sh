# bleach with an image stack (stack(5)): the intensity at depth
# d of column (x, y) is the stack's image linearly interpolated in depth
# between planes, times the standing-wave factor.  Checked against:
#  - the closed form of a non-bleaching resist (A = 0) with standing
#    waves off, M = exp(-C dose I_d(x, y) e^(-B d)), at every node of a
#    3-plane stack, with nz putting nodes on the planes (nz 5) and between
#    them (nz 8), a dark column (I = 0) and a negative intensity (exposes
#    nothing) included: 1e-9 (the formula is evaluated in closed form;
#    the trapezoidal optical depth of B alone is exact to rounding);
#  - a stack whose planes all equal one image gives that image's rate
#    file: byte for byte without bake (also resampled by "grid nx ny"),
#    to 1e-12 with a 3D bake (the z
#    bake then smooths the M array rather than the dose table: the same
#    linear map, another order of sums);
#  - the deeper planes matter: a stack darker at the bottom leaves more
#    PAC at the bottom than its top plane alone;
#  - errors naming both values: a stack thickness or index other than
#    the resist file's; a plane on another window or grid.
. "$TOP/tests/lib/common.sh"
cat >r0.in <<'IN'
wavelength 0.365
resist thickness 0.6 index 1.7 dill 0 0.5 0.02
substrate 1.7 0
dose 50
standingwaves off
develop mack 0.1 0.0001 0.5 5
IN
# planes at depths 0, 0.3, 0.6 on a 3 x 2 grid
cat >st.cont <<'ST'
stack planes 3 thickness 0.6 index 1.7
depth 0
-1 1 -1 1
3 2
1 0.5 0.2
0.8 0 -0.1
depth 0.3
-1 1 -1 1
3 2
0.7 0.9 0.1
0.6 0 0.3
depth 0.6
-1 1 -1 1
3 2
0.4 1.2 0.05
0.5 0 0.6
ST
for nz in 5 8; do
	{ cat r0.in; echo "grid nz $nz"; } >r$nz.in
	bleach -q -ascii -o m$nz.txt st.cont r$nz.in || fail "bleach, nz $nz: $(cat err.txt 2>/dev/null)"
	awk -v nz=$nz -v T=0.6 -v B=0.5 -v C=0.02 -v dose=50 '
		FNR == NR { if (/^depth/) { k = $2 == 0 ? 0 : k + 1; d[k] = $2; row = 0; next }
			    if (NF == 3) { for (i = 1; i <= 3; i++) v[k, row, i] = $i; row++ }
			    next }
		/^M$/ { on = 1; kz = 0; j = 0; next }
		on {
			depth = T - kz * T / (nz - 1)
			if (kz == nz - 1) depth = 0
			p = depth < d[1] ? 0 : 1
			w = (depth - d[p]) / (d[p + 1] - d[p])
			for (i = 1; i <= 3; i++) {
				a = v[p, j, i]; b = v[p + 1, j, i]; I = a + w * (b - a)
				if (I < 0) I = 0
				want = exp(-C * dose * I * exp(-B * depth))
				e = $i - want; if (e < 0) e = -e
				if (e > worst) worst = e
				n++
			}
			if (++j == 2) { j = 0; kz++ }
		}
		END { printf "nz %d: %d nodes, max |M - closed form| %.3g\n", nz, n, worst
		      if (n != 6 * nz || !(worst <= 1e-9)) exit 1 }' st.cont m$nz.txt ||
		fail "closed form, nz $nz"
done
# identical planes: a stack of one image three times
src=$TOP/examples/resists/olinhunt6512.in
sed 's/^grid .*/grid nz 61/; /^bake/d' "$src" >ol.in
th=$(awk '$1 == "resist" { for (i = 2; i < NF; i++) if ($i == "thickness") print $(i + 1) }' ol.in)
ix=$(awk '$1 == "resist" { for (i = 2; i < NF; i++) if ($i == "index") print $(i + 1) }' ol.in)
awk 'BEGIN { n = 9; print "-1 1 -1 1"; print n, n
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		x = -1 + 2 * i / (n - 1); y = -1 + 2 * j / (n - 1)
		printf "%.12g\n", 0.05 + 0.9 * exp(-(x * x + y * y) / 0.3) } }' >img.cont
{ echo "stack planes 3 thickness $th index $ix"
  echo "depth 0"; cat img.cont
  echo "depth $(awk -v t=$th 'BEGIN { print t / 2 }')"; cat img.cont
  echo "depth $th"; cat img.cont; } >same.cont
bleach -q -ascii -o a.txt img.cont ol.in || fail "plain image"
bleach -q -ascii -o b.txt same.cont ol.in || fail "stack of equal planes"
same a.txt b.txt
# the same through "grid nx ny" resampling
{ cat ol.in; echo "grid nx 5 ny 4 nz 41"; } | grep -v '^grid nz 61' >olr.in
bleach -q -ascii -o a.txt img.cont olr.in || fail "plain image, resampled"
bleach -q -ascii -o b.txt same.cont olr.in || fail "stack of equal planes, resampled"
same a.txt b.txt
sed -n 2p b.txt | grep -q '^5 4 41 2$' || fail "resampled stack: header $(sed -n 2p b.txt)"
{ cat ol.in; echo "bake3d diffusion 0.05"; } >olb.in
bleach -q -ascii -o a.txt img.cont olb.in || fail "plain image, bake3d"
bleach -q -ascii -o b.txt same.cont olb.in || fail "stack of equal planes, bake3d"
paste a.txt b.txt | awk 'NR > 3 && $1 + 0 == $1 { n = NF / 2; for (i = 1; i <= n; i++) {
	e = $i - $(i + n); if (e < 0) e = -e; if (e > w) w = e } }
	END { printf "equal planes with bake3d: max difference %.3g\n", w; exit !(w <= 1e-12) }' ||
	fail "equal planes with bake3d differ from the image"
# darker at depth: more PAC left at the bottom than with the top plane alone
{ echo "stack planes 2 thickness $th index $ix"
  echo "depth 0"; cat img.cont
  echo "depth $th"; awk 'NR <= 2 { print; next } { print $1 * 0.5 }' img.cont; } >dark.cont
bleach -q -ascii -o d.txt dark.cont ol.in || fail "darker stack"
bleach -q -ascii -o a.txt img.cont ol.in
mb() { awk '/^M$/ { on = 1; next } on && NR > 0 { print $5; exit }' "$1"; }   # bottom plane, row 1, column 5
awk -v a="$(mb d.txt)" -v b="$(mb a.txt)" 'BEGIN { exit !(a > b + 1e-3) }' ||
	fail "a darker bottom plane leaves M $(mb d.txt), the top image alone $(mb a.txt)"
# errors
sed 's/thickness 0.6/thickness 0.7/' st.cont >thick.cont
sed 's/^depth 0.6/depth 0.7/' thick.cont >thick2.cont
expect_error bleach -q -o x.bin thick2.cont r5.in
grep -q '0\.7.*0\.6' err.txt || fail "thickness message does not name both values: $(cat err.txt)"
[ ! -e x.bin ] || fail "output written for a thickness mismatch"
sed 's/index 1.7/index 1.6/' st.cont >index.cont
expect_error bleach -q -o x.bin index.cont r5.in
grep -q '1\.6.*1\.7' err.txt || fail "index message does not name both values: $(cat err.txt)"
awk '/^depth 0.3/ { print; getline; print "-1 1 -1 2"; next } { print }' st.cont >win.cont
expect_file_error bleach win.cont -q -o x.bin win.cont r5.in
grep -q 'window' err.txt || fail "window mismatch message: $(cat err.txt)"
awk '/^depth 0.6/ { print; getline; print; getline; print "2 3"; print "1 1"; next } { print }' st.cont >grid.cont
expect_file_error bleach grid.cont -q -o x.bin grid.cont r5.in
[ ! -e x.bin ] || fail "output written for a bad stack"
exit 0
