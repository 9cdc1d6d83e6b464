/*
 * surf.c - the triangle soup of a developed surface and the vertical-ray
 * test (see surf.h).
 *
 * The ray test looks only at the triangles registered in the x-y grid cell
 * of the point: a uniform grid of about one cell per two triangles, every
 * triangle entered in each cell its x-y bounding box overlaps.  A steep
 * wall puts many triangles in few cells, which costs a little time, never
 * a wrong answer.  A point inside a triangle's projection is decided by
 * the crossing rule (an edge counts if one end is at or above the point's
 * y and the other below, and the point lies left of it), so a point on a
 * shared edge belongs to exactly one of the two triangles, and a triangle
 * seen edge-on (a vertical wall) holds no point.
 */
#include "surf.h"
#include "util.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct surf *surf_new(const double *box)
{
	struct surf *s = xcalloc(1, sizeof *s);
	memcpy(s->box, box, sizeof s->box);
	return s;
}

void surf_add(struct surf *s, const double *tri9)
{
	xgrow(&s->v, &s->cap, 9 * (s->ntri + 1), sizeof *s->v);
	memcpy(s->v + 9 * s->ntri, tri9, 9 * sizeof *tri9);
	s->ntri++;
}

void surf_free(struct surf *s)
{
	if (!s)
		return;
	free(s->v);
	free(s->gstart);
	free(s->gtri);
	free(s);
}

/* The cell range [c0, c1] of the interval [a, b] on a grid of n cells
 * of width h from o, clamped to the grid. */
static void cell_range(double a, double b, double o, double h, int n, int *c0, int *c1)
{
	double fa = floor((a - o) / h), fb = floor((b - o) / h);
	*c0 = fa < 0 ? 0 : fa > n - 1 ? n - 1 : (int)fa;
	*c1 = fb < 0 ? 0 : fb > n - 1 ? n - 1 : (int)fb;
}

static void tri_xy_range(const struct surf *s, size_t t, int *x0, int *x1, int *y0, int *y1)
{
	const double *p = s->v + 9 * t;
	double xa = fmin(p[0], fmin(p[3], p[6])), xb = fmax(p[0], fmax(p[3], p[6]));
	double ya = fmin(p[1], fmin(p[4], p[7])), yb = fmax(p[1], fmax(p[4], p[7]));
	cell_range(xa, xb, s->gx0, s->ghx, s->gnx, x0, x1);
	cell_range(ya, yb, s->gy0, s->ghy, s->gny, y0, y1);
}

/* Entries a grid of nx x ny cells would hold. */
static size_t grid_entries(struct surf *s, int nx, int ny)
{
	s->gnx = nx, s->gny = ny;
	s->gx0 = s->box[0], s->gy0 = s->box[2];
	s->ghx = (s->box[1] - s->box[0]) / nx;
	s->ghy = (s->box[3] - s->box[2]) / ny;
	size_t n = 0;
	for (size_t t = 0; t < s->ntri; t++) {
		int x0, x1, y0, y1;
		tri_xy_range(s, t, &x0, &x1, &y0, &y1);
		n += (size_t)(x1 - x0 + 1) * (size_t)(y1 - y0 + 1);
	}
	return n;
}

/* About one cell per two triangles, cells as square as the box allows;
 * coarsened while large triangles would make the grid hold more than
 * GRID_FILL entries per triangle on average. */
enum { GRID_FILL = 8, GRID_MAX_SIDE = 4096 };

void surf_index(struct surf *s)
{
	free(s->gstart);
	free(s->gtri);
	double wx = s->box[1] - s->box[0], wy = s->box[3] - s->box[2];
	double cells = s->ntri / 2.0 + 1;
	double side = sqrt(wx * wy / cells);
	int nx = (int)fmin(GRID_MAX_SIDE, fmax(1, ceil(wx / side)));
	int ny = (int)fmin(GRID_MAX_SIDE, fmax(1, ceil(wy / side)));
	size_t limit = GRID_FILL * s->ntri + 1024;
	size_t n;
	while ((n = grid_entries(s, nx, ny)) > limit && (nx > 1 || ny > 1)) {
		nx = (nx + 1) / 2;
		ny = (ny + 1) / 2;
	}
	size_t ncell = (size_t)nx * (size_t)ny;
	s->gstart = xcalloc(ncell + 1, sizeof *s->gstart);
	s->gtri = xreallocarray(NULL, n ? n : 1, sizeof *s->gtri);
	for (size_t t = 0; t < s->ntri; t++) {
		int x0, x1, y0, y1;
		tri_xy_range(s, t, &x0, &x1, &y0, &y1);
		for (int j = y0; j <= y1; j++)
			for (int i = x0; i <= x1; i++)
				s->gstart[(size_t)j * nx + i + 1]++;
	}
	for (size_t c = 0; c < ncell; c++)
		s->gstart[c + 1] += s->gstart[c];
	size_t *fill = xreallocarray(NULL, ncell, sizeof *fill);
	memcpy(fill, s->gstart, ncell * sizeof *fill);
	for (size_t t = 0; t < s->ntri; t++) {
		int x0, x1, y0, y1;
		tri_xy_range(s, t, &x0, &x1, &y0, &y1);
		for (int j = y0; j <= y1; j++)
			for (int i = x0; i <= x1; i++)
				s->gtri[fill[(size_t)j * nx + i]++] = (unsigned)t;
	}
	free(fill);
}

