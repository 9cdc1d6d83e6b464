# measure -ler on exact synthetic rough lines and spaces (tests/lib/roughsurf:
# planar faces, so the section at half height passes through the known
# edge values, straight between mesh rows):
#   - sine edges on 2048 rows against the closed form: LER = 3 A / sqrt(2),
#     LWR = 3 sqrt((A1^2 + A2^2) / 2) (two frequencies, orthogonal),
#     corr_length = L acos(1/e) / (2 pi n) averaged over the two edges
#     (the sampled sine's periodic autocorrelation is cos(2 pi n k / N));
#     LER, LWR within 0.2 %, corr_length within 1 %;
#   - the PSD file (plot2d): two curves of N/2 points at f = k / L, the
#     sine's power A^2 L / 2 at its frequency (0.1 %), and Parseval: the
#     sum of each curve / L is (LER / 3)^2 (0.1 %); drawplot draws it on
#     log axes;
#   - AR(1) edges on 4096 rows, a space along x (cut along y), and a
#     white-noise edge on 300 rows (read on 1200 lines, 4 per row, where
#     reading only the rows would be 20 % off), and sine edges on rows
#     jittered off a grid (read on 1024 evenly spaced lines): against
#     tests/measure/edges.awk, measure(1)'s definitions computed in awk
#     from the known edges at the same lines: LER, LWR within 0.1 %,
#     corr_length within 1 %;
#   - the usual table comes first, the roughness lines after it, and the
#     output is the same bytes with 1, 2 and 3 threads.
. "$TOP/tests/lib/common.sh"
RS=$BUILD/tests/lib/roughsurf
[ -x "$RS" ] || fail "tests/lib/roughsurf is not built"
PI=3.14159265358979
fig() { awk -v k="# $2" 'index($0, k " ") == 1 { print $3 }' "$1"; }
ler_left() { awk '/^# ler left / { print $4 }' "$1"; }
ler_right() { awk '/^# ler left / { print $6 }' "$1"; }
# rel A B TOL WHAT: |A / B - 1| <= TOL
rel() {
	awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a / b - 1; if (d < 0) d = -d; exit !(b != 0 && d <= t) }' ||
		fail "$4: $1 is not within $3 (relative) of $2"
}
# against TABLE EXPECTED(ler_left ler_right lwr corr) WHAT
against() {
	set -- "$1" "$(cat "$2")" "$3"
	exp_l=$(echo "$2" | awk '{ print $1 }') exp_r=$(echo "$2" | awk '{ print $2 }')
	exp_w=$(echo "$2" | awk '{ print $3 }') exp_c=$(echo "$2" | awk '{ print $4 }')
	rel "$(ler_left "$1")" "$exp_l" 0.001 "$3 ler left"
	rel "$(ler_right "$1")" "$exp_r" 0.001 "$3 ler right"
	rel "$(fig "$1" lwr)" "$exp_w" 0.001 "$3 lwr"
	rel "$(fig "$1" corr_length)" "$exp_c" 0.01 "$3 corr_length"
}

# sine edges: left -0.2 + 0.01 sin(8 theta), right 0.2 + 0.006 sin(5 theta + 1)
"$RS" line -left sin:-0.2:0.01:8:0 -right sin:0.2:0.006:5:1 -truth sine.txt -o sine.plot ||
	fail "roughsurf line failed"
measure -rel 50 -ler -line 0 0 x -psd psd.plot sine.plot >sine.out || fail "measure -ler: $(cat sine.out)"
rel "$(ler_left sine.out)" "$(awk 'BEGIN { print 3 * 0.01 / sqrt(2) }')" 0.002 "sine ler left"
rel "$(ler_right sine.out)" "$(awk 'BEGIN { print 3 * 0.006 / sqrt(2) }')" 0.002 "sine ler right"
rel "$(fig sine.out lwr)" "$(awk 'BEGIN { print 3 * sqrt((0.01^2 + 0.006^2) / 2) }')" 0.002 "sine lwr"
rel "$(fig sine.out corr_length)" \
	"$(awk -v pi=$PI 'BEGIN { c = atan2(sqrt(1 - exp(-2)), exp(-1)); print 2 * c / (2 * pi) * (1 / 8 + 1 / 5) / 2 }')" \
	0.01 "sine corr_length"
# the table first, then the roughness lines, in the order of measure(1)
awk '/^#/ { print $2 }' sine.out | tr '\n' ' ' | grep -q '^z resist_loss cleared ler lwr corr_length $' ||
	fail "sine: table and roughness lines out of order: $(cat sine.out)"
