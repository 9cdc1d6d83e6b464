/*
 * e2test.h - helpers shared by etch2d's C tests: a 2D rate array from a
 * function of (x, z), one etch2d run in memory, the points of a set, and
 * the distance from a point to the polylines of a set.
 */
#ifndef E2TEST_H
#define E2TEST_H

#include "etch2d.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A 2D (ny = 1) rate array of nx x nz points over the box b (x0 x1 z0 z1). */
static inline struct ratefile *t_rate(int nx, int nz, const double b[4],
				      double (*rate)(double x, double z))
{
	double bb[6] = {b[0], b[1], 0, 0, b[2], b[3]};
	struct ratefile *r = fmt_rate_new(nx, 1, nz, bb);
	double *v = fmt_rate_values(r);
	for (int k = 0; k < nz; k++)
		for (int i = 0; i < nx; i++)
			v[(size_t)k * nx + i] = rate(fmt_rate_x(r, i), fmt_rate_z(r, k));
	return r;
}

static inline void t_opts(struct e2opts *o, int method, double et, double pt)
{
	memset(o, 0, sizeof *o);
	o->method = method;
	o->et = et;
	o->pt = pt;
	o->rl = 0.1;
}

/* Runs o over r; the caller frees with e2_free. */
static inline void t_run(struct e2 *e, const struct ratefile *r, struct rfield *f,
			 const struct e2opts *o)
{
	fmt_rate_field(f, r, "test");
	e2_init(e, f, o);
	e2_run(e);
}

/* Distance from p to the polylines of set s. */
static inline double t_dist(const struct plot_set *s, const double p[2])
{
	double best = INFINITY;
	for (int c = 0; c < s->ncurves; c++) {
		const struct plot_curve *cv = &s->curves[c];
		for (int k = 0; k + 1 < cv->npts; k++) {
			const double *a = cv->p + 2 * k, *b = a + 2;
			double dx = b[0] - a[0], dz = b[1] - a[1], l2 = dx * dx + dz * dz;
			double u = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dz) / l2 : 0;
			if (u < 0) u = 0;
			if (u > 1) u = 1;
			double d = hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dz);
			if (d < best)
				best = d;
		}
	}
	return best;
}

static int t_cmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return x < y ? -1 : x > y;
}

/* The q-quantile of n values (sorted in place). */
static inline double t_quantile(double *v, size_t n, double q)
{
	qsort(v, n, sizeof *v, t_cmp);
	size_t k = (size_t)floor(q * (double)(n - 1) + 0.5);
	return v[k];
}

#endif
