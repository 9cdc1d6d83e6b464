# contrast.awk - of an image stack (stack(5)), the plane nearest depth D
# (um below the resist top): its contrast (max - min) / (max + min), and,
# from the header and the window, the angle to the normal (degrees) inside
# the resist of the two beams of a symmetric two-beam image of one period
# across the window (sin theta = wavelength / (2 period index)) and
# |cos 2 theta|, the share of TM waves that interferes there.
# One line: "contrast theta cos2theta".
#   awk -v D=0.05 -f contrast.awk image.stack
BEGIN { RS = "[ \t\n,]+"; st = 0 }
$0 == "" { next }
st == 0 && ($0 == "index" || $0 == "wavelength") { key = $0; st = -1; next }
st == -1 { h[key] = $0 + 0; st = 0; next }
st == 0 && $0 == "depth" { st = 1; next }
st == 1 { z = $0 + 0; st = 2; k = 0; next }
st == 2 { b[++k] = $0 + 0; if (k == 4) st = 3; next }   # xmin xmax ymin ymax
st == 3 { nx = $0 + 0; st = 4; next }
st == 4 { ny = $0 + 0; st = 5; n = 0; next }
st == 5 {
	v = $0 + 0
	if (n == 0 || v > hi) hi = v
	if (n == 0 || v < lo) lo = v
	if (++n == nx * ny) {
		st = 0; d = z - D; if (d < 0) d = -d
		if (best == "" || d < best) { best = d; c = (hi - lo) / (hi + lo) }
	}
}
END {
	if (best == "" || !h["index"] || !h["wavelength"]) exit 1
	s = h["wavelength"] / (2 * (b[2] - b[1]) * h["index"])
	t = atan2(s, sqrt(1 - s * s))
	c2 = cos(2 * t); if (c2 < 0) c2 = -c2
	printf "%.4f %.2f %.4f\n", c, t * 45 / atan2(1, 1), c2
}
