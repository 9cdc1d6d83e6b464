/*
 * fmm_query.c - point queries on a fast-marching solution: T anywhere
 * (trilinear), and the distance from a point to the developed surface
 * T = t, the measure by which etch's two engines are cross-checked
 * (median node distance of the ray-string mesh to the fast-marching
 * front, in grid cells).
 *
 * The distance starts from the first-order estimate |T - t| / |grad T|
 * (|grad T| = 1/R by the eikonal equation) and is then made exact for the
 * interpolated field by bracketing the crossing along the gradient line
 * and bisecting: near the surface the gradient is its normal, so this is
 * the normal distance, and the search is robust where the estimate is
 * poor (rates changing within a cell, standing waves).
 */
#include "fmm.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>

/* Bisection steps: 60 halvings take any bracket below a double's
 * resolution of it. */
enum { BISECT_STEPS = 60, BRACKET_STEPS = 60 };

double fmm_time_at(const struct fmm *f, const double p[3])
{
	int lo[3];
	double w[3];
	for (int d = 0; d < 3; d++) {
		lo[d] = 0;
		w[d] = 0;
		if (f->n[d] < 2)
			continue;
		double x = fmin(fmax(p[d], f->bounds[2 * d]), f->bounds[2 * d + 1]);
		double u = (x - f->bounds[2 * d]) / f->h[d];
		lo[d] = (int)u;
		if (lo[d] > f->n[d] - 2)
			lo[d] = f->n[d] - 2;
		w[d] = u - lo[d];
	}
	size_t sy = (size_t)f->n[0], sz = sy * (size_t)f->n[1];
	double sum = 0;
	for (int q = 0; q < 8; q++) {
		double wq = 1;
		size_t n = 0;
		for (int d = 0; d < 3; d++) {
			int e = (q >> d) & 1;
			wq *= e ? w[d] : 1 - w[d];
			n += (size_t)(lo[d] + e) * (d == 0 ? 1 : d == 1 ? sy : sz);
		}
		if (wq > 0)
			sum += wq * f->t[n];
	}
	return sum;
}

/* grad T by central differences over half a cell, one-sided at the box */
static void gradient(const struct fmm *f, const double p[3], double g[3])
{
	for (int d = 0; d < 3; d++) {
		g[d] = 0;
		if (f->n[d] < 2)
			continue;
		double a[3] = {p[0], p[1], p[2]}, b[3] = {p[0], p[1], p[2]};
		a[d] = fmax(p[d] - 0.5 * f->h[d], f->bounds[2 * d]);
		b[d] = fmin(p[d] + 0.5 * f->h[d], f->bounds[2 * d + 1]);
		if (b[d] > a[d])
			g[d] = (fmm_time_at(f, b) - fmm_time_at(f, a)) / (b[d] - a[d]);
	}
}

static double along(const struct fmm *f, const double p[3], const double u[3], double s)
{
	double x[3] = {p[0] + s * u[0], p[1] + s * u[1], p[2] + s * u[2]};
	return fmm_time_at(f, x);
}

double fmm_distance(const struct fmm *f, const double p[3], double t)
{
	double q[3];
	for (int d = 0; d < 3; d++)
		q[d] = fmin(fmax(p[d], f->bounds[2 * d]), f->bounds[2 * d + 1]);
	double t0 = fmm_time_at(f, q);
	if (t0 >= 0.5 * FMM_UNREACHED)
		return FMM_UNREACHED;
	double phi0 = t0 - t;
	if (phi0 == 0)
		return 0;
	/* developed resist: the substrate below is surface too */
	double sub = INFINITY;
	if (phi0 < 0) {
		double b[3] = {q[0], q[1], f->bounds[4]};
		if (fmm_time_at(f, b) < t)
			sub = q[2] - f->bounds[4];
	}
	double g[3];
	gradient(f, q, g);
	double gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
	if (!(gn > 0))
		return sub < INFINITY ? sub : FMM_UNREACHED;
	/* walk downhill in T if T(p) > t, uphill otherwise */
	double sg = phi0 > 0 ? -1 : 1, u[3];
	for (int d = 0; d < 3; d++)
		u[d] = sg * g[d] / gn;
	double est = fabs(phi0) / gn;
	double diag = 0;
	for (int d = 0; d < 3; d++)
		diag += (f->bounds[2 * d + 1] - f->bounds[2 * d]) *
			(f->bounds[2 * d + 1] - f->bounds[2 * d]);
	diag = sqrt(diag);
	double lo = 0, hi = est, step = est;
	int found = 0;
	for (int k = 0; k < BRACKET_STEPS && lo <= diag; k++) {
		double ph = along(f, q, u, hi) - t;
		if ((ph > 0) != (phi0 > 0) || ph == 0) {
			found = 1;
			break;
		}
		lo = hi;
		step *= 1.5;
		hi = lo + step;
	}
	double d = est;
	if (found) {
		for (int k = 0; k < BISECT_STEPS; k++) {
			double mid = 0.5 * (lo + hi);
			if (mid <= lo || mid >= hi)
				break;
			double pm = along(f, q, u, mid) - t;
			if ((pm > 0) == (phi0 > 0) && pm != 0)
				lo = mid;
			else
				hi = mid;
		}
		d = 0.5 * (lo + hi);
	}
	return fmin(d, sub);
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

void fmm_distance_stats(const struct fmm *f, const double *p, size_t n, double t,
			double *median, double *p95)
{
	*median = *p95 = 0;
	if (n == 0)
		return;
	double *d = xreallocarray(NULL, n, sizeof *d);
	for (size_t i = 0; i < n; i++)
		d[i] = fmm_distance(f, p + 3 * i, t);
	qsort(d, n, sizeof *d, cmp_double);
	/* nearest rank: the smallest value with at least q*n values at or below it */
	size_t im = (n + 1) / 2, i95 = (size_t)ceil(0.95 * (double)n);
	*median = d[im - 1];
	*p95 = d[(i95 < 1 ? 1 : i95) - 1];
	free(d);
}
