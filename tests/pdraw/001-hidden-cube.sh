# pdraw -h: a unit cube of six closed faces seen from the corner (1,1,1)
# shows no back edges.  Checked against an independent picture: the nine
# visible edges drawn as plain lines with the same bounds (so the same
# page mapping), rendered by ghostscript at one pixel per point.  The
# hidden-line image must match it: dark pixels of either with no dark
# pixel within one pixel in the other, at most 2% of the reference's
# (rasterisation of a polygon outline vs. separate segments).  The cube
# without -h must differ by more than 10% (its three back edges), so the
# comparison can fail.
. "$TOP/tests/lib/common.sh"
need gs
B="-0.1 1.1 -0.1 1.1 -0.1 1.1"
face() { printf '5\n%s\n%s\n%s\n%s\n%s\n' "$1" "$2" "$3" "$4" "$1"; }
{
	echo "$B"; echo 6
	face "0 0 0" "1 0 0" "1 1 0" "0 1 0"
	face "0 0 1" "1 0 1" "1 1 1" "0 1 1"
	face "0 0 0" "1 0 0" "1 0 1" "0 0 1"
	face "0 1 0" "1 1 0" "1 1 1" "0 1 1"
	face "0 0 0" "0 1 0" "0 1 1" "0 0 1"
	face "1 0 0" "1 1 0" "1 1 1" "1 0 1"
} >cube.3D
seg() { printf '2\n%s\n%s\n' "$1" "$2"; }
{
	echo "$B"; echo 9
	seg "1 0 0" "1 1 0"; seg "1 1 0" "1 1 1"; seg "1 1 1" "1 0 1"; seg "1 0 1" "1 0 0"
	seg "0 1 0" "1 1 0"; seg "1 1 1" "0 1 1"; seg "0 1 1" "0 1 0"
	seg "0 0 1" "1 0 1"; seg "0 1 1" "0 0 1"
} >visible.3D
render() {
	gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=pgm -r72 -sOutputFile="$2" "$1" </dev/null >gs.out 2>&1 ||
		fail "ghostscript failed on $1: $(head -c 300 gs.out)"
}
pdraw -noplot -v 1 1 1 -h cube.3D </dev/null || fail "pdraw -h failed"
gs_check dataplot.ps
render dataplot.ps hidden.pgm
pdraw -noplot -v 1 1 1 cube.3D </dev/null || fail "pdraw failed"
render dataplot.ps plain.pgm
pdraw -noplot -v 1 1 1 visible.3D </dev/null || fail "pdraw failed on the reference"
render dataplot.ps ref.pgm
set -- $(awk -v mode=diff -f "$TOP/tests/pdraw/pixels.awk" hidden.pgm ref.pgm)
echo "hidden vs reference: dark $1 / $2, only in hidden $3, only in reference $4"
[ "$2" -gt 500 ] || fail "reference picture has too little ink ($2 dark pixels)"
[ $(( $3 * 50 )) -le "$2" ] || fail "hidden-line cube has $3 dark pixels the reference lacks (back edges?)"
[ $(( $4 * 50 )) -le "$2" ] || fail "hidden-line cube lacks $4 dark pixels of the visible edges"
set -- $(awk -v mode=diff -f "$TOP/tests/pdraw/pixels.awk" plain.pgm ref.pgm)
echo "plain vs reference: only in plain $3"
[ $(( $3 * 10 )) -gt "$2" ] || fail "the check cannot see back edges (plain cube differs by only $3)"
exit 0
