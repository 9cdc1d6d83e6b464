# tests/lib/xcheck.sh - the check of the engines' cross-check tests
# (tests/xcheck/002, 004, 005): source it after common.sh.
# xcheck_log LOG: every "xcheck t = " line of etch -xcheck in LOG has its
# median under half an x-y cell and its 95th percentile under two.
xcheck_log() {
	grep -q 'xcheck t = ' "$1" || fail "$1: no xcheck report"
	grep 'xcheck t = ' "$1"
	grep 'xcheck t = ' "$1" | awk '{ for (i = 1; i <= NF; i++) if ($i == "x-y") { split($(i - 3), a, "("); m = a[2]; p = $(i - 1) } 
		if (!(m + 0 < 0.5 && p + 0 < 2)) bad = 1 } END { exit bad }' || fail "$1: the engines disagree"
}
