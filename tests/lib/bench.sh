# tests/lib/bench.sh - sourced by the benches (tests/bench/) that compare
# this tree with an older revision in the same run.
#
# bench_base NAME REV DIR [TARGET...]: exports revision REV of this
# repository (git archive) into DIR and builds TARGET... there (default
# all; make -j2, BUILD=build, its log in DIR.log).  On success base_bin is
# DIR/build/bin; otherwise base_bin is empty, a line "NAME: ..." says why
# and the status is 2 when REV is not in this repository (a shallow
# clone: nothing to compare with), 1 when the export or the build failed
# (with the log's last lines).  Needs TOP.
bench_base() {
	_bn=$1 _br=$2 _bd=$3
	shift 3
	[ $# -gt 0 ] || set -- all
	base_bin=
	if ! git -C "$TOP" rev-parse --verify -q "$_br^{commit}" >/dev/null; then
		echo "$_bn: base revision $_br not in this repository; no comparison"
		return 2
	fi
	mkdir -p "$_bd"
	if ! git -C "$TOP" archive "$_br" | tar -x -C "$_bd"; then
		echo "$_bn: git archive of $_br failed; no comparison"
		return 1
	fi
	if ! make -s -C "$_bd" -j2 BUILD=build "$@" >"$_bd.log" 2>&1; then
		echo "$_bn: building $_br failed; no comparison"
		tail -n 5 "$_bd.log"
		return 1
	fi
	base_bin=$_bd/build/bin
}

# bench_run LABEL COMMAND...: runs COMMAND once under /usr/bin/time -v
# (its output discarded) in the current directory, prints a line with its
# CPU (user + sys) and wall seconds and peak RSS (MB), and keeps "cpu wall
# peak-MB" in LABEL.fig; on failure prints the command's last lines and
# returns 1.  bench_fig LABEL FIELD prints one of them (1 cpu, 2 wall,
# 3 peak), or nan if the run left none.
bench_run() {
	_bl=$1
	shift
	/usr/bin/time -v -o t.txt "$@" >/dev/null 2>err.txt || { echo "  $_bl: failed"; tail -n 3 err.txt; return 1; }
	awk -F': ' '
		/User time/ { u = $2 } /System time/ { s = $2 } /Maximum resident/ { m = $2 }
		/Elapsed \(wall/ { n = split($2, a, ":"); w = 0; for (i = 1; i <= n; i++) w = 60 * w + a[i] }
		END { printf "%.2f %.2f %.1f\n", u + s, w, m / 1024 }' t.txt >"$_bl.fig"
	read -r _bc _bw _bm <"$_bl.fig"
	printf '  %-34s cpu %8.2f s  wall %8.2f s  peak %8.1f MB\n' "$_bl" "$_bc" "$_bw" "$_bm"
}
bench_fig() {
	[ -r "$1.fig" ] && awk -v f="$2" '{ print $f }' "$1.fig" || echo nan
}
