# -xlog/-ylog put the decades evenly: over 1..1000 the tick labels 1, 10,
# 100, 1000 sit at equal distances (from the PostScript text positions,
# tolerance 0.02 pt: two-decimal coordinates).  Points <= 0 are
# dropped, not a crash.
. "$TOP/tests/lib/common.sh"
printf '1 1000 1 1000\n1\n4\n1 1\n10 10\n1000 1000\n0 5\n' >g.2D
drawplot -noplot -xlog -ylog g.2D </dev/null || fail "drawplot -xlog -ylog"
gs_check dataplot.ps
# x tick labels: "(text) x y 10 0 0 1 T" (centred, hanging below the axis)
for v in 1 10 100 1000; do
	awk -v v="($v)" '$1 == v && $6 == 0 && $7 == 1 { print $2; exit }' dataplot.ps
done >xs.txt
[ "$(wc -l <xs.txt)" -eq 4 ] || fail "decade labels missing: $(cat xs.txt)"
set -- $(cat xs.txt)
d1=$(awk -v a="$1" -v b="$2" 'BEGIN { print b - a }')
d2=$(awk -v a="$2" -v b="$3" 'BEGIN { print b - a }')
d3=$(awk -v a="$3" -v b="$4" 'BEGIN { print b - a }')
close "$d1" "$d2" 0.02 "decade 1-10 vs 10-100"
close "$d2" "$d3" 0.02 "decade 10-100 vs 100-1000"
exit 0
