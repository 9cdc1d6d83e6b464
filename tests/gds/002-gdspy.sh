# Layouts written afresh by gdspy (Debian python3-gdspy, a real GDSII
# writer): references rotated by 90, 180 and 30 degrees, reflected and
# magnified, arrays with rotation and reflection, overlapping shapes,
# decoy layers and datatypes, paths of pathtypes 0, 1, 2 and 4 with bends,
# and the SRAM-like clip of examples/layout.  Our flattening (the gds
# statement) against gdspy's own (get_polygons, as polygon statements):
# images agree to 1e-9, round path ends (gdspy's tolerance 1e-5 um, ours
# 1 nm; gdspy also snaps to its 1 nm grid; measured 8e-5) to 2e-4.  Skips when no python3 with gdspy is installed.
. "$TOP/tests/lib/common.sh"
PY=
for p in python3 /usr/bin/python3; do
	if command -v "$p" >/dev/null 2>&1 && "$p" -c 'import gdspy' 2>/dev/null; then
		PY=$p
		break
	fi
done
[ -n "$PY" ] || skip "python3-gdspy is not installed"
optics='wavelength 0.365
na 0.5
sigma 0.5
grid 31 31'
for c in refs paths round sram; do
	"$PY" "$TOP/tests/gds/mklayout.py" $c $c.gds $c.in 2>py.err || fail "gdspy $c: $(cat py.err)"
	[ -s $c.in ] || fail "gdspy $c: no shapes on layer 1/0"
	win='window -3 3 -3 3'
	[ $c = sram ] && win='window 0 7.2 0 3.2'
	tol=1e-9
	[ $c = round ] && tol=2e-4
	printf '%s\n' "$optics" "$win" "gds $c.gds layer 1/0" >g_$c.in
	printf '%s\n' "$optics" "$win" "clip on" >p_$c.in
	cat $c.in >>p_$c.in
	splat -q -o g_$c.cont g_$c.in 2>err.txt || fail "$c: splat on the gds: $(cat err.txt)"
	splat -q -o p_$c.cont p_$c.in 2>err.txt || fail "$c: splat on the polygons: $(cat err.txt)"
	plotdiff -tol $tol g_$c.cont p_$c.cont >diff.txt 2>&1 ||
		fail "$c: our flattening and gdspy's differ: $(cat diff.txt)"
done
exit 0
