# klayout.rb - run by tests/gds/004-klayout.sh as "klayout -b -r klayout.rb":
# KLayout (a second real GDSII writer) writes k.gds: a cell LEAF with a
# polygon with a hole (written as a cut polygon), a path with begin and
# end extensions (pathtype 4) and a decoy box on layer 2, placed in TOP
# once mirrored, rotated by 90 degrees and magnified 2, and as a 2 x 2
# array rotated by 270 degrees.  KLayout then flattens and merges layer
# 1/0 itself and writes the result, cut into convex pieces, as splat
# polygon statements (k.in).
ly = RBA::Layout.new
ly.dbu = 0.001
top = ly.create_cell("TOP")
leaf = ly.create_cell("LEAF")
l1 = ly.layer(1, 0)
l2 = ly.layer(2, 0)
pt = lambda { |x, y| RBA::DPoint.new(x, y) }
poly = RBA::DPolygon.new([pt.(0, 0), pt.(1, 0), pt.(1, 1), pt.(0, 1)])
poly.insert_hole([pt.(0.3, 0.3), pt.(0.7, 0.3), pt.(0.7, 0.7), pt.(0.3, 0.7)])
leaf.shapes(l1).insert(poly)
leaf.shapes(l1).insert(RBA::DPath.new([pt.(-0.6, -0.5), pt.(0.5, -0.5), pt.(0.5, 0.2)], 0.2, 0.1, 0.15))
leaf.shapes(l2).insert(RBA::DBox.new(-1, -1, 1, 1))
top.insert(RBA::DCellInstArray.new(leaf.cell_index, RBA::DCplxTrans.new(2, 90, true, RBA::DVector.new(1, 1))))
top.insert(RBA::DCellInstArray.new(leaf.cell_index, RBA::DCplxTrans.new(1, 270, false, RBA::DVector.new(-2, 0)), RBA::DVector.new(0, 1.6), RBA::DVector.new(1.4, 0), 2, 2))
ly.write("k.gds")
r = RBA::Region.new(top.begin_shapes_rec(l1))
r.merge
File.open("k.in", "w") do |f|
  r.decompose_convex.each do |s|
    p = s.polygon
    f.puts "polygon " + p.to_dtype(ly.dbu).each_point_hull.map { |q| "#{q.x} #{q.y}" }.join(" ")
  end
end
