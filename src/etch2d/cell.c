/*
 * cell.c - Dill's cell-removal algorithm (thesis 3.2, Figure 3.1).
 *
 * The box is tiled by nx x nz cells, each etched, or unetched with the
 * fraction f of it left (1 when untouched).  A boundary cell (unetched,
 * with a face on an etched cell or, from the resist top, on the developer
 * above) loses material at the rate R of its centre through its exposed
 * faces: the time to remove a whole cell of side a is a/R with one face,
 * a/(sqrt 2 R) with two adjacent faces (a top and a side), a/(2R) with
 * two opposite faces or three or four (our reading of the lost Figure 3.1
 * equations; they give the thesis' octagons).  Each step
 * [I]-[IV]: find the boundary cell that empties first, advance every
 * boundary cell by that time, remove the emptied ones and add their
 * unetched neighbours to the boundary.  Print times cut a step short.
 * The boundary is a plain list scanned in full every step, as the thesis
 * implemented it, so that Table 3.1's growth (about N^3) is reproduced.
 *
 * a is the side normal to the face for one face, the mean side otherwise
 * (cells are square by default).
 */
#include "methods.h"

#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A cell with less than this fraction left counts as removed: the
 * fastest cell's f - v dt is zero up to rounding. */
#define F_TINY 1e-9

struct grid {
	int nx, nz;
	double dx, dz;
	unsigned char *etched, *inlist;
	double *f, *rate;
	int *list;
	size_t nlist;
	int open_top;
};

/* Removal speed (fraction per second) of boundary cell c. */
static double speed(const struct grid *g, int c)
{
	int i = c % g->nx, k = c / g->nx;
	int l = i > 0 && g->etched[c - 1], r = i + 1 < g->nx && g->etched[c + 1];
	int d = k > 0 && g->etched[c - g->nx];
	int u = k + 1 < g->nz ? g->etched[c + g->nx] : g->open_top;
	int nface = l + r + d + u;
	double R = g->rate[c];
	if (nface == 0 || !(R > 0))
		return 0;
	if (nface == 1)
		return R / ((l || r) ? g->dx : g->dz);
	double a = 0.5 * (g->dx + g->dz);
	if (nface == 2 && !(l && r) && !(u && d))
		return M_SQRT2 * R / a;
	return 2 * R / a;
}

static void add_boundary(struct grid *g, int c)
{
	if (g->etched[c] || g->inlist[c])
		return;
	g->inlist[c] = 1;
	g->list[g->nlist++] = c;
}

static void remove_cell(struct grid *g, int c)
{
	g->etched[c] = 1;
	int i = c % g->nx, k = c / g->nx;
	if (i > 0) add_boundary(g, c - 1);
	if (i + 1 < g->nx) add_boundary(g, c + 1);
	if (k > 0) add_boundary(g, c - g->nx);
	if (k + 1 < g->nz) add_boundary(g, c + g->nx);
}

void e2_run_cell(struct e2 *e)
{
	struct grid g = {0};
	e2_cells(e, &g.nx, &g.nz);
	size_t n = (size_t)g.nx * g.nz;
	g.dx = (e->x1 - e->x0) / g.nx;
	g.dz = (e->z1 - e->z0) / g.nz;
	g.etched = xcalloc(n, 1);
	g.inlist = xcalloc(n, 1);
	g.f = xreallocarray(NULL, n, sizeof *g.f);
	g.rate = xreallocarray(NULL, n, sizeof *g.rate);
	g.list = xreallocarray(NULL, n, sizeof *g.list);
	double *v = xreallocarray(NULL, n, sizeof *v);
	e->st.bytes = n * (2 + 3 * sizeof(double) + sizeof(int));
	e->st.total = (long)n;
	for (size_t c = 0; c < n; c++) {
		int i = (int)(c % g.nx), k = (int)(c / g.nx);
		g.f[c] = 1;
		g.rate[c] = e2_rate(e, e->x0 + (i + 0.5) * g.dx, e->z0 + (k + 0.5) * g.dz, NULL);
	}
	if (e->o.seeded) {
		int i = (int)floor((e->o.seed[0] - e->x0) / g.dx);
		int k = (int)floor((e->o.seed[1] - e->z0) / g.dz);
		i = i < 0 ? 0 : i >= g.nx ? g.nx - 1 : i;
		k = k < 0 ? 0 : k >= g.nz ? g.nz - 1 : k;
		remove_cell(&g, k * g.nx + i);
	} else if (e->sp) {
		/* the cells whose centres lie above the start profile are
		 * etched; the boundary: the others beside them or on top */
		g.open_top = 1;
		for (size_t c = 0; c < n; c++) {
			int i = (int)(c % g.nx), k = (int)(c / g.nx);
			g.etched[c] = (unsigned char)e2_start_etched(e, e->x0 + (i + 0.5) * g.dx,
								      e->z0 + (k + 0.5) * g.dz);
		}
		for (size_t c = 0; c < n; c++) {
			int i = (int)(c % g.nx), k = (int)(c / g.nx);
			if (!g.etched[c] && (k == g.nz - 1 || (i > 0 && g.etched[c - 1]) ||
					     (i + 1 < g.nx && g.etched[c + 1]) ||
					     (k > 0 && g.etched[c - g.nx]) || g.etched[c + g.nx]))
				add_boundary(&g, (int)c);
		}
	} else {
		g.open_top = 1;
		for (int i = 0; i < g.nx; i++)
			add_boundary(&g, (g.nz - 1) * g.nx + i);
	}
	double t = 0;
	int next = 0;
	while (next < e->ntp) {
		if ((long)g.nlist > e->st.items)
			e->st.items = (long)g.nlist;
		/* [I] every boundary cell's removal time; the smallest is the step */
		double dt = INFINITY;
		for (size_t q = 0; q < g.nlist; q++) {
			int c = g.list[q];
			v[q] = speed(&g, c);
			if (v[q] > 0 && g.f[c] / v[q] < dt)
				dt = g.f[c] / v[q];
		}
		double tp = e->tp[next];
		int print = !(t + dt < tp);
		if (print)
			dt = tp - t;
		/* [II] advance every boundary cell by dt */
		for (size_t q = 0; q < g.nlist; q++)
			g.f[g.list[q]] -= v[q] * dt;
		t = print ? tp : t + dt;
		/* [III] remove the emptied cells, then add their neighbours */
		size_t keep = 0, nl = g.nlist;
		int *gone = NULL;
		size_t ngone = 0, gcap = 0;
		for (size_t q = 0; q < nl; q++) {
			int c = g.list[q];
			if (g.f[c] <= F_TINY) {
				xgrow(&gone, &gcap, ngone + 1, sizeof *gone);
				gone[ngone++] = c;
				g.inlist[c] = 0;
			} else {
				g.list[keep++] = c;
			}
		}
		g.nlist = keep;
		for (size_t q = 0; q < ngone; q++) {
			g.f[gone[q]] = 0;
			remove_cell(&g, gone[q]);
		}
		free(gone);
		if (ngone)
			e->st.steps++;
		if (print) {
			e2_begin_set(e);
			cells_emit(e, g.etched, g.nx, g.nz, g.open_top);
			next++;
		}
	}
	free(v);
	free(g.etched);
	free(g.inlist);
	free(g.f);
	free(g.rate);
	free(g.list);
}
