# fem writes the user's words into DIR/Makefile and the Slurm scripts: none
# of them may run as a command there.  Checked: the two injections through
# -measure (a -s value the probe cannot try) and -etch (an -o that etch's
# option check accepts) create no file and are refused in one line; a sweep
# from an odd directory (blanks, $, `, quotes, ;, #, % and a backslash in
# DIR and in the path of fem and its programs) runs, gives both points in
# fem.dat and runs nothing else; -slurm with such a DIR and -sbatch words
# gives sbatch exactly those words (a stand-in sbatch records its argv) and
# the scripts pass sh -n.  Against: the words themselves, byte for byte.
. "$TOP/tests/lib/common.sh"
E=$TOP/examples/contact
cp "$E/mask.in" mask.in
cp "$E/resist.in" resist.in
ok="-if mask.in -bf resist.in -et 10 -dose 60,70 -focus 0"
m="-rel 50 -hole 0 0"

expect_error fem $ok -measure '-s 1`id>PWNED` -rel 50 -hole 0 0' -d o1
grep -q -- "-s 1.id>PWNED.: expected a set number" err.txt || fail "-s: $(cat err.txt)"
expect_error fem $ok -measure "$m" -etch '-o x;id>PWNED3;:' -d o2
grep -q "drop -o" err.txt || fail "-etch -o: $(cat err.txt)"
expect_error fem $ok -measure "$m" -etch '-clip 1;id>PWNED4;:' -d o3
expect_error fem $ok -measure "$m" -d 'o4
x'
grep -q "newline" err.txt || fail "a newline in -d: $(cat err.txt)"
for p in PWNED PWNED3 PWNED4; do [ ! -e $p ] || fail "$p: an injected command ran"; done
for d in o1 o2 o3 o4; do [ ! -e $d ] || fail "$d: made for a refused sweep"; done

# fem and its programs in an odd folder, found beside fem (the Makefile's
# SPLAT, ETCH, ... variables), and an odd DIR
odd='o d$(id>PWNED6)`id>PWNED7`;#%'"'"'"x\#'
mkdir -p "bin/$odd"
cp "$(command -v fem)" "bin/$odd/fem"
cp "$(dirname "$(command -v fem)")/etchopts.sh" "bin/$odd/etchopts.sh"
for p in splat bleach etch measure femwin drawplot; do
	ln -s "$(command -v $p)" "bin/$odd/$p"
done
"bin/$odd/fem" -q $ok -measure "$m" -d "$odd" -j 2 >out.txt 2>err.txt ||
	fail "a sweep in an odd DIR failed: $(cat err.txt)"
[ "$(grep -c '^0 [67]0 ' "$odd/fem.dat")" -eq 2 ] || fail "expected two points in fem.dat: $(cat "$odd/fem.dat")"
grep -q "^SPLAT = .*bin/o d" "$odd/Makefile" || fail "the sweep did not use the programs beside fem"

# Slurm: the words reach sbatch as given
mkdir fake
cat >fake/sbatch <<'EOF'
#!/bin/sh
printf '%s\n' "$@" >>"$SBATCH_LOG"
echo 7
EOF
chmod +x fake/sbatch
sb='-p short;id>PWNED8 $(id>PWNED9) a'"'"'b c#d'
"bin/$odd/fem" -q $ok -measure "$m" -d "$odd" -slurm -sbatch "$sb" 2>err.txt ||
	fail "-slurm in an odd DIR: $(cat err.txt)"
for f in submit.sh fem.sbatch images.sbatch; do
	sh -n "$odd/$f" || fail "$f: not valid sh"
done
SBATCH_LOG=$PWD/sbatch.log PATH=$PWD/fake:$PATH sh "$odd/submit.sh" >submit.out 2>&1 ||
	fail "submit.sh: $(cat submit.out)"
# the words of -sbatch, one a line, then the script, twice
printf '%s\n' --parsable -p 'short;id>PWNED8' '$(id>PWNED9)' "a'b" 'c#d' images.sbatch >want.log
printf '%s\n' --parsable -p 'short;id>PWNED8' '$(id>PWNED9)' "a'b" 'c#d' --dependency=afterok:7 fem.sbatch >>want.log
same sbatch.log want.log
grep -q "fem -collect -d $PWD/o d" submit.out || fail "submit.sh: $(cat submit.out)"
for p in PWNED6 PWNED7 PWNED8 PWNED9; do
	[ ! -e $p ] && [ ! -e "$odd/$p" ] && [ ! -e "$odd/f0/$p" ] || fail "$p: an injected command ran"
done
exit 0
