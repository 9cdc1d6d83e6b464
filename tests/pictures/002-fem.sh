# The pictures fem draws by default (bossung.ps, window.ps, region.ps) for
# a 3 focus x 3 dose matrix of a small contact (21 x 21 image, 60 z
# planes, fast marching), rendered by ghostscript at 80 dpi, each checked
# as tests/pictures/001-slide.sh checks sample3D's: gs renders every page
# without a message, no two texts overlap (textboxes.awk), every number
# drawn has at most 3 significant digits (round ticks); and the titles:
# the Bossung curves' names the CD's height (-rel 10), the region's the
# target and tolerance, and the region is shaded (a 0.85 grey fill).
. "$TOP/tests/lib/common.sh"
need gs
E=$TOP/examples/contact
cat >mask.in <<'M'
wavelength 0.436
na 0.28
sigma 0.5
window -1.5 1.5 -1.5 1.5
grid 21 21
background dark
rect -0.6 -0.6 0.6 0.6
M
sed 's/^grid .*/grid nz 60/' "$E/resist.in" >resist.in
fem -q -if mask.in -bf resist.in -et 60 -method fmm -dose 70,85,100 -focus -1,0,1 \
	-measure "-rel 10 -hole 0 0" -target 0.85 -tol 10 -j 2 -d f >/dev/null || fail "fem"
TB=$TOP/tests/pictures/textboxes.awk
for f in f/bossung.ps f/window.ps f/region.ps; do
	[ -s "$f" ] || fail "$f not written"
	gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=pgmraw -r80 -sOutputFile=/dev/null "$f" \
		</dev/null >gs.log 2>&1 || { cat gs.log; fail "gs cannot render $f"; }
	[ ! -s gs.log ] || { cat gs.log; fail "gs complains about $f"; }
	awk -v mode=overlap -f "$TB" "$f" || fail "$f: texts overlap"
	awk -v mode=texts -f "$TB" "$f" | awk -F '\t' -v f="$f" '$2 ~ /^-?[0-9]*\.?[0-9]+$/ {
		s = $2; sub(/^-/, "", s); sub(/\./, "", s); sub(/^0+/, "", s); sub(/0+$/, "", s)
		if (length(s) > 3) { print f ": unround label " $2; bad = 1 } }
		END { exit bad }' || fail "$f: unround tick labels"
done
awk -v mode=texts -f "$TB" f/bossung.ps | grep -q "CD at 10 % of the resist's height" ||
	fail "bossung.ps: the title names no CD height"
awk -v mode=texts -f "$TB" f/region.ps | grep -q 'CD 0.85 um +- 10 %' ||
	fail "region.ps: the title names no target"
grep -q ' 0.85 F' f/region.ps || fail "region.ps: the region is not shaded"
exit 0
