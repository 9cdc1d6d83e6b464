/*
 * fmm_levels.c - the z levels a decimated surface is extracted on.
 *
 * The rate grid is often far finer in z than in x-y (examples/defect:
 * 0.0023 um against 0.1 um, to resolve the standing waves), so marching
 * tetrahedra make the walls of thin slivers, hundreds of thousands a
 * set, which the decimator then spends its time failing to collapse.
 * Where T is smooth in z, the planes between some of the z nodes add
 * nothing the tolerance can see: here, for the set at time t, a subset
 * of the z nodes is kept, the same for every column (so the cells stay a
 * grid and marching tetrahedra on it a conforming surface), chosen
 * greedily from the top, so that in the cells the surface at t crosses
 * (mark_near) every node skipped has, by the coarser grid's edge model
 * (iso_crossing, inverted), a value within err um of distance of its
 * own: |T - T'| R, first order, as |grad T| = 1 / R (the eikonal
 * equation, fmm.h); and the taller cells' tetrahedra move T by no more
 * (cells_ok: their mixed differences).  Values after the last print
 * time are clamped to it (no surface written reaches them).  A span
 * never exceeds the finer x-y spacing, so the cells stay no taller than
 * wide.  The estimates are first order: on examples/contact without
 * bake the distances measured exceeded them by up to 30 %, which the
 * caller's margin covers (fmm.h, FMM_LEVEL_MARGIN).
 *
 * The grid kept is returned as a struct fmm whose z axis counts levels
 * (bounds 0 .. nk-1, spacing 1), and the levels' z: a point of its
 * surface at level coordinate u maps to z affinely inside each layer,
 * which is exactly the surface marching tetrahedra give on the
 * non-uniform grid (fmm_level_z).
 */
#include "fmm.h"
#include "iso.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* grid line k of axis d, the expression iso.c places its points by */
static double line(const struct fmm *f, int d, int k)
{
	return f->bounds[2 * d] + (f->bounds[2 * d + 1] - f->bounds[2 * d]) * k / (f->n[d] - 1);
}

/* A span's test: the grid, the set's time t, values clamped at tm (the
 * last time written), the bound err, um, and per column (scratch) whether
 * a cell beside it holds the surface at t within the span. */
struct span {
	const struct fmm *f;
	double t, tm, err;
	unsigned char *near;
	double est;             /* the largest estimate of the last span tested */
};

/* Marks the columns beside the cells between z nodes a and b (a < b)
 * whose nodes there have values on both sides of t (the cells the
 * surface at t crosses); 0 if there are none. */
static int mark_near(const struct span *sp, int a, int b)
{
	const struct fmm *f = sp->f;
	size_t nx = (size_t)f->n[0], nxy = nx * (size_t)f->n[1];
	int any = 0;
	memset(sp->near, 0, nxy);
	for (size_t j = 0; j + 1 < (size_t)f->n[1]; j++)
		for (size_t i = 0; i + 1 < nx; i++) {
			size_t c[4] = {j * nx + i, j * nx + i + 1, (j + 1) * nx + i, (j + 1) * nx + i + 1};
			int below = 0, above = 0;
			for (int k = a; k <= b && !(below && above); k++)
				for (int q = 0; q < 4; q++) {
					double v = f->t[(size_t)k * nxy + c[q]];
					below |= v < sp->t;
					above |= v >= sp->t;
				}
			if (below && above) {
				for (int q = 0; q < 4; q++)
					sp->near[c[q]] = 1;
				any = 1;
			}
		}
	return any;
}

/* Whether the cells between the z nodes a and b, as one layer, stay
 * within err of the layers of the nodes: marching tetrahedra interpolate
 * a cell linearly in each of its six tetrahedra, which a layer's
 * columns changing by different amounts in z (a mixed difference D)
 * moves by up to D / 4 in T, |grad T| estimated by the cell's mean
 * differences (at least 1 / R, the fastest corner's rate).  Only the
 * cells whose four columns are all near the surface are tested. */
static int cells_ok(struct span *sp, int a, int b)
{
	const struct fmm *f = sp->f;
	double tm = sp->tm;
	size_t nx = (size_t)f->n[0], nxy = nx * (size_t)f->n[1];
	const double *ta = f->t + (size_t)a * nxy, *tb = f->t + (size_t)b * nxy;
	const double *ra = f->rate + (size_t)a * nxy, *rb = f->rate + (size_t)b * nxy;
	double dz = line(f, 2, b) - line(f, 2, a);
	for (size_t j = 0; j + 1 < (size_t)f->n[1]; j++)
		for (size_t i = 0; i + 1 < nx; i++) {
			size_t c[4] = {j * nx + i, j * nx + i + 1, (j + 1) * nx + i, (j + 1) * nx + i + 1};
			if (!(sp->near[c[0]] && sp->near[c[1]] && sp->near[c[2]] && sp->near[c[3]]))
				continue;
			double va[4], vb[4], lo = INFINITY, hi = -INFINITY, gz = 0, rmax = 0;
			for (int q = 0; q < 4; q++) {
				va[q] = fmin(ta[c[q]], tm);
				vb[q] = fmin(tb[c[q]], tm);
				double d = vb[q] - va[q];
				lo = fmin(lo, d);
				hi = fmax(hi, d);
				gz += fabs(d);
				rmax = fmax(rmax, fmax(ra[c[q]], rb[c[q]]));
			}
			double mixed = hi - lo;
			if (mixed == 0)
				continue;
			double gx = (fabs(va[1] - va[0]) + fabs(va[3] - va[2]) + fabs(vb[1] - vb[0]) +
				     fabs(vb[3] - vb[2])) / (4 * f->h[0]);
			double gy = (fabs(va[2] - va[0]) + fabs(va[3] - va[1]) + fabs(vb[2] - vb[0]) +
				     fabs(vb[3] - vb[1])) / (4 * f->h[1]);
			gz /= 4 * dz;
			double g = fmax(sqrt(gx * gx + gy * gy + gz * gz), rmax > 0 ? 1 / rmax : 0);
			double e = g > 0 ? 0.25 * mixed / g : INFINITY;
			if (!(e <= sp->err))
				return 0;
			sp->est = fmax(sp->est, e);
		}
	return 1;
}

