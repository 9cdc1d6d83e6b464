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
 * triangles, kept as a sorted list of (cell, triangle) entries; a pair is
 * tested only in the first cell both boxes share, so each pair is tested
 * once.
 */
#include "surf.h"
#include "util.h"
#include "vec3.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Relative tolerance of "touching": 1e-9 of the box diagonal, far below
 * any mesh spacing (nm at worst) and far above rounding (1e-16). */
#define CROSS_EPS 1e-9

/* 1 if segment p-q passes through the inside of triangle t (9 numbers),
 * whose normal n and |n|^2 are given; eps is the length tolerance. */
static int seg_through(const double *p, const double *q, const double *t,
		       const double *n, double nn, double eps)
{
	double ap[3], aq[3];
	vec3_sub(p, t, ap);
	vec3_sub(q, t, aq);
	double len = sqrt(nn);
	double dp = vec3_dot(n, ap) / len, dq = vec3_dot(n, aq) / len;
	if (!((dp > eps && dq < -eps) || (dp < -eps && dq > eps)))
		return 0;
	double f = dp / (dp - dq), x[3];
	for (int k = 0; k < 3; k++)
		x[k] = p[k] + f * (q[k] - p[k]);
	for (int k = 0; k < 3; k++) {
		const double *a = t + 3 * k, *b = t + 3 * ((k + 1) % 3);
		double ab[3], ax[3], c[3];
		vec3_sub(b, a, ab);
		vec3_sub(x, a, ax);
		vec3_cross(ab, ax, c);
		/* twice the area of (a, b, x) over twice the triangle's: the
		 * barycentric weight of the opposite vertex */
		if (vec3_dot(c, n) / nn <= CROSS_EPS)
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
	vec3_sub(a + 3, a, e1);
	vec3_sub(a + 6, a, e2);
	vec3_cross(e1, e2, na);
	vec3_sub(b + 3, b, e1);
	vec3_sub(b + 6, b, e2);
	vec3_cross(e1, e2, nb);
	double nna = vec3_dot(na, na), nnb = vec3_dot(nb, nb);
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

/* One entry of the grid: a triangle in a cell. */
struct entry {
	uint64_t cell;
	unsigned tri;
};

/* LSD radix sort of entries by cell, 16 bits a pass: stable, so the
 * triangles of a cell stay in file order and the count is the same
 * whatever the sort. */
static void sort_entries(struct entry *e, size_t n, uint64_t maxcell)
{
	struct entry *tmp = xreallocarray(NULL, n ? n : 1, sizeof *tmp);
	size_t *count = xreallocarray(NULL, 65537, sizeof *count);
	for (int shift = 0; shift < 64 && (maxcell >> shift) > 0; shift += 16) {
		memset(count, 0, 65537 * sizeof *count);
		for (size_t i = 0; i < n; i++)
			count[((e[i].cell >> shift) & 0xffff) + 1]++;
		for (int d = 0; d < 65536; d++)
			count[d + 1] += count[d];
		for (size_t i = 0; i < n; i++)
			tmp[count[(e[i].cell >> shift) & 0xffff]++] = e[i];
		memcpy(e, tmp, n * sizeof *e);
	}
	free(count);
	free(tmp);
}

/* Cells of side about the mean triangle extent hold a few triangles each
 * wherever the surface passes; the grid is sparse (a sorted list of
 * entries), so its size follows the surface, not the box.  Large
 * triangles among small ones would enter many cells: the side doubles
 * while the entries would pass ENTRY_FILL per triangle. */
enum { ENTRY_FILL = 8, GRID_MAX_SIDE = 65535 };

long surf_crossings(const struct surf *s, long max)
{
	if (s->ntri < 2 || max <= 0)
		return 0;
	const double *box = s->box;
	double w[3] = {box[1] - box[0], box[3] - box[2], box[5] - box[4]};
	double diag = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
	double eps = CROSS_EPS * diag;
	/* bounding boxes, and the mean extent */
	double *bb = xreallocarray(NULL, 6 * s->ntri, sizeof *bb), ext = 0;
	for (size_t t = 0; t < s->ntri; t++) {
		const double *p = s->v + 9 * t;
		for (int k = 0; k < 3; k++) {
			bb[6 * t + 2 * k] = fmin(p[k], fmin(p[3 + k], p[6 + k]));
			bb[6 * t + 2 * k + 1] = fmax(p[k], fmax(p[3 + k], p[6 + k]));
			ext += bb[6 * t + 2 * k + 1] - bb[6 * t + 2 * k];
		}
	}
	ext /= 3.0 * (double)s->ntri;
	double side = fmax(ext, diag / GRID_MAX_SIDE);
	if (!(side > 0))
		side = diag;
	struct grid3 g;
	int *cr = xreallocarray(NULL, 6 * s->ntri, sizeof *cr); /* cell ranges */
	size_t nent;
	for (;;) {
		for (int k = 0; k < 3; k++) {
			g.n[k] = (int)fmin(GRID_MAX_SIDE, fmax(1, ceil(w[k] / side)));
			g.o[k] = box[2 * k];
			g.h[k] = w[k] / g.n[k];
		}
		nent = 0;
		for (size_t t = 0; t < s->ntri; t++) {
			size_t m = 1;
			for (int k = 0; k < 3; k++) {
				int *c = cr + 6 * t + 2 * k;
				c[0] = cell_of(&g, k, bb[6 * t + 2 * k]);
				c[1] = cell_of(&g, k, bb[6 * t + 2 * k + 1]);
				m *= (size_t)(c[1] - c[0] + 1);
			}
			nent += m;
		}
		if (nent <= ENTRY_FILL * s->ntri + 1024 ||
		    (g.n[0] == 1 && g.n[1] == 1 && g.n[2] == 1))
			break;
		side *= 2;
	}
	struct entry *e = xreallocarray(NULL, nent, sizeof *e);
	size_t ne = 0;
	for (size_t t = 0; t < s->ntri; t++) {
		const int *c = cr + 6 * t;
		for (int k = c[4]; k <= c[5]; k++)
			for (int j = c[2]; j <= c[3]; j++)
				for (int i = c[0]; i <= c[1]; i++)
					e[ne++] = (struct entry){
						((uint64_t)k * (uint64_t)g.n[1] + (uint64_t)j) *
							(uint64_t)g.n[0] + (uint64_t)i,
						(unsigned)t};
	}
	sort_entries(e, ne, (uint64_t)g.n[0] * g.n[1] * g.n[2]);

	long found = 0;
	for (size_t u0 = 0; u0 < ne && found < max;) {
		size_t u1 = u0 + 1;
		while (u1 < ne && e[u1].cell == e[u0].cell)
			u1++;
		uint64_t c = e[u0].cell;
		int ci = (int)(c % (uint64_t)g.n[0]), cj = (int)(c / (uint64_t)g.n[0] % (uint64_t)g.n[1]),
		    ck = (int)(c / ((uint64_t)g.n[0] * (uint64_t)g.n[1]));
		for (size_t u = u0; u < u1 && found < max; u++) {
			size_t ta = e[u].tri;
			const double *ba = bb + 6 * ta;
			const int *ca = cr + 6 * ta;
			for (size_t v = u + 1; v < u1; v++) {
				size_t tb = e[v].tri;
				const double *bbb = bb + 6 * tb;
				if (ba[1] < bbb[0] || bbb[1] < ba[0] || ba[3] < bbb[2] ||
				    bbb[3] < ba[2] || ba[5] < bbb[4] || bbb[5] < ba[4])
					continue;
				/* test the pair only in the first cell both share */
				const int *cb = cr + 6 * tb;
				if (ci != (ca[0] > cb[0] ? ca[0] : cb[0]) ||
				    cj != (ca[2] > cb[2] ? ca[2] : cb[2]) ||
				    ck != (ca[4] > cb[4] ? ca[4] : cb[4]))
					continue;
				const double *a = s->v + 9 * ta, *b = s->v + 9 * tb;
				if (share_vertex(a, b))
					continue;
				if (tris_cross(a, b, eps) && ++found >= max)
					break;
			}
		}
		u0 = u1;
	}
	free(e);
	free(cr);
	free(bb);
	return found;
}
