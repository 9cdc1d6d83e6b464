/*
 * fmm_cut.c - the profile of a fast-marching solution along a cutline:
 * where the plane x = v (or y = v) cuts the developed surface at time t,
 * as polylines of (y, z) (or (x, z)), laid out as etch's curves.cut
 * (ray_output.c): open chains first, then closed loops, one set per call.
 * This is what 2D simulations along cutlines are compared with (thesis
 * Figures 9.14, 9.16), and what the deloop tests compare ray-string
 * profiles against (Figure 8.12's profile).
 *
 * T is sampled on the plane at the grid's own nodes of the other two
 * axes (trilinear, so linear between the two slabs around v) and
 * contoured by marching triangles, every cell split on its
 * (0,0)-(1,1) diagonal.  A crossing is named by the grid edge it lies on
 * and computed from that edge's two ends in a fixed order (placed by
 * their rates as fmm_surface places its vertices, iso_crossing), so the
 * triangles on either side of an edge produce the same point bit for
 * bit and the pieces chain by name, not by comparing coordinates.  As in
 * fmm_surface, the substrate where T < t belongs to the profile: a
 * virtual row of values above t sits on z = zmin itself, so the contour
 * runs along the substrate there and joins the T = t curve where it
 * meets it.  Side walls and the top are not part of the profile.
 */
#include "fmm.h"
#include "iso.h"
#include "util.h"

#include <stdlib.h>

struct plane {
	int nj, nk;             /* nodes along the other axis and along z, the
				 * virtual substrate row included (row 0) */
	double *v;              /* nj * nk values */
	double *w;              /* their rates (0 on the virtual row) */
	double *u, *z;          /* coordinates of columns and rows */
	double level;
};

static double val(const struct plane *pl, int j, int k)
{
	return pl->v[(size_t)k * (size_t)pl->nj + (size_t)j];
}

/* The two ends of edge e: 3 per node (j, k): 0 along u, 1 along z, 2 the
 * diagonal to (j+1, k+1). */
static void edge_ends(const struct plane *pl, size_t e, int a[2], int b[2])
{
	size_t node = e / 3;
	a[0] = (int)(node % (size_t)pl->nj);
	a[1] = (int)(node / (size_t)pl->nj);
	b[0] = a[0] + (e % 3 != 1);
	b[1] = a[1] + (e % 3 != 0);
}

static void edge_point(const struct plane *pl, size_t e, double p[2])
{
	int a[2], b[2];
	edge_ends(pl, e, a, b);
	size_t ia = (size_t)a[1] * (size_t)pl->nj + (size_t)a[0];
	size_t ib = (size_t)b[1] * (size_t)pl->nj + (size_t)b[0];
	double s = iso_crossing(pl->v[ia], pl->w[ia], pl->v[ib], pl->w[ib], pl->level);
	p[0] = pl->u[a[0]] + s * (pl->u[b[0]] - pl->u[a[0]]);
	p[1] = pl->z[a[1]] + s * (pl->z[b[1]] - pl->z[a[1]]);
}

static size_t edge_id(const struct plane *pl, int j, int k, int kind)
{
	return 3 * ((size_t)k * (size_t)pl->nj + (size_t)j) + (size_t)kind;
}

struct links {
	size_t *to;             /* two neighbours per edge; (size_t)-1 none */
};

#define NONE ((size_t)-1)

static void join(struct links *l, size_t a, size_t b)
{
	size_t *s = l->to + 2 * a;
	if (s[0] == NONE)
		s[0] = b;
	else
		s[1] = b;
	s = l->to + 2 * b;
	if (s[0] == NONE)
		s[0] = a;
	else
		s[1] = a;
}

/* one triangle: corners (j, k) and their edges e[0] (c0-c1), e[1] (c1-c2),
 * e[2] (c2-c0) */
static void triangle(const struct plane *pl, struct links *l, const int c[3][2],
		     const size_t e[3])
{
	int below[3], n = 0;
	for (int q = 0; q < 3; q++) {
		below[q] = val(pl, c[q][0], c[q][1]) < pl->level;
		n += below[q];
	}
	if (n == 0 || n == 3)
		return;
	size_t cross[2];
	int m = 0;
	for (int q = 0; q < 3; q++)
		if (below[q] != below[(q + 1) % 3])
			cross[m++] = e[q];
	join(l, cross[0], cross[1]);
}

