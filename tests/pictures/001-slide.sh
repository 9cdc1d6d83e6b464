# The pictures sample3D and sample2D draw by default, for the unbaked
# contact of examples/contact (-pt 20: three pages; a mesh of 0.1 M
# triangles finer than the page's pixels), rendered by ghostscript at the
# 80 dpi of a slide, each checked for:
# - rendering: gs -r80 reads every page without an error;
# - titles: every page's title names the feature (contact/mask.in) and,
#   where there are print times, its time; the cut's names its line;
# - round ticks: every number drawn is a 1, 2 or 5 step's multiple as the
#   axes print them, so no label has more than 3 significant digits
#   (tick labels such as -0.2012 fail);
# - no overlapping texts: the boxes of the texts (textboxes.awk, from
#   Helvetica's widths) of a page overlap by at most half a point;
# - no black noise: at most 15 % of the profile's drawn (not white)
#   pixels darker than 64 of 255 (the mesh outlined closer than its pixels
#   made 32 %, the shaded picture makes 1.5 %: the texts and axes);
# - size: every file under 20 MB (the shaded picture of pdraw -raster).
. "$TOP/tests/lib/common.sh"
need gs
E=$TOP/examples/contact
sample3D -q -if "$E/mask.in" -bf "$E/resist-nobake.in" -et 60 -pt 20 -hidden ||
	fail "sample3D"
sample2D -q -if "$E/mask.in" -bf "$E/resist-nobake.in" -cut -2.5 0 2.5 0 -et 60 -pt 20 ||
	fail "sample2D"
TB=$TOP/tests/pictures/textboxes.awk
MAXBYTES=20000000
for f in profile.ps cut.ps image.ps profile2D.ps; do
	[ -s "$f" ] || fail "$f not written"
	[ "$(wc -c <"$f")" -lt $MAXBYTES ] || fail "$f: $(wc -c <"$f") bytes, over 20 MB"
	gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=pgmraw -r80 -sOutputFile="${f%.ps}-%d.pgm" \
		"$f" </dev/null >gs.log 2>&1 || { cat gs.log; fail "gs cannot render $f"; }
	[ ! -s gs.log ] || { cat gs.log; fail "gs complains about $f"; }
	awk -v mode=overlap -f "$TB" "$f" || fail "$f: texts overlap"
	awk -v mode=texts -f "$TB" "$f" >texts.txt
	# numbers: at most 3 significant digits
	awk -F '\t' -v f="$f" '$2 ~ /^-?[0-9]*\.?[0-9]+$/ {
		s = $2; sub(/^-/, "", s); sub(/\./, "", s); sub(/^0+/, "", s); sub(/0+$/, "", s)
		if (length(s) > 3) { print f ": unround label " $2; bad = 1 } }
		END { exit bad }' texts.txt || fail "$f: unround tick labels"
done
# the titles: on each page of the profile and of sample2D's, the text
# naming the mask, with the page's print time
pages() { grep -c '^%%Page: ' "$1"; }
for f in profile.ps profile2D.ps; do
	[ "$(pages "$f")" -eq 3 ] || fail "$f: $(pages "$f") pages, not 3"
	awk -v mode=texts -f "$TB" "$f" >texts.txt
	for p in 1 2 3; do
		t=$(awk -F '\t' -v p=$p '$1 == p && /mask\.in/ { print $2; exit }' texts.txt)
		case $t in *"t = $((p * 20)) s"*) ;; *) fail "$f page $p: title \"$t\" without t = $((p * 20)) s" ;; esac
	done
done
awk -v mode=texts -f "$TB" profile.ps | grep -q 'contact/mask\.in' || fail "profile.ps: no feature in the title"
awk -v mode=texts -f "$TB" cut.ps | grep -q 'cross-section at y = 0 um.*contact/mask\.in' ||
	fail "cut.ps: the title names no cut line or feature"
awk -v mode=texts -f "$TB" image.ps | grep -q 'contact/mask\.in' || fail "image.ps: no feature in the title"
awk -v mode=texts -f "$TB" profile2D.ps | grep -q 'distance along the cut (um)' || fail "profile2D.ps: x axis not the distance along the cut"
# black noise: the dark pixels among the drawn (not white) ones of the
# last profile page (the raw PGM's pixels are its last width x height bytes)
set -- $(sed -n 3p profile-3.pgm)
# (counted by tr: the bytes left once 250-255, or 64-255, are deleted)
tail -c $(($1 * $2)) profile-3.pgm >pixels.raw
n=$(LC_ALL=C tr -d '\372-\377' <pixels.raw | wc -c)
d=$(LC_ALL=C tr -d '\100-\377' <pixels.raw | wc -c)
dark=$(awk -v d="$d" -v n="$n" 'BEGIN { printf "%.4f", d / n }')
echo "profile page 3: dark pixels $dark of those drawn"
awk -v d="$dark" -v max=0.15 'BEGIN { exit !(d < max) }' ||
	fail "profile.ps is black noise ($dark of its drawn pixels dark)"
exit 0
