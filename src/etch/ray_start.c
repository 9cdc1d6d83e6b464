/*
 * ray_start.c - the initial surface of a simulation.
 *
 * The flat resist top (thesis 8.3): the plane z = zmax over the whole x-y
 * extent of the rate box, triangulated with rows of nodes S_ideal apart
 * and rows S_ideal sqrt(3)/2 apart, every other row offset by half a
 * spacing, so the triangles are equilateral with sides S_ideal (the ideal
 * length) except the half-width ones at the x walls.  Every ray points
 * down.  Row nodes on a wall carry that wall's flag (boundary
 * flattening, thesis 7.5.2.2, and no merging, 8.4.1.2).
 *
 * A seed point (thesis Figure 8.3): an icosahedron shrunk to the point,
 * twelve nodes at the same place with rays along the icosahedron's
 * vertex directions; the first advance spreads them into a small sphere.
 */
#include "etch.h"

#include "checked.h"
#include "util.h"
#include "vec3.h"

#include <math.h>
#include <stdlib.h>

static const double down[3] = {0, 0, -1};

/* tolerance for equal x positions of nodes in adjacent rows: both are
 * computed from the same expressions, so this is rounding only */
#define ROW_X_TOL 1e-12

void start_flat(struct mesh *m, const struct rfield *f, double seg)
{
	double xw = f->hi[0] - f->lo[0], yw = f->hi[1] - f->lo[1];
	/* the guard before any cast: bounds of 1e308 overflow an int */
	double dnx = fmax(ceil(xw / seg - 1e-9), 1), dny = fmax(ceil(yw / (seg * sqrt(3) / 2) - 1e-9), 1);
	if (!(dnx * dny <= 5e7))
		die("-seg %g gives too many nodes for the box (%.3g)", seg, dnx * dny);
	int nx = ck_int(dnx, 1, 50000000, "mesh columns"), ny = ck_int(dny, 1, 50000000, "mesh rows");
	double hx = xw / nx, hy = yw / ny;
	int *prev = NULL, *cur = NULL;
	double *prevx = NULL, *curx = NULL;
	int nprev = 0;
	for (int j = 0; j <= ny; j++) {
		int odd = j & 1 && nx > 0;
		int n = odd ? nx + 2 : nx + 1;
		cur = xreallocarray(NULL, (size_t)n, sizeof *cur);
		curx = xreallocarray(NULL, (size_t)n, sizeof *curx);
		double y = j == ny ? f->hi[1] : f->lo[1] + j * hy;
		for (int i = 0; i < n; i++) {
			double x;
			if (!odd)
				x = i == nx ? f->hi[0] : f->lo[0] + i * hx;
			else
				x = i == 0 ? f->lo[0] : i == n - 1 ? f->hi[0] : f->lo[0] + (i - 0.5) * hx;
			unsigned fl = 0;
			if (i == 0) fl |= ON_X0;
			if (i == n - 1) fl |= ON_X1;
			if (j == 0) fl |= ON_Y0;
			if (j == ny) fl |= ON_Y1;
			double p[3] = {x, y, f->hi[2]};
			cur[i] = mesh_add_node(m, p, down, fl);
			curx[i] = x;
		}
		if (j > 0) {
			/* zip the strip between the rows, each triangle closing
			 * with the shorter of the two possible diagonals (no
			 * segment longer than S_ideal); triangles clockwise
			 * seen from above, so their normals point down */
			int i = 0, k = 0;
			while (i < nprev - 1 || k < n - 1) {
				int along_prev;
				if (i == nprev - 1)
					along_prev = 0;
				else if (k == n - 1)
					along_prev = 1;
				else    /* the shorter new diagonal (rows are
					 * equally far apart, so compare x) */
					along_prev = fabs(prevx[i + 1] - curx[k]) <=
						fabs(curx[k + 1] - prevx[i]) + ROW_X_TOL;
				if (along_prev) {
					mesh_add_triangle(m, prev[i], cur[k], prev[i + 1]);
					i++;
				} else {
					mesh_add_triangle(m, prev[i], cur[k], cur[k + 1]);
					k++;
				}
			}
		}
		free(prev);
		free(prevx);
		prev = cur;
		prevx = curx;
		nprev = n;
	}
	free(prev);
	free(prevx);
}

void start_seed(struct mesh *m, const double p[3])
{
	/* icosahedron vertices (0, +-1, +-phi) and cyclic permutations */
	const double ph = (1 + sqrt(5)) / 2;
	double v[12][3];
	int k = 0;
	for (int a = -1; a <= 1; a += 2)
		for (int b = -1; b <= 1; b += 2) {
			double q[3][3] = {{0, a, b * ph}, {a, b * ph, 0}, {b * ph, 0, a}};
			for (int c = 0; c < 3; c++) {
				double r = sqrt(1 + ph * ph);
				for (int d = 0; d < 3; d++)
					v[k + 4 * c][d] = q[c][d] / r;
			}
			k++;
		}
	int id[12];
	for (int i = 0; i < 12; i++)
		id[i] = mesh_add_node(m, p, v[i], 0);
	/* faces: triples of mutually nearest vertices, oriented with the
	 * normal outwards, along the rays */
	double e2 = 1e300;
	for (int i = 1; i < 12; i++) {
		double d2 = 0;
		for (int d = 0; d < 3; d++)
			d2 += (v[0][d] - v[i][d]) * (v[0][d] - v[i][d]);
		if (d2 < e2)
			e2 = d2;
	}
	for (int a = 0; a < 12; a++)
		for (int b = a + 1; b < 12; b++)
			for (int c = b + 1; c < 12; c++) {
				int ok = 1;
				int pr[3][2] = {{a, b}, {b, c}, {a, c}};
				for (int q = 0; q < 3 && ok; q++) {
					double d2 = 0;
					for (int d = 0; d < 3; d++)
						d2 += (v[pr[q][0]][d] - v[pr[q][1]][d]) * (v[pr[q][0]][d] - v[pr[q][1]][d]);
					ok = d2 < e2 * 1.01;
				}
				if (!ok)
					continue;
				double u[3], w[3], n[3], cen = 0;
				vec3_sub(v[b], v[a], u);
				vec3_sub(v[c], v[a], w);
				vec3_cross(u, w, n);
				for (int d = 0; d < 3; d++)
					cen += n[d] * (v[a][d] + v[b][d] + v[c][d]);
				if (cen > 0)
					mesh_add_triangle(m, id[a], id[b], id[c]);
				else
					mesh_add_triangle(m, id[a], id[c], id[b]);
			}
}
