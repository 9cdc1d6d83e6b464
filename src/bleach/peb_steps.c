/*
 * peb_steps.c - the step counts of the chemically amplified resist's bake
 * (peb.c): the column steps n, doubled until m of sample columns changes
 * by less than PEB_TOL between two counts, and the x-y steps K, doubled
 * until m of the x-z and y-z slices through the steepest image edge
 * does; the error of the finer count estimated by Richardson once the
 * changes fall as a second-order scheme's do.  The whole bake's cost is
 * checked against the budget before each count is tried.  Then, for a
 * deterministic bake, whether two bakes of a half and a quarter of the
 * chosen count, extrapolated (Richardson), are as accurate for less.
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

/* The sample columns of peb_choose_steps and peb_choose_extrapolated:
 * the columns of least and most acid and quantiles between, by column
 * mean, each with its own reaction and front history; their indices into
 * pick, their count returned. */
static size_t pick_columns(const double *h0, size_t ncol, int nz, size_t pick[PEB_SAMPLES])
{
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
	free(mean);
	free(idx);
	return ns;
}

int peb_choose_steps(const struct peb_params *pp, const double *h0, size_t ncol, int nz,
		     double dz, double *change)
{
	size_t pick[PEB_SAMPLES], ns = pick_columns(h0, ncol, nz, pick);
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

/* The column where the column-mean acid changes most from its neighbours
 * in x and y, the steepest image edge: the slices of peb_choose_outer
 * and peb_choose_extrapolated pass through it. */
static void steepest_edge(const double *h0, int nx, int ny, int nz, int *bi, int *bj)
{
	size_t ncol = (size_t)nx * (size_t)ny;
	double *c = xcalloc(ncol, sizeof *c);
	for (int k = 0; k < nz; k++)
		for (size_t q = 0; q < ncol; q++)
			c[q] += h0[(size_t)k * ncol + q];
	*bi = *bj = 0;
	double best = -1;
	for (int j = 0; j + 1 < ny || (ny == 1 && j == 0); j++)
		for (int i = 0; i + 1 < nx; i++) {
			size_t q = (size_t)j * nx + i;
			double g = fabs(c[q + 1] - c[q]) + (j + 1 < ny ? fabs(c[q + nx] - c[q]) : 0);
			if (g > best) {
				best = g;
				*bi = i;
				*bj = j;
			}
		}
	free(c);
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
	int bi, bj;
	steepest_edge(h0, nx, ny, nz, &bi, &bj);
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

/* ---- the extrapolated bake ---- */

/* Strang splitting is symmetric (each step the same composition read
 * forwards and backwards), so the error of m after n steps expands in even
 * powers, c / n^2 + d / n^4 + ..., the graded steps (peb.c) a fixed map of
 * uniform ones; Richardson's (4 m_2n - m_n) / 3 takes the n^-2 term out
 * and errs by about d / (4 n^4).  Measured against 512 steps on
 * examples/car-krf-lines, m from 8 and 16 steps extrapolated errs by
 * 7.8e-4, from 16 and 32 by 8.5e-5, where 32 steps alone err by 7.4e-4. */
double peb_extrapolate(double coarse, double fine)
{
	double m = (4 * fine - coarse) / 3;
	return m < 0 ? 0 : m > 1 ? 1 : m;
}

/* The counts of one level of peb_choose_extrapolated: (n, K) halved, or
 * 0 when it cannot be (the x-y splitting, one outer step, would not
 * refine with it; fewer than 2 steps). */
static int halve(int *n, int *K, int xy)
{
	if (*n < 4 || (*K == 1 && xy))
		return 0;
	*n /= 2;
	if (*K > 1)
		*K /= 2;
	return 1;
}

struct samples {
	size_t ns;              /* sample columns */
	size_t pick[PEB_SAMPLES];
	int slices, bi, bj;     /* slices through (bi, bj): 1 if taken */
	size_t len;             /* values of one level: columns, then slices */
};

/* m of the samples after the bake in n steps, K of them in x-y, into out
 * (s->len values): the columns z and reaction only (as peb_choose_steps),
 * the slices with the x-y diffusion (as peb_choose_outer). */
static void samples_run(const struct peb_params *pp, const struct samples *s,
			const double *h0, int nx, int ny, int nz, double dx, double dy,
			double dz, int n, int K, double *out)
{
	size_t ncol = (size_t)nx * (size_t)ny;
	for (int k = 0; k < nz; k++)
		for (size_t c = 0; c < s->ns; c++)
			out[(size_t)k * s->ns + c] = h0[(size_t)k * ncol + s->pick[c]];
	peb_columns(pp, out, s->ns, nz, dz, n);
	double *o = out + s->ns * (size_t)nz;
	for (int dir = 0; s->slices && dir < 2; dir++) {
		if ((dir == 0 ? nx : ny) <= 2)
			continue;
		slice_run(pp, h0, nx, ny, nz, dx, dy, dz, dir == 0, dir == 0 ? s->bj : s->bi, n, K, o);
		o += (size_t)(dir == 0 ? nx : ny) * nz;
	}
}

int peb_choose_extrapolated(const struct peb_params *pp, const double *h0, int nx, int ny,
			    int nz, double dx, double dy, double dz, int n, int nouter, int counts[4],
			    double *change)
{
	struct samples s = {0};
	int xy = (nx > 2 || ny > 2) && (pp->dh > 0 || pp->dq > 0);
	s.ns = pick_columns(h0, (size_t)nx * (size_t)ny, nz, s.pick);
	s.len = s.ns * (size_t)nz;
	/* the slices where peb_choose_outer takes them (periods beyond the
	 * circulant's: x-y steps fewer than column steps) */
	if (xy && (nx - 1 > PEB_XY_CIRC_MAX || ny - 1 > PEB_XY_CIRC_MAX)) {
		s.slices = 1;
		steepest_edge(h0, nx, ny, nz, &s.bi, &s.bj);
		s.len += (size_t)((nx > 2 ? nx : 0) + (ny > 2 ? ny : 0)) * nz;
	}
	/* m at n, n / 2 and n / 4: the pair (n / 4, n / 2) extrapolated is
	 * within the estimate of converged when it is within it of the pair
	 * (n / 2, n), whose own error is some 16 times smaller.  Pairs of
	 * fewer steps are not tried: the columns do not see the x-y
	 * splitting where the periods are short (no slices), and on
	 * examples/car-arf-contact the pair (4, 8) errs by 4.3e-3 where the
	 * columns' estimate is 8.9e-4 (the pair (8, 16): 6.3e-4) */
	double *m[3];
	for (int l = 0; l < 3; l++)
		m[l] = xreallocarray(NULL, s.len, sizeof *m[l]);
	int c[4] = {n, nouter, 0, 0}, best = 0, ok = halve(&c[0], &c[1], xy);
	c[2] = c[0];
	c[3] = c[1];
	if (ok && halve(&c[2], &c[3], xy)) {
		samples_run(pp, &s, h0, nx, ny, nz, dx, dy, dz, n, nouter, m[0]);
		samples_run(pp, &s, h0, nx, ny, nz, dx, dy, dz, c[0], c[1], m[1]);
		samples_run(pp, &s, h0, nx, ny, nz, dx, dy, dz, c[2], c[3], m[2]);
		double err = 0;
		for (size_t k = 0; k < s.len; k++) {
			double e = fabs(peb_extrapolate(m[2][k], m[1][k]) -
					peb_extrapolate(m[1][k], m[0][k]));
			if (e > err)
				err = e;
		}
		if (err < PEB_TOL) {
			best = c[0];
			memcpy(counts, c, sizeof c);
			if (change)
				*change = err;
		}
	}
	for (int l = 0; l < 3; l++)
		free(m[l]);
	return best;
}
