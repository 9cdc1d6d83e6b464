# mklayout.py CASE OUT.gds OUT.in - writes a test layout with gdspy (a
# real GDSII writer, not ours) and, from gdspy's own flattening
# (get_polygons), the same shapes of layer 1 datatype 0 as splat polygon
# statements, so tests can compare our reader with an independent one.
#   refs    references rotated (90, 180, 30 degrees), reflected and
#           magnified, an array with rotation, overlapping shapes, and
#           decoy shapes on layer 2 and on layer 1 datatype 1
#   paths   paths of pathtype 0, 2 and 4 with bends (mitred joins)
#   round   a path of pathtype 1 (round ends)
#   boxes   overlapping rectangles on a nanometre grid (comparable with
#           rect statements) and decoys; a second top cell OTHER
#   cycle   cells A and B referencing each other under TOP
#   sram    a small SRAM-like cell arrayed 2x2 (examples/layout)
import sys
import datetime
import gdspy

STAMP = datetime.datetime(2026, 1, 1)  # fixed, so the files are reproducible

case, out_gds, out_in = sys.argv[1], sys.argv[2], sys.argv[3]
lib = gdspy.GdsLibrary(unit=1e-6, precision=1e-9)

def new_cell(name):
    c = gdspy.Cell(name, exclude_from_current=True)
    lib.add(c)
    return c

def decoys(c):
    c.add(gdspy.Rectangle((-3, -3), (3, 3), layer=2))
    c.add(gdspy.Rectangle((-0.2, -2.5), (0.2, 2.5), layer=1, datatype=1))
    c.add(gdspy.Label("decoy", (0, 0), layer=1))

if case == "refs":
    leaf = new_cell("LEAF")
    leaf.add(gdspy.Polygon([(0, 0), (0.6, 0), (0.6, 0.2), (0.2, 0.2), (0.2, 0.5), (0, 0.5)], layer=1))
    leaf.add(gdspy.Rectangle((0.1, 0.1), (0.4, 0.35), layer=1))       # overlaps the L
    leaf.add(gdspy.Rectangle((0, 0), (0.3, 0.3), layer=3))            # decoy
    top = new_cell("TOP")
    top.add(gdspy.CellReference(leaf, (-2.0, -2.0)))
    top.add(gdspy.CellReference(leaf, (1.5, -2.0), rotation=90))
    top.add(gdspy.CellReference(leaf, (1.5, 1.5), rotation=180, x_reflection=True))
    top.add(gdspy.CellReference(leaf, (-1.8, 0.6), rotation=30, magnification=1.5))
    top.add(gdspy.CellArray(leaf, 3, 2, (0.8, 0.7), (-0.6, -1.2), rotation=90))
    top.add(gdspy.Polygon([(-0.3, 1.0), (0.6, 1.3), (0.2, 2.1)], layer=1))
    top.add(gdspy.Rectangle((0.0, 1.2), (0.9, 1.5), layer=1))         # overlaps the triangle
    decoys(top)
    cell = top
elif case in ("paths", "round"):
    top = new_cell("TOP")
    if case == "paths":
        top.add(gdspy.FlexPath([(-2.5, -2), (-0.5, -2), (-0.5, -0.5)], 0.3, ends="flush",
                               gdsii_path=True, layer=1))
        top.add(gdspy.FlexPath([(0.5, -2.2), (2.2, -2.2), (2.2, 0)], 0.25, ends="extended",
                               gdsii_path=True, layer=1))
        top.add(gdspy.FlexPath([(-2.2, 0.5), (-1, 0.5), (0, 1.5), (1.5, 1.5)], 0.2,
                               ends=(0.1, 0.3), gdsii_path=True, layer=1))
    else:
        top.add(gdspy.FlexPath([(-1.5, 0), (1.5, 0)], 0.6, ends="round", tolerance=1e-5,
                               gdsii_path=True, layer=1))
    decoys(top)
    cell = top
elif case == "boxes":
    top = new_cell("TOP")
    for (x0, y0, x1, y1) in [(-2.5, -1.5, -0.5, -0.5), (-1.0, -1.0, 0.25, 0.75),
                             (0.5, -2.0, 1.125, 2.0), (-2.0, 1.25, 2.0, 1.75),
                             (1.0, 1.0, 2.5, 1.5)]:
        top.add(gdspy.Rectangle((x0, y0), (x1, y1), layer=1))
    decoys(top)
    other = new_cell("OTHER")
    other.add(gdspy.Rectangle((0, 0), (1, 1), layer=1))
    cell = top
elif case == "cycle":
    top = new_cell("TOP")
    a = new_cell("A")
    b = new_cell("B")
    a.add(gdspy.Rectangle((0, 0), (1, 1), layer=1))
    a.add(gdspy.CellReference(b, (2, 0)))
    b.add(gdspy.CellReference(a, (0, 2)))
    top.add(gdspy.CellReference(a, (0, 0)))
    lib.write_gds(out_gds, timestamp=STAMP)
    open(out_in, "w").close()
    sys.exit(0)
elif case == "sram":
    bit = new_cell("BIT")
    # a 6T-like bit cell on a 1.2 x 1.6 um pitch: diffusion (1) and poly (2)
    bit.add(gdspy.Rectangle((0.1, 0.1), (0.35, 1.5), layer=1))
    bit.add(gdspy.Rectangle((0.85, 0.1), (1.1, 1.5), layer=1))
    bit.add(gdspy.Polygon([(0.35, 0.6), (0.55, 0.6), (0.55, 0.3), (0.85, 0.3), (0.85, 0.5),
                           (0.65, 0.5), (0.65, 0.8), (0.35, 0.8)], layer=1))
    bit.add(gdspy.FlexPath([(0.0, 1.1), (0.6, 1.1), (0.6, 1.3), (1.2, 1.3)], 0.15,
                           gdsii_path=True, layer=2))
    bit.add(gdspy.Rectangle((0.0, 0.0), (1.2, 1.6), layer=10))       # cell boundary
    top = new_cell("SRAM")
    top.add(gdspy.CellArray(bit, 2, 2, (1.2, 1.6), (0, 0)))
    top.add(gdspy.CellArray(bit, 2, 2, (1.2, 1.6), (4.8, 0), x_reflection=True))
    cell = top
else:
    sys.exit("unknown case " + case)

lib.write_gds(out_gds, timestamp=STAMP)
polys = cell.get_polygons(by_spec=True).get((1, 0), [])
with open(out_in, "w") as f:
    for p in polys:
        f.write("polygon " + " ".join(repr(float(v)) for xy in p for v in xy) + "\n")
