# The GDSII reader on a malformed corpus (truncated files, wrong record
# lengths and data types, absurd units and counts, reference loops and
# explosions, missing cells, garbage): every case is one line on stderr,
# "splat: IN:LINE: FILE: byte N: what", a non-zero exit, no output and no
# crash or sanitizer report.  Byte offsets of the patched records are
# those of the file mkgds writes (HEADER 0, BGNLIB 6, LIBNAME 34, UNITS
# 44, BGNSTR 64, STRNAME 92, BOUNDARY 100, LAYER 104, DATATYPE 110, XY
# 116, ENDEL 160, ENDSTR 164, ENDLIB 168; 172 bytes).
. "$TOP/tests/lib/common.sh"
M=$BUILD/tests/lib/mkgds
[ -x "$M" ] || fail "no mkgds"
"$M" grid 1 1 0.5 ok.gds || fail "mkgds"
[ "$(wc -c <ok.gds)" -eq 172 ] || fail "mkgds wrote $(wc -c <ok.gds) bytes, expected 172"
n=0
check() {  # check FILE PATTERN [STATEMENT-TAIL]: splat must fail on FILE naming PATTERN
	n=$((n + 1))
	printf 'window -2 2 -2 2\ngds %s layer 1%s\n' "$1" "${3:-}" >c$n.in
	expect_error splat -q -o c$n.cont c$n.in
	grep -q "^splat: c$n.in:2: $1: byte [0-9]*: " err.txt ||
		fail "case $n ($1): not 'file: byte N:': $(cat err.txt)"
	grep -q "$2" err.txt || fail "case $n ($1): message lacks '$2': $(cat err.txt)"
	[ ! -e c$n.cont ] || fail "case $n: output written"
}
patch() {  # patch OUT OFFSET OCTAL-BYTES: a copy of ok.gds with bytes replaced
	cp ok.gds "$1"
	printf "$3" | dd of="$1" bs=1 seek="$2" conv=notrunc 2>/dev/null
}
printf 'window -2 2 -2 2\ngds ok.gds layer 1\n' >good.in
splat -q -o good.cont good.in || fail "the unpatched file fails: $(cat err.txt)"

: >empty.gds
check empty.gds "truncated file"
printf 'this is not a layout at all\n' >text.gds
check text.gds "runs past the end"
patch p1.gds 116 '\000\052';     check p1.gds "byte 116: XY record has 38 data bytes"
patch p2.gds 104 '\000\002';     check p2.gds "byte 104: bad record length 2"
patch p3.gds 116 '\177\376';     check p3.gds "byte 116: truncated file"
patch p4.gds 107 '\006';         check p4.gds "byte 104: LAYER record has data type 6"
patch p5.gds 56 '\000\000\000\000\000\000\000\000'; check p5.gds "byte 44: UNITS"
patch p6.gds 162 '\007';         check p6.gds "byte 160: ENDSTR record inside an element"
patch p7.gds 2 '\005';           check p7.gds "byte 0: not a GDSII"
patch p8.gds 102 '\020';         check p8.gds "byte 100: "
patch p9.gds 170 '\000';         check p9.gds "byte 168: second HEADER"
head -c 168 ok.gds >t1.gds;     check t1.gds "truncated file: no ENDLIB"
head -c 170 ok.gds >t2.gds;     check t2.gds "truncated"
# every truncation of a gdspy file with references, arrays and paths
cp "$TOP/tests/gds/data/refs.gds" .
size=$(wc -c <refs.gds)
k=0
while [ $k -lt "$size" ]; do
	head -c $k refs.gds >tr$k.gds
	check tr$k.gds "."
	k=$((k + 37))
done
# references: loops, depth, explosions, missing cells
cp "$TOP/tests/gds/data/cycle.gds" .
check cycle.gds "reference loop"
"$M" chain 1200 deep.gds;        check deep.gds "nested more than 1000 deep"
"$M" array 32767 32767 wide.gds; check wide.gds 'cell "TOP" layer 1 gives 1.07e+09 shapes .* use -big'
# with -big the walk is still bounded, before it starts
printf 'window -2 2 -2 2\ngds wide.gds layer 1\n' >wide.in
expect_error splat -big -q -o wide.cont wide.in
grep -q "visits 2.15e+09 elements, more than 50000000" err.txt || fail "wide.gds -big: $(cat err.txt)"
"$M" array 0 1 zero.gds;         check zero.gds "COLROW 0 1"
"$M" chain 2 c2.gds
cp c2.gds miss.gds; printf '9' | dd of=miss.gds bs=1 seek=105 conv=notrunc 2>/dev/null
check miss.gds 'byte 96: SREF to a missing cell "C9"'
cp c2.gds self.gds; printf '0' | dd of=self.gds bs=1 seek=105 conv=notrunc 2>/dev/null
check self.gds 'reference loop' " cell C0"
check c2.gds 'no cell named "X"' " cell X"
# not a regular file: a device would be read without end
printf 'window -2 2 -2 2\ngds /dev/zero layer 1\n' >dev.in
expect_error splat -q -o dev.cont dev.in
grep -q "^splat: dev.in:2: /dev/zero: not a regular file" err.txt || fail "/dev/zero: $(cat err.txt)"
exit 0
