# measure on etch's own output, against closed forms:
#   - a flat front: 0.1 um/s everywhere for 1, 2, 3 s (ray-string): the
#     front at z = -0.1 t, so above it a space is the whole box and below
#     it a line is, the resist loss of set t is 0.1 t (within 1e-6 um: a
#     uniform rate moves the ray-string nodes exactly), never cleared;
#   - a cylinder-like hole (fast marching): a rate of 20 um/s inside
#     r = 0.4 um falling to 0.05 um/s outside,
#     R(r) = 0.05 + 19.95 / (1 + exp((r - 0.4) / 0.05)),
#     for 1.5 s through 0.5 um.  The core develops through in 0.03 s, then
#     the wall moves out radially: its radius solves int_0^r dr'/R = t,
#     the same at every height, so cd = 2 r within 1 % (the engine's
#     error on this 0.025 um grid, 0.2 %, and the core's 0.03 s), the wall
#     vertical within 1 degree between 10 and 50 %, and the resist loss
#     beside it R(1) t (the top far from the hole) within 1e-4 um.
. "$TOP/tests/lib/common.sh"
mkrate=$BUILD/tests/lib/mkrate
figure() { awk -v k="# $2" 'index($0, k " ") == 1 { print $3 }' "$1"; }
cd_at() { awk -v z="$2" '!/^#/ && $1 == z { print $2 }' "$1"; }

"$mkrate" -o flat.bin 11 11 8 -1 1 -1 1 -0.7 0 0.1 || fail "mkrate flat"
etch -q -et 3 -pt 1 -o flat.plot flat.bin || fail "etch flat"
for t in 1 2 3; do
	above=$(awk -v t=$t 'BEGIN { print -0.1 * t + 0.05 }')
	below=$(awk -v t=$t 'BEGIN { print -0.1 * t - 0.05 }')
	measure -s $t -at "$above,$below" -space 0.3 -0.2 x flat.plot >s$t.txt 2>/dev/null || fail "measure flat set $t"
	close "$(cd_at s$t.txt "$above")" 2 1e-6 "set $t: space above the front"
	close "$(cd_at s$t.txt "$below")" 0 0 "set $t: space below the front"
	close "$(figure s$t.txt resist_loss)" "$(awk -v t=$t 'BEGIN { print 0.1 * t }')" 1e-6 "set $t: resist loss"
	[ "$(figure s$t.txt cleared)" = no ] || fail "set $t: cleared: $(cat s$t.txt)"
	measure -s $t -at "$below" -line 0.3 -0.2 y flat.plot >l$t.txt 2>/dev/null || fail "measure flat line $t"
	close "$(cd_at l$t.txt "$below")" 2 1e-6 "set $t: line below the front"
done

"$mkrate" -o cyl.bin 81 81 11 -1 1 -1 1 -0.5 0 \
	"0.05 + 19.95 / (1 + exp((sqrt(x * x + y * y) - 0.4) / 0.05))" || fail "mkrate cylinder"
etch -q -et 1.5 -method fmm -o cyl.plot cyl.bin || fail "etch -method fmm cylinder"
measure -rel 10,50 -hole 0 0 cyl.plot >cyl.txt || fail "measure cylinder: $(cat cyl.txt)"
cd=$(awk 'BEGIN { r = 0; dr = 1e-5; t = 0
	while (t < 1.5) { R = 0.05 + 19.95 / (1 + exp((r + dr / 2 - 0.4) / 0.05)); t += dr / R; r += dr }
	print 2 * r }')
for z in -0.45 -0.25; do
	close "$(cd_at cyl.txt $z)" "$cd" "$(awk -v c="$cd" 'BEGIN { print 0.01 * c }')" "cylinder cd at z = $z"
done
close "$(figure cyl.txt swa)" 90 1 "cylinder wall angle"
close "$(figure cyl.txt resist_loss)" "$(awk 'BEGIN { print 1.5 * (0.05 + 19.95 / (1 + exp(0.6 / 0.05))) }')" 1e-4 \
	"cylinder resist loss"
[ "$(figure cyl.txt cleared)" = yes ] || fail "cylinder not cleared: $(cat cyl.txt)"
exit 0
