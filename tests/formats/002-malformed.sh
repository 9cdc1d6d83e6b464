# Every reader refuses a corpus of malformed files: one line on stderr,
# "fmtcat: FILE:LINE: ...", a non-zero exit, no crash (no signal, no
# sanitizer report), no output file, and an existing output left intact.
. "$TOP/tests/lib/common.sh"
PATH=$BUILD/tests/lib:$PATH F=fmtcat
MK=$BUILD/tests/lib/mkrate

bad() { # bad TYPE NAME CONTENT(printf format)
	printf "$3" >"$2"
	echo previous >out
	expect_file_error fmtcat "$2" "$1" "$2" out
	[ "$(cat out)" = previous ] || fail "$1 $2: the previous output was destroyed"
	ls out.tmp* >/dev/null 2>&1 && fail "$1 $2: a temporary file was left behind"
	rm -f out
	$F "$1" "$2" out2 2>/dev/null
	[ -e out2 ] && fail "$1 $2: an output file was written"
	return 0
}
garbage() { awk 'BEGIN { for (i = 0; i < 300; i++) printf "%c", (i * 37 + 11) % 256 }' >"$1"; }  # deterministic binary junk

# contour-file
bad contour c-empty ''
bad contour c-trunc '0 1 0 1\n2 2\n1 2 3\n'
bad contour c-nan '0 1 0 1\n2 2\n1 nan 3 4\n'
bad contour c-inf '0 1 0 1\n2 2\n1 2 inf 4\n'
bad contour c-neg '0 1 0 1\n-2 2\n'
bad contour c-huge '0 1 0 1\n100000 100000\n1 2 3\n'
bad contour c-frac '0 1 0 1\n2.5 2\n1 2 3 4 5\n'
bad contour c-bounds '1 0 0 1\n2 2\n1 2 3 4\n'
bad contour c-extra '0 1 0 1\n2 2\n1 2 3 4 5\n'
bad contour c-word '0 1 zero 1\n'
bad contour c-1e400 '0 1e400 0 1\n2 2\n1 2 3 4\n'
garbage c-garbage; bad contour c-garbage "$(cat c-garbage | tr -d '%\\' | head -c 200)"
bad contour-old o-trunc '0 0 1 1\n1 2 3\n'
bad contour-old o-len '0 0 -1 1\n'

# plot files
bad plot3 p-empty ''
bad plot3 p-trunc '0 1 0 1 0 1\n1\n3\n0 0 0\n1 1\n'
bad plot3 p-count '0 1 0 1 0 1\n-1\n'
bad plot3 p-huge '0 1 0 1 0 1\n1\n2000000000\n0 0 0\n'
bad plot3 p-nan '0 1 0 1 0 1\n1\n1\n0 NaN 0\n'
bad plot3 p-frac '0 1 0 1 0 1\n1.5\n'
bad plot2 q-trunc '0 1 0 1\n2\n1\n0 0\n'
bad plot2 q-word '0 1 0 1\n1\n2\n0 0\n1 one\n'
bad plot2 q-toobig '0 1 0 1\n99999999999\n'

# options-file
bad options op-unknown 'colour red\n'
bad options op-range 'scale 2\n'
bad options op-int 'xticks 2.5\n'
bad options op-onoff 'grid maybe\n'
bad options op-word 'joinlevel middle\n'
bad options op-missing 'scale\n'
bad options op-extra 'label two words\n'
bad options op-quote 'label "unterminated\n'
bad options op-nan 'scale nan\n'

# rate files, ASCII
bad rate r-empty ''
bad rate r-magic 'RVAL4D 1\n'
bad rate r-version 'RVAL3D 7\n2 2 2 1\n0 1 0 1 -1 0\nrate\n'
bad rate r-dims 'RVAL3D 1\n1 2 2 1\n'
bad rate r-huge 'RVAL3D 1\n1048576 1048576 1048576 1\n0 1 0 1 -1 0\nrate\n1 2 3\n'
bad rate r-trunc 'RVAL3D 1\n2 2 2 1\n0 1 0 1 -1 0\nrate\n1 2 3\n'
bad rate r-nan 'RVAL3D 1\n2 2 2 1\n0 1 0 1 -1 0\nrate\n1 2 3 4 5 6 7 nan\n'
bad rate r-name 'RVAL3D 1\n2 2 2 1\n0 1 0 1 -1 0\n1 2 3 4 5 6 7 8\n'
bad rate r-bounds 'RVAL3D 1\n2 2 2 1\n0 1 0 1 0 -1\nrate\n1 2 3 4 5 6 7 8\n'
bad rate r-extra 'RVAL3D 1\n2 2 2 1\n0 1 0 1 -1 0\nrate\n1 2 3 4 5 6 7 8 9\n'
garbage r-garbage; expect_error fmtcat rate r-garbage out

# rate files, binary: truncated, a flipped byte, a foreign version, garbage tail
$MK -o good.bin 3 3 3 0 1 0 1 -1 0 '1+x' || fail "mkrate failed"
n=$(wc -c <good.bin)
head -c $((n - 1)) good.bin >b-trunc
expect_file_error fmtcat b-trunc rate b-trunc out
head -c 40 good.bin >b-short
expect_file_error fmtcat b-short rate b-short out
head -c 5 good.bin >b-tiny
expect_file_error fmtcat b-tiny rate b-tiny out
for off in 9 20 40 100 200; do
	# flip every bit of one byte at offset $off
	{ head -c $off good.bin
	  dd if=good.bin bs=1 skip=$off count=1 2>/dev/null | od -An -tu1 |
		awk '{ printf "%c", 255 - $1 }'
	  tail -c +$((off + 2)) good.bin; } >b-flip$off
	[ "$(wc -c <b-flip$off)" -eq "$n" ] || fail "could not build b-flip$off"
	expect_file_error fmtcat b-flip$off rate b-flip$off out
	grep -q 'checksum\|version\|size\|bytes\|count' err.txt || fail "b-flip$off: unclear message: $(cat err.txt)"
done
{ cat good.bin; printf 'x'; } >b-long
expect_file_error fmtcat b-long rate b-long out
# a missing file and a directory
expect_error fmtcat rate no-such-file out
mkdir adir
expect_error fmtcat plot2 adir out
exit 0
