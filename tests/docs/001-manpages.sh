# Every program has a man page in man/man1 with the sections the house
# style asks for, and every option its --help lists appears in that page
# (the usage text and the man page agree).  Every man page renders
# without a groff error.
. "$TOP/tests/lib/common.sh"
for bin in "$BUILD"/bin/*; do
	# a program is what is executable there (etchopts.sh is sourced by
	# the drivers, not run)
	[ -x "$bin" ] || continue
	p=$(basename "$bin")
	page=$TOP/man/man1/$p.1
	[ -f "$page" ] || fail "$p has no man page man/man1/$p.1"
	for s in NAME SYNOPSIS DESCRIPTION OPTIONS "EXIT STATUS" EXAMPLES "SEE ALSO"; do
		grep -q "^\.SH \"*$s" "$page" || fail "$p.1 has no $s section"
	done
	"$bin" --help >help.txt 2>&1 </dev/null || fail "$p --help exits non-zero"
	grep -qi usage help.txt || fail "$p --help prints no usage"
	# options: words starting with a dash, as in "-et" or "--help", each
	# found in the page as a whole word (-t is not found in "-tol"): not
	# preceded by a dash, letter or digit, nor followed by a letter or digit
	for o in $(grep -o -- '\(^\|[[ ]\)--*[a-zA-Z][a-zA-Z0-9]*' help.txt | tr -d '[ ' | sort -u); do
		# man pages escape the dash: \-et
		esc=$(printf '%s' "$o" | sed 's/-/\\\\-/g')
		grep -Eq -- "(^|[^-A-Za-z0-9])($esc|$o)([^A-Za-z0-9]|\$)" "$page" ||
			fail "$p: option $o of --help is not in man/man1/$p.1 (as a whole word)"
	done
done
if command -v groff >/dev/null; then
	for page in "$TOP"/man/man1/*.1 "$TOP"/man/man5/*.5; do
		groff -man -Tutf8 -ww "$page" >/dev/null 2>groff.err || fail "groff failed on $page"
		grep -v 'table wider than line width\|around line' groff.err | grep -q . &&
			fail "groff warns on $page: $(head -3 groff.err)"
	done
fi
exit 0
