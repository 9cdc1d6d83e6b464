# etch interrupted keeps the print times it finished: killed (SIGTERM; a
# ^C's SIGINT and SIGHUP take the same path) once curves.plot's temporary
# holds two whole sets, etch dies of the signal (143), says in one line
# "etch: interrupted: FILE keeps the K print times finished", and leaves
# FILE holding exactly K whole sets: byte-identical to a run with
# -et K -pt 1 (the same steps, cut at print time K), no temporary left.
# Killed before its first print time, it says nothing was written and
# leaves no file.
. "$TOP/tests/lib/common.sh"
built splat bleach etch
E=$TOP/examples/contact
splat -q -o image.cont "$E/mask.in" && bleach -q image.cont "$E/resist.in" || fail "splat, bleach"
# a slow run: 60 print times of a fine mesh, one thread
etch -q -et 60 -pt 1 -seg 0.03 -threads 1 -o slow.plot rval.3D.binary 2>err.txt &
pid=$!
n=0
until [ "$(cat slow.plot.tmp* 2>/dev/null | grep -c '^$')" -ge 2 ]; do
	sleep 0.1
	n=$((n + 1))
	[ $n -lt 3000 ] || { kill "$pid"; fail "etch wrote no two print times in 300 s"; }
	kill -0 "$pid" 2>/dev/null || fail "etch ended before it could be interrupted"
done
kill -TERM "$pid"
wait "$pid"
st=$?
[ $st -eq 143 ] || fail "interrupted etch: exit $st, expected 143: $(cat err.txt)"
[ "$(wc -l <err.txt)" -eq 1 ] || fail "not one line: $(cat err.txt)"
k=$(sed -n 's/^etch: interrupted: slow.plot keeps the \([0-9]*\) print times finished$/\1/p' err.txt)
[ -n "$k" ] || fail "no line saying what was kept: $(cat err.txt)"
[ "$k" -ge 2 ] && [ "$k" -lt 60 ] || fail "kept $k print times"
[ -z "$(ls | grep '\.tmp')" ] || fail "temporaries left: $(ls)"
etch -q -et "$k" -pt 1 -seg 0.03 -threads 1 -o short.plot rval.3D.binary || fail "etch -et $k"
same slow.plot short.plot
# before the first print time: nothing
etch -q -et 60 -seg 0.03 -threads 1 -o none.plot rval.3D.binary 2>err2.txt &
pid=$!
until ls none.plot.tmp* >/dev/null 2>&1; do sleep 0.05; done
kill -TERM "$pid"
wait "$pid"
[ $? -eq 143 ] || fail "interrupted etch (no print time): not 143"
grep -qx 'etch: interrupted before the first of the print times: nothing written' err2.txt ||
	fail "no line saying nothing was written: $(cat err2.txt)"
[ ! -e none.plot ] || fail "a file was written with no print time finished"
exit 0
