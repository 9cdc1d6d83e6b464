# make_sram.py - writes sram.gds, the layout clip of examples/layout, with
# gdspy (Debian python3-gdspy): a 6T-like SRAM bit cell at g-line scale
# (4 x 5 um, 1 um active lines) arrayed 2 x 1 and mirrored about x above
# (as SRAM rows are), so the clip holds references, an array, a
# reflection, paths with a 45-degree mitred bend and overlapping shapes.
#   active  layer 1/0: two vertical bars and a cross-coupling path that
#           overlaps them, with a 45-degree jog
#   contact layer 1/1: small squares (not simulated: another datatype)
#   poly    layer 2/0: word line and gates (a decoy for the active mask)
#   outline layer 10/0: the cell boundary
# Run: python3 make_sram.py (writes sram.gds here; the committed copy was
# made this way, with the fixed timestamp below).
import datetime
import gdspy

lib = gdspy.GdsLibrary(unit=1e-6, precision=1e-9)
bit = gdspy.Cell("BIT", exclude_from_current=True)
bit.add(gdspy.Rectangle((0.4, 0.3), (1.4, 4.7), layer=1))
bit.add(gdspy.Rectangle((2.6, 0.3), (3.6, 4.7), layer=1))
bit.add(gdspy.FlexPath([(1.0, 1.6), (2.0, 1.6), (3.0, 2.6)], 0.8, ends="flush",
                       gdsii_path=True, layer=1))
for (x, y) in [(0.65, 0.55), (2.85, 4.05)]:
    bit.add(gdspy.Rectangle((x, y), (x + 0.5, y + 0.5), layer=1, datatype=1))
bit.add(gdspy.FlexPath([(0.0, 3.5), (4.0, 3.5)], 0.6, ends="extended",
                       gdsii_path=True, layer=2))
bit.add(gdspy.Rectangle((0, 0), (4, 5), layer=10))
top = gdspy.Cell("SRAM", exclude_from_current=True)
top.add(gdspy.CellArray(bit, 2, 1, (4, 5), (0, 0)))
top.add(gdspy.CellArray(bit, 2, 1, (4, 5), (0, 10), x_reflection=True))
lib.add(bit)
lib.add(top)
lib.write_gds("sram.gds", timestamp=datetime.datetime(2026, 1, 1))