/* 1 if the edge a-b, taken lower end first, crosses the horizontal line
 * through (x, y) to the right of the point. */
static int edge_right(const double *a, const double *b, double x, double y)
{
	if (a[1] > b[1]) {
		const double *t = a;
		a = b;
		b = t;
	}
	if (!(a[1] <= y && y < b[1]))
		return 0;
	double xi = a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
	return x < xi;
}

/* z of triangle p's plane above (x, y); -inf for a triangle seen
 * edge-on (rounding can put a point inside its zero-area projection). */
static double plane_z(const double *p, double x, double y)
{
	double ax = p[3] - p[0], ay = p[4] - p[1], bx = p[6] - p[0], by = p[7] - p[1];
	double d = ax * by - bx * ay;
	if (d == 0)
		return -INFINITY;
	double u = ((x - p[0]) * by - bx * (y - p[1])) / d;
	double v = (ax * (y - p[1]) - (x - p[0]) * ay) / d;
	return p[2] + u * (p[5] - p[2]) + v * (p[8] - p[2]);
}

int surf_above(const struct surf *s, double x, double y, double z)
{
	int i, j;
	cell_range(x, x, s->gx0, s->ghx, s->gnx, &i, &i);
	cell_range(y, y, s->gy0, s->ghy, s->gny, &j, &j);
	size_t c = (size_t)j * s->gnx + i;
	int n = 0;
	for (size_t k = s->gstart[c]; k < s->gstart[c + 1]; k++) {
		const double *p = s->v + 9 * (size_t)s->gtri[k];
		if ((x < p[0] && x < p[3] && x < p[6]) ||
		    (y < p[1] && y < p[4] && y < p[7]) ||
		    (y > p[1] && y > p[4] && y > p[7]))
			continue;
		int in = edge_right(p, p + 3, x, y) ^ edge_right(p + 3, p + 6, x, y) ^
			 edge_right(p + 6, p, x, y);
		if (in && plane_z(p, x, y) >= z)
			n++;
	}
	return n;
}

/* Closest point of triangle abc to p (Ericson, Real-Time Collision
 * Detection, 5.1.5); returns the squared distance. */
double surf_point_tri_dist2(const double p[3], const double *a, const double *b, const double *c)
{
	double ab[3], ac[3], ap[3], x[3];
	for (int d = 0; d < 3; d++) {
		ab[d] = b[d] - a[d];
		ac[d] = c[d] - a[d];
		ap[d] = p[d] - a[d];
	}
#define DOT(u, v) ((u)[0] * (v)[0] + (u)[1] * (v)[1] + (u)[2] * (v)[2])
	double d1 = DOT(ab, ap), d2 = DOT(ac, ap);
	double bp[3] = {p[0] - b[0], p[1] - b[1], p[2] - b[2]};
	double cp[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
	double d3 = DOT(ab, bp), d4 = DOT(ac, bp), d5 = DOT(ab, cp), d6 = DOT(ac, cp);
#undef DOT
	double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
	if (d1 <= 0 && d2 <= 0) {
		memcpy(x, a, sizeof x);
	} else if (d3 >= 0 && d4 <= d3) {
		memcpy(x, b, sizeof x);
	} else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
		double v = d1 / (d1 - d3);
		for (int d = 0; d < 3; d++)
			x[d] = a[d] + v * ab[d];
	} else if (d6 >= 0 && d5 <= d6) {
		memcpy(x, c, sizeof x);
	} else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
		double w = d2 / (d2 - d6);
		for (int d = 0; d < 3; d++)
			x[d] = a[d] + w * ac[d];
	} else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
		double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
		for (int d = 0; d < 3; d++)
			x[d] = b[d] + w * (c[d] - b[d]);
	} else {
		double den = 1 / (va + vb + vc), v = vb * den, w = vc * den;
		for (int d = 0; d < 3; d++)
			x[d] = a[d] + v * ab[d] + w * ac[d];
	}
	double e = 0;
	for (int d = 0; d < 3; d++)
		e += (p[d] - x[d]) * (p[d] - x[d]);
	return e;
}
