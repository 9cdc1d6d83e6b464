/*
 * peb_steps.c - the step counts of the chemically amplified resist's bake
 * (peb.c): the column steps n, doubled until m of sample columns changes
 * by less than PEB_TOL between two counts, and the x-y steps K, doubled
 * until m of the x-z and y-z slices through the steepest image edge
 * does; the error of the finer count estimated by Richardson once the
 * changes fall as a second-order scheme's do.  The whole bake's cost is
 * checked against the budget before each count is tried.
 */
#include "bleach.h"
#include "budget.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Whether the finer of two step counts is within PEB_TOL of the converged
 * m, from the change diff between them and the change prev between the
 * two counts before (0: none): the change itself below PEB_TOL (the
 * finer count's error is below it if the scheme is at least first
 * order), or, once the changes fall as a second-order scheme's do (by 3
 * or more a doubling; 4 in theory, 3.8 to 3.9 measured on the examples),
 * a third of it, the finer count's error by Richardson's estimate. */
static double peb_error(double diff, double prev)
{
	return prev > 0 && prev >= 3 * diff ? diff / 3 : diff;
}

static int peb_converged(double diff, double prev)
{
	return peb_error(diff, prev) < PEB_TOL;
}

/* Sample columns for the step choice. */
#define PEB_SAMPLES 9

/* budget_check of the whole bake in n steps, once it is beyond the
 * limits (with -big it only reports, once). */
static double budget_points, budget_t_point;
static const char *budget_where;

void peb_set_budget(double points, double t_point, const char *where)
{
	budget_points = points;
	budget_t_point = t_point;
	budget_where = where;
}

static void peb_budget(const struct peb_params *pp, double h0max, int n, int *checked)
{
	if (!(budget_points > 0) || *checked)
		return;
	double per = budget_t_point + peb_react_seconds(pp, h0max, pp->t / n);
	double secs = budget_points * n * per, bytes = budget_points * 3 * sizeof(double);
	if (secs <= BUDGET_SECONDS && bytes <= budget_memory())
		return;
	char what[80];
	snprintf(what, sizeof what, "%.3g bake points x %d steps or more", budget_points, n);
	budget_check(budget_where, what, secs, bytes);
	*checked = 1;
}

int peb_choose_steps(const struct peb_params *pp, const double *h0, size_t ncol, int nz,
		     double dz, double *change)
{
	/* the columns of least and most acid and quantiles between, by
	 * column mean: each with its own reaction and front history */
	double *mean = xreallocarray(NULL, ncol, sizeof *mean);
	size_t *idx = xreallocarray(NULL, ncol, sizeof *idx);
	for (size_t q = 0; q < ncol; q++) {
		double s = 0;
		for (int k = 0; k < nz; k++)
			s += h0[(size_t)k * ncol + q];
		mean[q] = s;
		idx[q] = q;
	}
	/* insertion-free selection: sort indices by mean (ties by index, so
	 * the choice is deterministic) */
	for (size_t i = 1; i < ncol; i++) {
		size_t v = idx[i], j = i;
		if (ncol > 4096)
			break;  /* large windows: sampled below by stride instead */
		while (j > 0 && (mean[idx[j - 1]] > mean[v] ||
				 (mean[idx[j - 1]] == mean[v] && idx[j - 1] > v))) {
			idx[j] = idx[j - 1];
			j--;
		}
		idx[j] = v;
	}
	size_t ns = ncol < PEB_SAMPLES ? ncol : PEB_SAMPLES;
	size_t pick[PEB_SAMPLES];
	if (ncol > 4096) {
		/* most and least acid, and columns spread over the window */
		size_t qmin = 0, qmax = 0;
		for (size_t q = 1; q < ncol; q++) {
			if (mean[q] < mean[qmin]) qmin = q;
			if (mean[q] > mean[qmax]) qmax = q;
		}
		pick[0] = qmin;
		pick[1] = qmax;
		for (size_t s = 2; s < ns; s++)
			pick[s] = (s - 1) * ncol / ns;
	} else {
		for (size_t s = 0; s < ns; s++)
			pick[s] = idx[ns > 1 ? s * (ncol - 1) / (ns - 1) : 0];
	}
	size_t nn = ns * (size_t)nz;
	double *col = xreallocarray(NULL, nn, sizeof *col);
	double *a = xreallocarray(NULL, nn, sizeof *a);
	double *b = xreallocarray(NULL, nn, sizeof *b);
	for (int k = 0; k < nz; k++)
		for (size_t s = 0; s < ns; s++)
			col[(size_t)k * ns + s] = h0[(size_t)k * ncol + pick[s]];
	int n = PEB_MIN_STEPS;
	double h0max = 0;
	for (size_t k = 0; k < nn; k++)
		h0max = fmax(h0max, col[k]);
	/* the bake at the count about to be tried must fit the budget, so
	 * that the search itself (a small part of it) never runs away */
	int checked = 0;
	peb_budget(pp, h0max, n, &checked);
	memcpy(a, col, nn * sizeof *a);
	peb_columns(pp, a, ns, nz, dz, n);
	double diff = 0, prev = 0;
	for (;;) {
		peb_budget(pp, h0max, 2 * n, &checked);
		memcpy(b, col, nn * sizeof *b);
		peb_columns(pp, b, ns, nz, dz, 2 * n);
		diff = 0;
		for (size_t k = 0; k < nn; k++)
			if (fabs(a[k] - b[k]) > diff)
				diff = fabs(a[k] - b[k]);
		n *= 2;
		if (peb_converged(diff, prev) || n >= PEB_MAX_STEPS)
			break;
		prev = diff;
		memcpy(a, b, nn * sizeof *a);
	}
	if (change)
		*change = peb_error(diff, prev);
	free(mean);
	free(idx);
	free(col);
	free(a);
	free(b);
	return n;
}