void fmm_cut(const struct fmm *f, double t, int axis, double value,
	     struct plot_file *pf, const double bounds[4])
{
	struct plot_set *set = fmt_plot_add_set(pf, bounds);
	int other = 1 - axis;
	if (f->n[other] < 2 || f->n[2] < 2)
		return;
	if (t <= 0) {       /* the flat resist top */
		double top[4] = {f->bounds[2 * other], f->bounds[5],
				 f->bounds[2 * other + 1], f->bounds[5]};
		fmt_plot_add_curve(pf, set, 2, top);
		return;
	}
	struct plane pl;
	pl.nj = f->n[other];
	pl.nk = f->n[2] + 1;
	pl.level = t;
	size_t nn = (size_t)pl.nj * (size_t)pl.nk;
	pl.v = xreallocarray(NULL, nn, sizeof *pl.v);
	pl.w = xreallocarray(NULL, nn, sizeof *pl.w);
	pl.u = xreallocarray(NULL, (size_t)pl.nj, sizeof *pl.u);
	pl.z = xreallocarray(NULL, (size_t)pl.nk, sizeof *pl.z);
	for (int j = 0; j < pl.nj; j++)
		pl.u[j] = j == pl.nj - 1 ? f->bounds[2 * other + 1]
					 : f->bounds[2 * other] + j * f->h[other];
	pl.z[0] = f->bounds[4];
	for (int k = 1; k < pl.nk; k++)
		pl.z[k] = k == pl.nk - 1 ? f->bounds[5] : f->bounds[4] + (k - 1) * f->h[2];
	for (int j = 0; j < pl.nj; j++) {
		pl.v[j] = t + 1;    /* the virtual row: above the level */
		pl.w[j] = 0;
		for (int k = 1; k < pl.nk; k++) {
			double p[3];
			p[axis] = value;
			p[other] = pl.u[j];
			p[2] = pl.z[k];
			pl.v[(size_t)k * (size_t)pl.nj + (size_t)j] = fmm_time_at(f, p);
			pl.w[(size_t)k * (size_t)pl.nj + (size_t)j] = fmm_rate_at(f, p);
		}
	}
	struct links l;
	l.to = xreallocarray(NULL, 3 * nn, 2 * sizeof *l.to);
	for (size_t i = 0; i < 6 * nn; i++)
		l.to[i] = NONE;
	for (int k = 0; k + 1 < pl.nk; k++)
		for (int j = 0; j + 1 < pl.nj; j++) {
			size_t h0 = edge_id(&pl, j, k, 0), h1 = edge_id(&pl, j, k + 1, 0);
			size_t v0 = edge_id(&pl, j, k, 1), v1 = edge_id(&pl, j + 1, k, 1);
			size_t dg = edge_id(&pl, j, k, 2);
			const int ta[3][2] = {{j, k}, {j + 1, k}, {j + 1, k + 1}};
			const size_t ea[3] = {h0, v1, dg};
			triangle(&pl, &l, ta, ea);
			const int tb[3][2] = {{j, k}, {j + 1, k + 1}, {j, k + 1}};
			const size_t eb[3] = {dg, h1, v0};
			triangle(&pl, &l, tb, eb);
		}
	/* chains: open ones from an end (one link) first, then loops */
	char *used = xcalloc(3 * nn, 1);
	double *poly = NULL;
	size_t cap = 0;
	for (int pass = 0; pass < 2; pass++)
		for (size_t s0 = 0; s0 < 3 * nn; s0++) {
			if (l.to[2 * s0] == NONE || used[s0])
				continue;
			if (pass == 0 && l.to[2 * s0 + 1] != NONE)
				continue;
			size_t n = 0, prev = NONE, s = s0;
			while (s != NONE && !used[s]) {
				used[s] = 1;
				xgrow(&poly, &cap, 2 * (n + 2), sizeof *poly);
				edge_point(&pl, s, poly + 2 * n);
				n++;
				size_t nx = l.to[2 * s] != prev ? l.to[2 * s] : l.to[2 * s + 1];
				prev = s;
				s = nx;
			}
			if (s == s0 && n > 2) {     /* a closed loop */
				poly[2 * n] = poly[0];
				poly[2 * n + 1] = poly[1];
				n++;
			}
			if (n >= 2 && n <= PLOT_MAX_COUNT)
				fmt_plot_add_curve(pf, set, (int)n, poly);
		}
	free(poly);
	free(used);
	free(l.to);
	free(pl.v);
	free(pl.w);
	free(pl.u);
	free(pl.z);
}
