/*
 * tri_weld.c - welding of a triangle soup (tri_weld.h) through a hash of
 * bins 1024 weld distances wide: a point is looked up in its bin and in
 * the neighbours it lies within the weld distance of, so two such points
 * always meet; of several within reach, the lowest-numbered vertex wins.
 * The table is linearly probed and at most half full; it doubles as the
 * vertices come (each rehashed into its bin's chain, so a lookup meets
 * the same vertices whatever the table's size: the numbering does not
 * depend on it).
 */
#include "tri_weld.h"
#include "util.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static uint64_t bin_hash(int64_t a, int64_t b, int64_t c)
{
	uint64_t h = (uint64_t)a * 0x9E3779B97F4A7C15u ^ (uint64_t)b * 0xC2B2AE3D27D4EB4Fu ^
		     (uint64_t)c * 0x165667B19E3779F9u;
	return h ^ (h >> 29);
}

static void bin_of(const double *x, double cell, int64_t b[3])
{
	for (int d = 0; d < 3; d++)
		b[d] = (int64_t)floor(x[d] / cell);
}

/* bins much larger than eps (still far smaller than the triangles): the
 * neighbouring bins are searched only along the axes where the point
 * lies within eps of its bin's side */
static double cell_of(double eps)
{
	return eps > 0 ? 1024 * eps : 1e-300;
}

static void tab_insert(struct tri_weld *w, int vert)
{
	int64_t b[3];
	bin_of(w->p + 3 * (size_t)vert, cell_of(w->eps), b);
	size_t s = bin_hash(b[0], b[1], b[2]) & (w->cap - 1);
	while (w->tab[s] >= 0)
		s = (s + 1) & (w->cap - 1);
	w->tab[s] = vert;
}

/* a table of at least want slots (a power of two), the vertices rehashed */
static void tab_resize(struct tri_weld *w, size_t want)
{
	size_t cap = 16;
	while (cap < want)
		cap *= 2;
	free(w->tab);
	w->tab = xreallocarray(NULL, cap, sizeof *w->tab);
	w->cap = cap;
	for (size_t i = 0; i < cap; i++)
		w->tab[i] = -1;
	for (size_t i = 0; i < w->nv; i++)
		tab_insert(w, (int)i);
}

/* the vertex of corner x: the lowest-numbered within eps, else a new one */
static int weld_point(struct tri_weld *w, const double *x)
{
	double eps = w->eps, cell = cell_of(eps);
	int64_t b[3];
	bin_of(x, cell, b);
	int lo[3], hi[3];
	for (int d = 0; d < 3; d++) {
		lo[d] = floor((x[d] - eps) / cell) < (double)b[d] ? -1 : 0;
		hi[d] = floor((x[d] + eps) / cell) > (double)b[d] ? 1 : 0;
	}
	int found = -1;
	size_t mask = w->cap - 1;
	for (int dz = lo[2]; dz <= hi[2]; dz++)
		for (int dy = lo[1]; dy <= hi[1]; dy++)
			for (int dx = lo[0]; dx <= hi[0]; dx++) {
				int64_t k[3] = {b[0] + dx, b[1] + dy, b[2] + dz};
				size_t s = bin_hash(k[0], k[1], k[2]) & mask;
				for (; w->tab[s] >= 0; s = (s + 1) & mask) {
					int v = w->tab[s];
					const double *y = w->p + 3 * (size_t)v;
					int64_t bw[3];
					bin_of(y, cell, bw);
					if (bw[0] != k[0] || bw[1] != k[1] || bw[2] != k[2])
						continue;
					if (fabs(y[0] - x[0]) <= eps && fabs(y[1] - x[1]) <= eps &&
					    fabs(y[2] - x[2]) <= eps && (found < 0 || v < found))
						found = v;
				}
			}
	if (found >= 0)
		return found;
	if (w->nv >= (size_t)INT32_MAX)
		die("tri_weld: more than %ld vertices", (long)INT32_MAX);
	found = (int)w->nv;
	xgrow(&w->p, &w->pcap, 3 * (w->nv + 1), sizeof *w->p);
	memcpy(w->p + 3 * w->nv, x, 3 * sizeof *x);
	w->nv++;
	if (2 * w->nv > w->cap)
		tab_resize(w, 4 * w->nv);
	else
		tab_insert(w, found);
	return found;
}

void tri_weld_add(struct tri_weld *w, const double tri[9])
{
	if (!w->tab)
		tab_resize(w, 16);
	xgrow(&w->tv, &w->tvcap, 3 * (w->nt + 1) + 1, sizeof *w->tv);
	for (int q = 0; q < 3; q++)
		w->tv[3 * w->nt + (size_t)q] = weld_point(w, tri + 3 * q);
	w->nt++;
}

size_t tri_weld_take(struct tri_weld *w, double **p, int **tv, size_t *nt)
{
	size_t nv = w->nv;
	if (!w->tv)     /* no triangle: an empty list still to free */
		w->tv = xreallocarray(NULL, 1, sizeof *w->tv);
	*p = w->p;
	*tv = w->tv;
	*nt = w->nt;
	w->p = NULL;
	w->tv = NULL;
	w->nv = w->nt = w->pcap = w->tvcap = 0;
	for (size_t i = 0; i < w->cap; i++)
		w->tab[i] = -1;
	return nv;
}

void tri_weld_free(struct tri_weld *w)
{
	free(w->p);
	free(w->tv);
	free(w->tab);
	memset(w, 0, sizeof *w);
}

size_t tri_weld(const double *v, size_t n, double eps, double **pp, int **tvp)
{
	/* the table sized once for the worst case, 3n vertices (a closed
	 * surface has about n/2) */
	struct tri_weld w = {0};
	w.eps = eps;
	tab_resize(&w, 6 * n + 16);
	w.tv = xreallocarray(NULL, 3 * n + 1, sizeof *w.tv);
	w.tvcap = 3 * n + 1;
	for (size_t t = 0; t < n; t++)
		tri_weld_add(&w, v + 9 * t);
	free(w.tab);
	*pp = w.p;
	*tvp = w.tv;
	return w.nv;
}
