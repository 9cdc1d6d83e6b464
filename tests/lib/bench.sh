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
