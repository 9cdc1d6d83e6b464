# tests/measure/synth.awk - writes a synthetic developed surface (plot3d,
# one set of triangles) whose sections the measure tests know exactly.
# Not a test itself (the runner takes only *.sh).
#
#   awk -v kind=rev -v prof="r1 z1 r2 z2 ..." -f synth.awk    a hole
#   awk -v kind=ext -v prof="x1 z1 x2 z2 ..." -f synth.awk    a line or space
#
# rev: the profile (r, z) from the axis outwards, revolved about the z
#   axis in N sectors (default 256, a multiple of 8 so that the box's
#   corners lie on sector edges); the last point is moved out along each
#   sector edge to the box's side, so the surface covers the box.
# ext: the profile (x, z) from the box's xmin to xmax, extruded along y in
#   M steps (default 7).
# -v step=h cuts each segment of the profile into equal pieces no longer
# than h um (but a rev profile's last, out to the box), so that the
# triangles of the walls are small.
# Box: -v box="xmin xmax ymin ymax zmin zmax" (default the contact's cell,
# -2.5 2.5 -2.5 2.5 -0.7 0).  -v gap="a0 a1 i0 i1" leaves out the
# triangles of sectors (rev) or steps (ext) a0 to a1, counted from 0, on
# the profile's segments i0 to i1, counted from 1: a window in a wall, whose
# rim is open border (as delooping can leave).  The triangles are written in random order
# (-v seed=N), each with its vertices rotated and its orientation flipped
# at random: measure must not depend on either.
function tri(ax, ay, az, bx, by, bz, cx, cy, cz) {
	nt++
	T[nt] = sprintf("%.17g %.17g %.17g|%.17g %.17g %.17g|%.17g %.17g %.17g", ax, ay, az, bx, by, bz, cx, cy, cz)
}
function quad(p, q, r, s) { # four points "x y z", p-q-r-s around
	split(p, P, " "); split(q, Q, " "); split(r, R, " "); split(s, S, " ")
	tri(P[1], P[2], P[3], Q[1], Q[2], Q[3], R[1], R[2], R[3])
	tri(P[1], P[2], P[3], R[1], R[2], R[3], S[1], S[2], S[3])
}
function pt(x, y, z) { return sprintf("%.17g %.17g %.17g", snap(x, 1), snap(y, 3), z) }
# a point within 1e-9 of the box's side is put on it
function snap(v, k) {
	if (v - B[k] < 1e-9 && v - B[k] > -1e-9) return B[k]
	if (v - B[k + 1] < 1e-9 && v - B[k + 1] > -1e-9) return B[k + 1]
	return v
}
BEGIN {
	if (box == "") box = "-2.5 2.5 -2.5 2.5 -0.7 0"
	split(box, B, " ")
	if (N == "") N = 256
	if (M == "") M = 7
	if (seed == "") seed = 1
	np = split(prof, F, " ") / 2
	if (gap == "") gap = "-1 -1 -1 -1"
	split(gap, G, " ")
	pi = atan2(0, -1)
	# the pieces: piece q from (PX[q], PZ[q]) to (PX[q + 1], PZ[q + 1]),
	# of the given segment PS[q] (rev: the last, out to the box, is whole)
	nq = 0; PX[1] = F[1]; PZ[1] = F[2]
	for (i = 1; i < np; i++) {
		dx = F[2 * i + 1] - F[2 * i - 1]; dz = F[2 * i + 2] - F[2 * i]
		n = step > 0 && !(kind == "rev" && i == np - 1) ? int(sqrt(dx * dx + dz * dz) / step) + 1 : 1
		for (m = 1; m <= n; m++) {
			nq++; PS[nq] = i
			PX[nq + 1] = m == n ? F[2 * i + 1] : F[2 * i - 1] + dx * m / n
			PZ[nq + 1] = m == n ? F[2 * i + 2] : F[2 * i] + dz * m / n
		}
	}
	if (kind == "rev") {
		for (k = 0; k < N; k++) {
			t0 = 2 * pi * k / N; t1 = 2 * pi * ((k + 1) % N) / N  # shared edges: equal bits
			for (q = 1; q <= nq; q++) {
				if (hole(k, PS[q])) continue
				r0 = PX[q]; z0 = PZ[q]; r1 = PX[q + 1]; z1 = PZ[q + 1]
				# the outermost ring: on the box's side along the sector edge
				if (q == nq) { e0 = edge(t0); e1 = edge(t1) } else { e0 = r1; e1 = r1 }
				if (r0 == 0)
					tri(0, 0, z0, snap(e0 * cos(t0), 1), snap(e0 * sin(t0), 3), z1,
					    snap(e1 * cos(t1), 1), snap(e1 * sin(t1), 3), z1)
				else
					quad(pt(r0 * cos(t0), r0 * sin(t0), z0), pt(e0 * cos(t0), e0 * sin(t0), z1),
					     pt(e1 * cos(t1), e1 * sin(t1), z1), pt(r0 * cos(t1), r0 * sin(t1), z0))
			}
		}
	} else {
		for (j = 0; j < M; j++) {
			y0 = B[3] + (B[4] - B[3]) * j / M; y1 = B[3] + (B[4] - B[3]) * (j + 1) / M
			for (q = 1; q <= nq; q++)
				if (!hole(j, PS[q])) quad(pt(PX[q], y0, PZ[q]), pt(PX[q + 1], y0, PZ[q + 1]),
				     pt(PX[q + 1], y1, PZ[q + 1]), pt(PX[q], y1, PZ[q]))
		}
	}
	srand(seed)
	for (i = nt; i > 1; i--) { j = 1 + int(rand() * i); t = T[i]; T[i] = T[j]; T[j] = t }
	print box
	print nt
	for (i = 1; i <= nt; i++) {
		split(T[i], V, "|")
		s = int(rand() * 3); d = rand() < 0.5 ? 1 : 2
		print 4
		for (k = 0; k < 4; k++) print V[1 + (s + d * k) % 3]
	}
}
# distance from the centre (0, 0) to the box's side along angle t
function edge(t,   c, s, ex, ey) {
	c = cos(t); s = sin(t)
	ex = (c > 1e-12) ? B[2] / c : (c < -1e-12) ? B[1] / c : 1e300
	ey = (s > 1e-12) ? B[4] / s : (s < -1e-12) ? B[3] / s : 1e300
	return ex < ey ? ex : ey
}
# whether the triangles of sector or step a on segment i are left out
function hole(a, i) { return a >= G[1] && a <= G[2] && i >= G[3] && i <= G[4] }
