#!/bin/sh
# etch -vtk and conv -vtk: VTK XML PolyData that VTK itself reads back.
# A bowl etched from a rate peak (two print times, so two pieces) is
# written as .vtp by etch -vtk and by conv -vtk from curves.plot: the two
# files are byte-identical.  Debian's python3-vtk9 (vtkXMLPolyDataReader,
# an independent reader) must find as many triangles as curves.plot has
# and as many points as its distinct vertices, every triangle's points
# equal to curves.plot's (1e-12 um), and the same total area as our own
# sum over curves.plot (relative 1e-9).  Skipped without python3-vtk9.
. "$TOP/tests/lib/common.sh"
MKRATE=$BUILD/tests/lib/mkrate
built "$MKRATE"
$MKRATE -o rate.bin 21 21 11 -1 1 -1 1 -0.5 0 '0.1 + 0.8 * exp(-(x^2 + y^2) / 0.2)' ||
	fail "mkrate"
etch -et 1 -pt 0.5 -q -vtk etch.vtp -no2d rate.bin || fail "etch -vtk"
[ -f etch.vtp ] || fail "no etch.vtp"
[ ! -f curves.plot.2D ] || fail "-no2d wrote curves.plot.2D"
conv -vtk curves.plot || fail "conv -vtk"
same etch.vtp curves.vtp
# our own figures from curves.plot: triangles, distinct vertices, area
awk '
	NF == 6 { set++; next }
	NF == 1 && !incurve { nc = $1; next }
	NF == 1 { next }
	NF == 3 { k++; x[k] = $1; y[k] = $2; z[k] = $3
		key = set " " $1 " " $2 " " $3; if (!(key in seen)) { seen[key] = 1; np++ }
		if (k == 4) { ntri++
			ax = x[2] - x[1]; ay = y[2] - y[1]; az = z[2] - z[1]
			bx = x[3] - x[1]; by = y[3] - y[1]; bz = z[3] - z[1]
			cx = ay * bz - az * by; cy = az * bx - ax * bz; cz = ax * by - ay * bx
			area += 0.5 * sqrt(cx * cx + cy * cy + cz * cz); k = 0 } }
	END { printf "%d %d %d %.15g\n", set, ntri, np, area }
' curves.plot >ours.txt
read sets ntri np area <ours.txt
[ "$sets" -eq 2 ] || fail "expected 2 sets in curves.plot, got $sets"
[ "$ntri" -gt 100 ] || fail "only $ntri triangles: the case is too small to test"
grep -q 'NumberOfPolys' etch.vtp || fail "no polys in etch.vtp"
PY=/usr/bin/python3
[ -x $PY ] || skip "python3 (Debian's) is not installed"
$PY -c 'import vtk' 2>/dev/null || skip "python3-vtk9 is not installed"
$PY - etch.vtp curves.plot >vtk.txt 2>&1 <<'PYEOF' || fail "VTK check: $(tail -n 3 vtk.txt)"
import sys, vtk
r = vtk.vtkXMLPolyDataReader()
r.SetFileName(sys.argv[1])
r.Update()
if r.GetErrorCode():
    sys.exit("reader error %d" % r.GetErrorCode())
pd = r.GetOutput()
ntri = 0
area = 0.0
tris = []
for c in range(pd.GetNumberOfCells()):
    cell = pd.GetCell(c)
    if cell.GetCellType() != vtk.VTK_TRIANGLE:
        sys.exit("cell %d is not a triangle" % c)
    ntri += 1
    p = [pd.GetPoint(cell.GetPointId(j)) for j in range(3)]
    area += vtk.vtkTriangle.TriangleArea(*p)
    tris.append(p)
# curves.plot, read independently: every triangle's corners in order
ref = []
cur = []
for line in open(sys.argv[2]):
    f = line.split()
    if len(f) == 3:
        cur.append(tuple(float(v) for v in f))
        if len(cur) == 4:
            ref.append(cur[:3]); cur = []
if len(ref) != ntri:
    sys.exit("VTK read %d triangles, curves.plot has %d" % (ntri, len(ref)))
worst = max(abs(a - b) for t, u in zip(tris, ref) for p, q in zip(t, u) for a, b in zip(p, q))
if worst > 1e-12:
    sys.exit("a triangle corner moved by %g um" % worst)
print(ntri, pd.GetNumberOfPoints(), "%.15g" % area)
PYEOF
read vtri vnp varea <vtk.txt
[ "$vtri" -eq "$ntri" ] || fail "VTK triangles $vtri, ours $ntri"
[ "$vnp" -eq "$np" ] || fail "VTK points $vnp, distinct vertices of curves.plot $np"
rel=$(awk -v a="$varea" -v b="$area" 'BEGIN { d = (a - b) / b; print d < 0 ? -d : d }')
close "$rel" 0 1e-9 "relative area difference VTK/ours (VTK $varea, ours $area)"
exit 0
