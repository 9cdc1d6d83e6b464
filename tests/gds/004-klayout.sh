# Layouts written by KLayout (Debian klayout, batch mode): references
# mirrored, rotated and magnified, an array, a polygon with a hole, a path
# with extensions (tests/gds/klayout.rb).  Our reading of the gds against
# KLayout's own flattening and merge (as convex polygon statements):
# images agree to 1e-9.  Skips when klayout is not installed.
. "$TOP/tests/lib/common.sh"
need klayout
klayout -b -r "$TOP/tests/gds/klayout.rb" >kl.log 2>&1 || fail "klayout: $(tail -n 3 kl.log)"
[ -s k.gds ] && [ -s k.in ] || fail "klayout wrote no layout: $(tail -n 3 kl.log)"
optics='wavelength 0.365
na 0.5
sigma 0.5
grid 31 31
window -4 4 -4 4'
printf '%s\n' "$optics" "gds k.gds layer 1/0" >g.in
printf '%s\n' "$optics" >p.in
cat k.in >>p.in
splat -q -o g.cont g.in 2>err.txt || fail "splat on the gds: $(cat err.txt)"
splat -q -o p.cont p.in 2>err.txt || fail "splat on KLayout's polygons: $(cat err.txt)"
plotdiff -tol 1e-9 g.cont p.cont >diff.txt 2>&1 || fail "our flattening and KLayout's differ: $(cat diff.txt)"
exit 0