/* whether the z nodes strictly between a and b (a < b) may be skipped */
static int span_ok(struct span *sp, int a, int b)
{
	sp->est = 0;
	if (!mark_near(sp, a, b))
		return 1;   /* the surface at t does not come here */
	if (!cells_ok(sp, a, b))
		return 0;
	const struct fmm *f = sp->f;
	double tm = sp->tm;
	size_t nxy = (size_t)f->n[0] * (size_t)f->n[1];
	const double *ta = f->t + (size_t)a * nxy, *tb = f->t + (size_t)b * nxy;
	const double *ra = f->rate + (size_t)a * nxy, *rb = f->rate + (size_t)b * nxy;
	double za = line(f, 2, a), zb = line(f, 2, b);
	for (int k = a + 1; k < b; k++) {
		double s = (line(f, 2, k) - za) / (zb - za);
		const double *tk = f->t + (size_t)k * nxy, *rk = f->rate + (size_t)k * nxy;
		for (size_t c = 0; c < nxy; c++) {
			if (!sp->near[c])
				continue;
			double tc = iso_value_at(ta[c], ra[c], tb[c], rb[c], s);
			double d = fabs(fmin(tk[c], tm) - fmin(tc, tm));
			if (d == 0)
				continue;
			double r = rk[c] > 0 ? rk[c] : fmax(ra[c], rb[c]);
			double e = r > 0 ? d * r : INFINITY;
			if (!(e <= sp->err))
				return 0;
			sp->est = fmax(sp->est, e);
		}
	}
	return 1;
}

/* Tests the span of w nodes below node b: on success it is the longest
 * known good, with its estimate; otherwise the shortest known bad. */
static void try_span(struct span *sp, int b, int w, int *good, int *bad, double *est)
{
	if (span_ok(sp, b - w, b)) {
		*good = w;
		*est = sp->est;
	} else
		*bad = w;
}

struct fmm *fmm_levels(const struct fmm *f, double t, double tmax, double err, double **zl,
		       double *used)
{
	int nz = f->n[2];
	int *keep = xreallocarray(NULL, (size_t)(nz > 0 ? nz : 1), sizeof *keep);
	int nk = 0;
	/* a span at most the finer x-y spacing, in z nodes */
	double hxy = fmin(f->h[0], f->h[1]);
	int maxspan = f->h[2] > 0 && hxy > 0 ? (int)fmin(hxy / f->h[2], (double)nz) : 1;
	if (maxspan < 1 || !f->rate)
		maxspan = 1;
	struct span sp = {f, t, tmax + 1e-9 * fabs(tmax), err, NULL, 0};
	*used = 0;
	sp.near = xcalloc((size_t)f->n[0] * (size_t)f->n[1], 1);
	/* from the top down: the longest span found by doubling, then halving */
	for (int b = nz - 1; b >= 0;) {
		keep[nk++] = b;
		if (b == 0)
			break;
		int good = 1, bad = 0;      /* spans known to pass / to fail (0: none) */
		double est = 0;             /* the estimate of span good */
		int lim = maxspan < b ? maxspan : b;
		for (int s = 2; maxspan >= 2 && !bad; s *= 2) {
			int w = s < lim ? s : lim;
			try_span(&sp, b, w, &good, &bad, &est);
			if (w == lim)
				break;
		}
		while (bad && bad - good > 1)
			try_span(&sp, b, good + (bad - good) / 2, &good, &bad, &est);
		b -= good;
		*used = fmax(*used, est);
	}
	/* ascending */
	for (int i = 0; i < nk / 2; i++) {
		int x = keep[i];
		keep[i] = keep[nk - 1 - i];
		keep[nk - 1 - i] = x;
	}
	struct fmm *g = xcalloc(1, sizeof *g);
	*g = *f;
	g->march = NULL;
	g->n[2] = nk;
	g->bounds[4] = 0;
	g->bounds[5] = nk - 1;
	g->h[2] = 1;
	size_t nxy = (size_t)f->n[0] * (size_t)f->n[1];
	g->t = xreallocarray(NULL, nxy * (size_t)nk, sizeof *g->t);
	g->rate = f->rate ? xreallocarray(NULL, nxy * (size_t)nk, sizeof *g->rate) : NULL;
	*zl = xreallocarray(NULL, (size_t)nk, sizeof **zl);
	for (int q = 0; q < nk; q++) {
		size_t from = (size_t)keep[q] * nxy, to = (size_t)q * nxy;
		for (size_t c = 0; c < nxy; c++) {
			g->t[to + c] = f->t[from + c];
			if (g->rate)
				g->rate[to + c] = f->rate[from + c];
		}
		(*zl)[q] = line(f, 2, keep[q]);
	}
	free(keep);
	free(sp.near);
	return g;
}

double fmm_level_z(const double *zl, int nk, double u)
{
	if (nk < 2 || u <= 0)
		return zl[0];
	if (u >= nk - 1)
		return zl[nk - 1];
	int k = (int)floor(u);
	double s = u - k;
	return s == 0 ? zl[k] : zl[k] + s * (zl[k + 1] - zl[k]);
}
