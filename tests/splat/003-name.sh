# splat -name prints the contour-file name without computing: the
# input's contour statement, else splat.cont, and -o overrides both; a bad
# input is still refused.  (sample3D relies on it to chain splat to bleach.)
. "$TOP/tests/lib/common.sh"
printf 'wavelength 0.436\nna 0.28\nsigma 0.5\nwindow -2 2 -2 2\ngrid 11 11\nbackground dark\nrect -0.5 -0.5 0.5 0.5\ncontour img.cont\n' >a.in
[ "$(splat -name a.in)" = img.cont ] || fail "expected img.cont, got $(splat -name a.in)"
[ ! -e img.cont ] || fail "-name computed the image"
grep -v '^contour' a.in >b.in
[ "$(splat -name b.in)" = splat.cont ] || fail "expected splat.cont"
[ "$(splat -name -o x.cont a.in)" = x.cont ] || fail "-o should override"
printf 'wavelength 0.436\nbogus 1\n' >bad.in
expect_file_error splat bad.in -name bad.in
exit 0
