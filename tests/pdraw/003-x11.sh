# With X11 built and Xvfb installed: pdraw opens a window (found by name
# with xdotool), the key "z" turns the view to the x-y projection and "q"
# ends the preview; the PostScript written is then byte-identical to
# that of "pdraw -noplot -v 0 0 1" (the guide: the final view is the one
# printed).  Skipped without Xvfb, xdotool, or an X11 build.
. "$TOP/tests/lib/common.sh"
need Xvfb
need xdotool
printf '0 1 0 1 0 1\n2\n2\n0 0 0\n1 1 1\n3\n0 0 1\n1 0 0\n0 1 0\n' >v.3D
# Xvfb picks a free display itself and writes its number (-displayfd),
# so tests running at the same time never share a server; -noreset: by
# default the server resets when its last client (the xdotool probe
# below) leaves, and refuses connections meanwhile, which made pdraw fail
# now and then with "cannot open the X display"
Xvfb -displayfd 3 -screen 0 800x800x24 -nolisten tcp -noreset 3>dpy.txt >xvfb.log 2>&1 &
xpid=$!
trap 'kill $xpid 2>/dev/null' EXIT
i=0
until [ -s dpy.txt ]; do
	i=$((i + 1)); [ $i -lt 100 ] || skip "Xvfb did not start: $(head -c 200 xvfb.log)"; sleep 0.1
done
export DISPLAY=:$(head -n 1 dpy.txt)
i=0
until xdotool getmouselocation >/dev/null 2>&1; do
	i=$((i + 1)); [ $i -lt 100 ] || skip "Xvfb did not answer: $(head -c 200 xvfb.log)"; sleep 0.1
done
pdraw v.3D </dev/null >out.txt 2>err.txt &
ppid=$!
i=0 wid=
while [ -z "$wid" ]; do
	if ! kill -0 $ppid 2>/dev/null; then
		grep -q "built without X11" err.txt && skip "pdraw built without X11"
		fail "pdraw ended without a window: $(cat err.txt)"
	fi
	i=$((i + 1)); [ $i -lt 100 ] || { kill $ppid; fail "no pdraw window appeared"; }
	sleep 0.1
	wid=$(xdotool search --name '^pdraw$' 2>/dev/null | head -n 1)
done
xdotool key --window "$wid" z 2>/dev/null
sleep 0.3
xdotool key --window "$wid" q 2>/dev/null
i=0
while kill -0 $ppid 2>/dev/null; do
	i=$((i + 1)); [ $i -lt 100 ] || { kill $ppid; fail "pdraw did not end on q"; }
	sleep 0.1
done
wait $ppid || fail "pdraw failed: $(cat err.txt)"
mv dataplot.ps keys.ps
pdraw -noplot -v 0 0 1 v.3D </dev/null 2>/dev/null || fail "pdraw -v 0 0 1"
same keys.ps dataplot.ps
pdraw -noplot v.3D </dev/null 2>/dev/null
cmp -s keys.ps dataplot.ps && fail "the key z did not change the view"
exit 0
