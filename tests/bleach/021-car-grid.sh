# The CA bake on a coarse output grid (m within 1e-3 of
# the converged solution whatever the output grid, as asked): bleach refines z inside,
# so a 13-point grid's m matches a 49-point grid's at the 13 common nodes
# within 1.5e-3 (each within 1e-3 of the converged m, bleach(1)); the
# output is the same whatever the thread count.
. "$TOP/tests/lib/common.sh"
awk 'BEGIN { print "-0.18 0.18 -0.02 0.02"; print 13, 3
	for (j = 0; j < 3; j++) for (i = 0; i < 13; i++) printf "%.12g\n", 0.3 + 0.25 * cos(2 * 3.14159265358979 * i / 12) }' >lines.cont
res() { printf '%s\n' 'wavelength 0.248' 'resist thickness 0.20 index 1.76 dill 0 0.45 0.04' \
	'substrate 1.57 3.57' 'dose 40' \
	'car quencher 0.15 amplification 0.4 order 1 loss 0.001 quenching 10' \
	'peb time 60 dacid 7.5e-6 dquencher 1e-6' 'develop enhanced 0.1 0.0002 0.004 5 13' "grid nz $1"; }
res 13 >coarse.in
res 49 >fine.in
bleach -q -ascii -o coarse.3D lines.cont coarse.in || fail "coarse run fails"
bleach -q -ascii -o fine.3D lines.cont fine.in || fail "fine run fails"
bleach -q -ascii -threads 1 -o one.3D lines.cont coarse.in || fail "one-thread run fails"
same coarse.3D one.3D
awk 'FNR == 1 { f++ } /^M$/ { on[f] = 1; next } on[f] { for (i = 1; i <= NF; i++) v[f, ++n[f]] = $i }
	END { ncol = 13 * 3; m = 0
		for (k = 0; k < 13; k++) for (q = 1; q <= ncol; q++) {
			d = v[1, k * ncol + q] - v[2, 4 * k * ncol + q]; if (d < 0) d = -d; if (d > m) m = d }
		printf "max |m(13 points) - m(49 points)| = %.3g\n", m; exit !(m <= 1.5e-3 && n[1] == 13 * ncol) }' \
	coarse.3D fine.3D || fail "coarse and fine grids disagree"
exit 0