/* m of an x-z slice (row j) or a y-z slice (column i) of h0 after the
 * bake in nouter x-y steps of n / nouter column steps, into out. */
static void slice_run(const struct peb_params *pp, const double *h0, int nx, int ny, int nz,
		      double dx, double dy, double dz, int along_x, int at, int n, int nouter,
		      double *out)
{
	int len = along_x ? nx : ny;
	size_t ncol = (size_t)nx * (size_t)ny;
	for (int k = 0; k < nz; k++)
		for (int s = 0; s < len; s++)
			out[(size_t)k * len + s] = h0[(size_t)k * ncol +
				(along_x ? (size_t)at * nx + s : (size_t)s * nx + at)];
	peb_run(pp, out, len, 1, nz, along_x ? dx : dy, 1, dz, nouter, n / nouter, NULL);
}

int peb_choose_outer(const struct peb_params *pp, const double *h0, int nx, int ny, int nz,
		     double dx, double dy, double dz, int n, int kmin, double *change)
{
	if (change)
		*change = 0;
	if ((nx <= 2 && ny <= 2) || !(pp->dh > 0 || pp->dq > 0))
		return 1;
	if (nx - 1 <= PEB_XY_CIRC_MAX && ny - 1 <= PEB_XY_CIRC_MAX)
		return n;
	/* the slices through the column where the column-mean acid changes
	 * most from its neighbours in x and y: the steepest image edge */
	size_t ncol = (size_t)nx * (size_t)ny;
	double *c = xcalloc(ncol, sizeof *c);
	for (int k = 0; k < nz; k++)
		for (size_t q = 0; q < ncol; q++)
			c[q] += h0[(size_t)k * ncol + q];
	int bi = 0, bj = 0;
	double best = -1;
	for (int j = 0; j + 1 < ny || (ny == 1 && j == 0); j++)
		for (int i = 0; i + 1 < nx; i++) {
			size_t q = (size_t)j * nx + i;
			double g = fabs(c[q + 1] - c[q]) + (j + 1 < ny ? fabs(c[q + nx] - c[q]) : 0);
			if (g > best) {
				best = g;
				bi = i;
				bj = j;
			}
		}
	free(c);
	int len = nx > ny ? nx : ny;
	double *a = xreallocarray(NULL, (size_t)len * nz, 2 * sizeof *a);
	double *b = xreallocarray(NULL, (size_t)len * nz, 2 * sizeof *b);
	int K = kmin > 0 ? kmin : n / PEB_OUTER_START > 0 ? n / PEB_OUTER_START : 1;
	double diff = 0, prev = 0;
	/* each count's slices run once: the finer of a pair is the coarser of
	 * the next */
	for (int dir = 0; dir < 2; dir++)
		if ((dir == 0 ? nx : ny) > 2 && K < n)
			slice_run(pp, h0, nx, ny, nz, dx, dy, dz, dir == 0, dir == 0 ? bj : bi, n, K,
				  a + (size_t)dir * len * nz);
	for (;;) {
		if (K >= n)
			break;
		diff = 0;
		for (int dir = 0; dir < 2; dir++) {
			int l = dir == 0 ? nx : ny;
			if (l <= 2)
				continue;
			double *ad = a + (size_t)dir * len * nz, *bd = b + (size_t)dir * len * nz;
			slice_run(pp, h0, nx, ny, nz, dx, dy, dz, dir == 0, dir == 0 ? bj : bi, n, 2 * K, bd);
			for (size_t s = 0; s < (size_t)l * nz; s++)
				if (fabs(ad[s] - bd[s]) > diff)
					diff = fabs(ad[s] - bd[s]);
			memcpy(ad, bd, (size_t)l * nz * sizeof *ad);
		}
		K *= 2;
		if (peb_converged(diff, prev))
			break;
		prev = diff;
	}
	free(a);
	free(b);
	if (change)
		*change = peb_error(diff, prev);
	return K < n ? K : n;
}