# the PSD: curve 1 the left edge (sin 8 theta: f = 8 / 2 um), 2 the right
awk '/^#/ { next } { print }' psd.plot | awk '
	NR == 1 { if ($1 != 0.5 || $2 != 512) exit 1; next }
	NR == 2 { if ($1 != 2) exit 2; next }
	NF == 1 { c++; if ($1 != 1024) exit 3; k = 0; next }
	{ k++; if ($1 != k / 2) exit 4; s[c] += $2 / 2
	  if ($2 > top[c]) { top[c] = $2; at[c] = $1 } }
	END { printf "%.9g %.9g %.9g %.9g %.9g %.9g\n", at[1], top[1], s[1], at[2], top[2], s[2] }' >psd.txt ||
	fail "psd.plot is not two curves of 1024 points at f = k / 2 um (step $?): $(head -5 psd.plot)"
read -r at1 top1 sum1 at2 top2 sum2 <psd.txt
[ "$at1" = 4 ] && [ "$at2" = 2.5 ] || fail "PSD peaks at $at1 and $at2 /um, expected 4 and 2.5"
rel "$top1" "$(awk 'BEGIN { print 0.01^2 * 2 / 2 }')" 0.001 "left PSD peak"
rel "$top2" "$(awk 'BEGIN { print 0.006^2 * 2 / 2 }')" 0.001 "right PSD peak"
rel "$sum1" "$(awk -v l="$(ler_left sine.out)" 'BEGIN { print (l / 3)^2 }')" 0.001 "left PSD sum (Parseval)"
rel "$sum2" "$(awk -v l="$(ler_right sine.out)" 'BEGIN { print (l / 3)^2 }')" 0.001 "right PSD sum (Parseval)"
drawplot -xlog -ylog -noplot -svg psd.svg psd.plot 2>err.txt || fail "drawplot -xlog -ylog psd.plot: $(cat err.txt)"
[ -s psd.svg ] || fail "drawplot wrote no picture of psd.plot"

# AR(1) edges on 4096 rows, a space along x (roughsurf -swap), cut along y
"$RS" space -swap -rows 4096 -left ar:-0.15:0.004:12:5 -right ar:0.15:0.003:6:9 \
	-truth ar.txt -o ar.plot || fail "roughsurf space failed"
measure -rel 50 -ler -space 0 0 y ar.plot >ar.out || fail "measure -ler -space: $(cat ar.out)"
awk -v at=rows -f "$TOP/tests/measure/edges.awk" ar.txt >ar.exp
against ar.out ar.exp "AR(1) space"
for t in 1 2 3; do
	SAMPLE3D_THREADS=$t measure -rel 50 -ler -space 0 0 y -psd p$t.plot ar.plot >t$t.out ||
		fail "measure with $t threads"
done
same t1.out t2.out
same t1.out t3.out
same p1.plot p2.plot
same p1.plot p3.plot

# white noise on 300 rows: read on 1200 lines, every row divided in 4
"$RS" line -rows 300 -left ar:-0.2:0.005:0.01:3 -right ar:0.2:0.005:0.01:4 \
	-truth w.txt -o w.plot || fail "roughsurf line -rows 300 failed"
measure -rel 50 -ler -line 0.01 0.3 x -psd wpsd.plot w.plot >w.out || fail "measure -ler 300 rows: $(cat w.out)"
awk -v at=sub -v n=1200 -f "$TOP/tests/measure/edges.awk" w.txt >w.exp
against w.out w.exp "300 rows"
[ "$(awk '!/^#/ && NF == 1 { print; exit }' wpsd.plot)" = 2 ] &&
	[ "$(awk '!/^#/ && NF == 1 { n++ } n == 2 { print; exit }' wpsd.plot)" = 600 ] ||
	fail "300 rows: the PSD is not of 1200 lines: $(head -5 wpsd.plot)"
# (reading the rows alone would give a LER 20 % higher: the test can tell)
awk -v at=rows -f "$TOP/tests/measure/edges.awk" w.txt >wrows.exp
awk 'NR == FNR { a = $1; next } { if (a / $1 < 1.1) exit 1 }' wrows.exp w.exp ||
	fail "300 rows: rows and lines give the same LER; the test cannot tell them apart"

# rows jittered off the grid: 1024 lines at the middles of equal parts
"$RS" line -jitter 7 -left sin:-0.2:0.01:8:0:0.004:21:2 -right sin:0.2:0.008:3:0 \
	-truth j.txt -o j.plot || fail "roughsurf line -jitter failed"
measure -rel 50 -ler -line 0 0 x j.plot >j.out || fail "measure -ler jittered: $(cat j.out)"
awk -v at=mid -v n=1024 -f "$TOP/tests/measure/edges.awk" j.txt >j.exp
against j.out j.exp "jittered rows"
exit 0
