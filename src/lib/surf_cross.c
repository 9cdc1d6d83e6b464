/*
 * surf_cross.c - crossings of a triangle soup with itself (see surf.h):
 * the loops a ray-string surface keeps where etch fronts meet unless it is
 * delooped (thesis 7.5.3, 8.5).  A surface with loops has no single
 * inside, so metrology refuses it.
 *
 * Two triangles cross when an edge of one passes through the inside of
 * the other; pairs sharing a vertex (equal coordinates) are neighbours of
 * the mesh and are skipped, as are touching configurations: an edge end
 * within CROSS_EPS of the other's plane, or a crossing point within
 * CROSS_EPS (relative) of its border.  Pairs are found through a uniform
 * 3D grid of the triangles' bounding boxes, cells about the size of the
 * triangles (at most two cells per triangle); a pair is tested only in the
 * first cell both boxes share, so each pair is tested once.
 */
#include "surf.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Relative tolerance of "touching": 1e-9 of the box diagonal, far below
 * any mesh spacing (nm at worst) and far above rounding (1e-16). */
#define CROSS_EPS 1e-9

static void sub(const double *a, const double *b, double *r)
{
	r[0] = a[0] - b[0], r[1] = a[1] - b[1], r[2] = a[2] - b[2];
}

static void cross(const double *a, const double *b, double *r)
{
	r[0] = a[1] * b[2] - a[2] * b[1];
	r[1] = a[2] * b[0] - a[0] * b[2];
	r[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot(const double *a, const double *b)
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* 1 if segment p-q passes through the inside of triangle t (9 numbers),
 * whose normal n and |n|^2 are given; eps is the length tolerance. */
static int seg_through(const double *p, const double *q, const double *t,
		       const double *n, double nn, double eps)
{
	double ap[3], aq[3];
	sub(p, t, ap);
	sub(q, t, aq);
	double len = sqrt(nn);
	double dp = dot(n, ap) / len, dq = dot(n, aq) / len;
	if (!((dp > eps && dq < -eps) || (dp < -eps && dq > eps)))
		return 0;
	double f = dp / (dp - dq), x[3];
	for (int k = 0; k < 3; k++)
		x[k] = p[k] + f * (q[k] - p[k]);
	for (int k = 0; k < 3; k++) {
		const double *a = t + 3 * k, *b = t + 3 * ((k + 1) % 3);
		double ab[3], ax[3], c[3];
		sub(b, a, ab);
		sub(x, a, ax);
		cross(ab, ax, c);
		/* twice the area of (a, b, x) over twice the triangle's: the
		 * barycentric weight of the opposite vertex */
		if (dot(c, n) / nn <= CROSS_EPS)
			return 0;
	}
	return 1;
}

static int share_vertex(const double *a, const double *b)
{
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			if (memcmp(a + 3 * i, b + 3 * j, 3 * sizeof *a) == 0)
				return 1;
	return 0;
}

static int tris_cross(const double *a, const double *b, double eps)
{
	double na[3], nb[3], e1[3], e2[3];
	sub(a + 3, a, e1);
	sub(a + 6, a, e2);
	cross(e1, e2, na);
	sub(b + 3, b, e1);
	sub(b + 6, b, e2);
	cross(e1, e2, nb);
	double nna = dot(na, na), nnb = dot(nb, nb);
	if (!(nna > 0) || !(nnb > 0))
		return 0;
	for (int k = 0; k < 3; k++) {
		if (seg_through(a + 3 * k, a + 3 * ((k + 1) % 3), b, nb, nnb, eps) ||
		    seg_through(b + 3 * k, b + 3 * ((k + 1) % 3), a, na, nna, eps))
			return 1;
	}
	return 0;
}

struct grid3 {
	int n[3];
	double o[3], h[3];
};

static int cell_of(const struct grid3 *g, int k, double v)
{
	double f = floor((v - g->o[k]) / g->h[k]);
	return f < 0 ? 0 : f > g->n[k] - 1 ? g->n[k] - 1 : (int)f;
}

static void tri_cells(const struct grid3 *g, const double *p, int *c0, int *c1)
{
	for (int k = 0; k < 3; k++) {
		c0[k] = cell_of(g, k, fmin(p[k], fmin(p[3 + k], p[6 + k])));
		c1[k] = cell_of(g, k, fmax(p[k], fmax(p[3 + k], p[6 + k])));
	}
}

long surf_crossings(const struct surf *s, long max)
{
	if (s->ntri < 2 || max <= 0)
		return 0;
	const double *box = s->box;
	double w[3] = {box[1] - box[0], box[3] - box[2], box[5] - box[4]};
	double diag = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
	double eps = CROSS_EPS * diag;
	/* cell side: the mean triangle extent, but no more than 2 cells per
	 * triangle over the box */
	double ext = 0;
	for (size_t t = 0; t < s->ntri; t++) {
		const double *p = s->v + 9 * t;
		for (int k = 0; k < 3; k++)
			ext += fmax(p[k], fmax(p[3 + k], p[6 + k])) -
			       fmin(p[k], fmin(p[3 + k], p[6 + k]));
	}
	ext /= 3.0 * (double)s->ntri;
	double side = fmax(ext, cbrt(w[0] * w[1] * w[2] / (2.0 * (double)s->ntri)));
	struct grid3 g;
	for (int k = 0; k < 3; k++) {
		g.n[k] = (int)fmin(1024, fmax(1, ceil(w[k] / side)));
		g.o[k] = box[2 * k];
		g.h[k] = w[k] / g.n[k];
	}
	size_t ncell = (size_t)g.n[0] * g.n[1] * g.n[2];
	size_t *start = xcalloc(ncell + 1, sizeof *start);
	unsigned short *cmin = xreallocarray(NULL, 3 * s->ntri, sizeof *cmin);
	int c0[3], c1[3];
	for (int pass = 0; pass < 2; pass++) {
		size_t *fill = NULL;
		unsigned *tri = NULL;
		if (pass == 1) {
			for (size_t c = 0; c < ncell; c++)
				start[c + 1] += start[c];
			fill = xreallocarray(NULL, ncell, sizeof *fill);
			memcpy(fill, start, ncell * sizeof *fill);
			tri = xreallocarray(NULL, start[ncell] ? start[ncell] : 1, sizeof *tri);
		}
		for (size_t t = 0; t < s->ntri; t++) {
			tri_cells(&g, s->v + 9 * t, c0, c1);
			for (int k = 0; k < 3; k++)
				cmin[3 * t + k] = (unsigned short)c0[k];
			for (int k = c0[2]; k <= c1[2]; k++)
				for (int j = c0[1]; j <= c1[1]; j++)
					for (int i = c0[0]; i <= c1[0]; i++) {
						size_t c = ((size_t)k * g.n[1] + j) * g.n[0] + i;
						if (pass == 0)
							start[c + 1]++;
						else
							tri[fill[c]++] = (unsigned)t;
					}
		}
		if (pass == 0)
			continue;
		free(fill);
		long found = 0;
		for (size_t c = 0; c < ncell && found < max; c++) {
			int ci = (int)(c % g.n[0]), cj = (int)(c / g.n[0] % g.n[1]),
			    ck = (int)(c / ((size_t)g.n[0] * g.n[1]));
			for (size_t u = start[c]; u < start[c + 1] && found < max; u++) {
				const double *a = s->v + 9 * (size_t)tri[u];
				const unsigned short *a0 = cmin + 3 * (size_t)tri[u];
				for (size_t v = u + 1; v < start[c + 1]; v++) {
					const double *b = s->v + 9 * (size_t)tri[v];
					const unsigned short *b0 = cmin + 3 * (size_t)tri[v];
					/* test the pair only in the first cell both share */
					if (ci != (a0[0] > b0[0] ? a0[0] : b0[0]) ||
					    cj != (a0[1] > b0[1] ? a0[1] : b0[1]) ||
					    ck != (a0[2] > b0[2] ? a0[2] : b0[2]))
						continue;
					int apart = 0;
					for (int k = 0; k < 3 && !apart; k++) {
						double amin = fmin(a[k], fmin(a[3 + k], a[6 + k]));
						double amax = fmax(a[k], fmax(a[3 + k], a[6 + k]));
						double bmin = fmin(b[k], fmin(b[3 + k], b[6 + k]));
						double bmax = fmax(b[k], fmax(b[3 + k], b[6 + k]));
						apart = amax < bmin || bmax < amin;
					}
					if (apart || share_vertex(a, b))
						continue;
					if (tris_cross(a, b, eps) && ++found >= max)
						break;
				}
			}
		}
		free(tri);
		free(start);
		free(cmin);
		return found;
	}
	return 0; /* not reached */
}
