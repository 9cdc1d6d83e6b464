/*
 * fit.c - residuals, the finite-difference Jacobian, the
 * Levenberg-Marquardt step and the covariance (see calibfit.h).
 *
 * The step is Marquardt's (1963): the normal equations damped by lambda
 * times their own diagonal, so that it does not depend on the parameters'
 * units; calib raises lambda ten-fold after a step that did not lower the
 * sum of squares and lowers it ten-fold after one that did.  The
 * parameters are few (two to a handful), so the p x p systems are solved
 * by Gaussian elimination with partial pivoting.
 */
#include "calibfit.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Points are matched when focus and dose agree to this relative
 * precision: fem prints both with 10 significant digits. */
#define CALIB_MATCH_TOL 1e-9
/* The finite-difference step, relative to the value: CD is smooth in the
 * resist parameters down to a few 0.1 % (etch -method fmm on a 41 x 41
 * grid, Mth 0.49-0.51: 0.5 nm per 0.2 %), so 1 % is well above the
 * discretisation's jitter and small against the curvature. */
#define CALIB_FD_REL 0.01
/* A step below this fraction of every finite-difference step (1e-4 of
 * the value) is nil: typically a few hundredths of the 1-sigma error. */
#define CALIB_STEP_TOL 0.01

static int same(double a, double b)
{
	return fabs(a - b) <= CALIB_MATCH_TOL * (1 + fabs(a) + fabs(b));
}

void calib_match(const struct fem_table *meas, const char *fem_path, struct calib_points *s)
{
	struct fem_table *t = fmt_fem_read(fem_path);
	s->n = meas->n;
	s->p = meas->p;
	s->cd = xcalloc((size_t)meas->n, sizeof *s->cd);
	s->uncleared = 0;
	/* both tables are in (focus, dose) order: one merge pass */
	int j = 0;
	for (int i = 0; i < meas->n; i++) {
		const struct fem_point *m = &meas->p[i];
		while (j < t->n && !same(t->p[j].focus, m->focus) && t->p[j].focus < m->focus)
			j++;
		while (j < t->n && same(t->p[j].focus, m->focus) && !same(t->p[j].dose, m->dose) &&
		       t->p[j].dose < m->dose)
			j++;
		if (j < t->n && same(t->p[j].focus, m->focus) && same(t->p[j].dose, m->dose) &&
		    t->p[j].cleared)
			s->cd[i] = t->p[j].cd;
		else
			s->uncleared++;
	}
	fmt_fem_free(t);
}

void calib_points_free(struct calib_points *s)
{
	free(s->cd);
	s->cd = NULL;
}

double calib_ssr(const struct calib_points *s)
{
	double ssr = 0;
	for (int i = 0; i < s->n; i++) {
		double r = s->cd[i] - s->p[i].cd;
		ssr += r * r;
	}
	return ssr;
}

double calib_round(double v)
{
	char buf[40];
	snprintf(buf, sizeof buf, "%.8g", v);
	return strtod(buf, NULL);
}

double calib_probe_value(const struct calib_free *f, double v)
{
	double h = CALIB_FD_REL * (v != 0 ? fabs(v) : f->hi - f->lo);
	double w = calib_round(v + h);
	if (w > f->hi)
		w = calib_round(v - h);
	return w;
}

void calib_jacobian(int p, const double *v, const double *vprobe,
		    const struct calib_points *base, const struct calib_points *probe, double *J)
{
	for (int j = 0; j < p; j++)
		for (int i = 0; i < base->n; i++)
			J[i * p + j] = (probe[j].cd[i] - base->cd[i]) / (vprobe[j] - v[j]);
}

int calib_solve(int p, double *A, double *b)
{
	for (int c = 0; c < p; c++) {
		int piv = c;
		for (int r = c + 1; r < p; r++)
			if (fabs(A[r * p + c]) > fabs(A[piv * p + c]))
				piv = r;
		if (!(fabs(A[piv * p + c]) > 0))
			return 0;
		if (piv != c) {
			for (int k = 0; k < p; k++) {
				double t = A[c * p + k];
				A[c * p + k] = A[piv * p + k];
				A[piv * p + k] = t;
			}
			double t = b[c];
			b[c] = b[piv];
			b[piv] = t;
		}
		for (int r = c + 1; r < p; r++) {
			double m = A[r * p + c] / A[c * p + c];
			for (int k = c; k < p; k++)
				A[r * p + k] -= m * A[c * p + k];
			b[r] -= m * b[c];
		}
	}
	for (int c = p - 1; c >= 0; c--) {
		double s = b[c];
		for (int k = c + 1; k < p; k++)
			s -= A[c * p + k] * b[k];
		b[c] = s / A[c * p + c];
	}
	return 1;
}

/* J'J (p x p) and J'r. */
static void normal(int p, int n, const double *J, const double *r, double *A, double *g)
{
	for (int a = 0; a < p; a++) {
		for (int b = 0; b < p; b++) {
			double s = 0;
			for (int i = 0; i < n; i++)
				s += J[i * p + a] * J[i * p + b];
			A[a * p + b] = s;
		}
		double s = 0;
		for (int i = 0; r && i < n; i++)
			s += J[i * p + a] * r[i];
		g[a] = s;
	}
}

int calib_step(int p, const struct calib_free *f, const double *v, int n, const double *J,
	       const double *r, double lambda, double scale, double *out)
{
	double A[CALIB_MAX_FREE * CALIB_MAX_FREE], g[CALIB_MAX_FREE];
	normal(p, n, J, r, A, g);
	for (int j = 0; j < p; j++) {
		g[j] = -g[j];
		if (A[j * p + j] > 0) {
			A[j * p + j] *= 1 + lambda;
		} else {
			/* no effect on any CD: the parameter stays where it is */
			for (int k = 0; k < p; k++)
				A[j * p + k] = A[k * p + j] = 0;
			A[j * p + j] = 1;
			g[j] = 0;
		}
	}
	if (!calib_solve(p, A, g))
		for (int j = 0; j < p; j++)
			g[j] = 0;
	int moved = 0;
	for (int j = 0; j < p; j++) {
		double h = fabs(calib_probe_value(&f[j], v[j]) - v[j]);
		double w = calib_round(fmin(fmax(v[j] + g[j], f[j].lo), f[j].hi));
		if (fabs(w - v[j]) > CALIB_STEP_TOL * h)
			moved = 1;
		out[j] = calib_round(fmin(fmax(v[j] + scale * g[j], f[j].lo), f[j].hi));
	}
	if (!moved)
		memcpy(out, v, (size_t)p * sizeof *out);
	return moved;
}

int calib_covariance(int p, int n, const double *J, double s2, double *cov)
{
	double A[CALIB_MAX_FREE * CALIB_MAX_FREE], g[CALIB_MAX_FREE];
	int ok = 1;
	for (int c = 0; c < p; c++) {
		double M[CALIB_MAX_FREE * CALIB_MAX_FREE], e[CALIB_MAX_FREE];
		normal(p, n, J, NULL, A, g);
		memcpy(M, A, sizeof A);
		for (int k = 0; k < p; k++)
			e[k] = k == c;
		if (!calib_solve(p, M, e)) {
			ok = 0;
			for (int k = 0; k < p; k++)
				e[k] = k == c ? INFINITY : NAN;
		}
		for (int k = 0; k < p; k++)
			cov[k * p + c] = s2 * e[k];
	}
	return ok;
}
