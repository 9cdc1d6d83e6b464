/*
 * expose.c - Dill's ABC bleaching (thesis 2.1, Figure 2.2; Dill et al.
 * 1975): dM/dt = -C I(z, t) M, with absorption alpha = A M + B, so that
 * the standing waves change as the resist bleaches and must be solved
 * again at every step.
 *
 * With vertical propagation (thesis 2.1) a column at aerial intensity
 * I_a receives dose D = dose * I_a, and its state depends on D alone:
 * dM/dD = -C I_rel(z; M) M.  So one column is integrated once, over dose,
 * by RK4 with a fixed step h, and the states M(z; kh) are tabulated
 * together with their exact derivatives -C I M; any column is then a
 * cubic Hermite interpolation between two rows (error O(h^4)).  This is
 * what makes a 51 x 51 x 300 exposure cost one 1D run.  The tests check
 * the table against direct runs at the same doses.
 */
#include "bleach.h"
#include "checked.h"
#include "util.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Fewest steps of a run, so that small doses are still finely resolved. */
#define EXPOSE_MIN_STEPS 16
/* Margin on the unbleached peak intensity: bleaching lets more light
 * down, and the standing-wave peaks can grow on the way. */
#define EXPOSE_IMAX_MARGIN 2.0

int exposure_init(struct exposure *e, const struct bleach_input *in, int nz,
		  double dmax, double step_scale)
{
	memset(e, 0, sizeof *e);
	thinfilm_init(&e->tf, in, nz);
	e->standing = in->standing;
	e->A = in->A;
	e->B = in->B;
	e->C = in->C;
	size_t n = (size_t)nz;
	e->kr = xcalloc(n, sizeof *e->kr);
	e->irel = xcalloc(n, sizeof *e->irel);
	e->k1 = xcalloc(n, sizeof *e->k1);
	e->k2 = xcalloc(n, sizeof *e->k2);
	e->k3 = xcalloc(n, sizeof *e->k3);
	e->k4 = xcalloc(n, sizeof *e->k4);
	e->tmp = xcalloc(n, sizeof *e->tmp);

	/* step from the peak intensity of the unbleached column */
	for (size_t j = 0; j < n; j++)
		e->tmp[j] = 1;
	exposure_intensity(e, e->tmp, e->irel);
	double imax = 0;
	for (size_t j = 0; j < n; j++)
		if (e->irel[j] > imax)
			imax = e->irel[j];
	double rate = e->C * imax * EXPOSE_IMAX_MARGIN;   /* 1/(mJ/cm2) */
	double steps = EXPOSE_MIN_STEPS;
	if (rate * dmax / EXPOSE_STEP > steps)
		steps = ceil(rate * dmax / EXPOSE_STEP);
	steps = ceil(steps / step_scale);
	if (!(steps <= EXPOSE_MAX_STEPS)) {
		exposure_free(e);
		memset(e, 0, sizeof *e);
		return -1;
	}
	e->h = dmax > 0 ? dmax / steps : 1;
	/* a dose so small that dmax / steps underflows (4e-324 mJ/cm2):
	 * one step of the whole dose, which exposes nothing measurable */
	if (!(e->h >= DBL_MIN))
		e->h = dmax > 0 ? dmax : 1;
	return 0;
}

void exposure_free(struct exposure *e)
{
	free(e->kr);
	free(e->irel);
	free(e->k1);
	free(e->k2);
	free(e->k3);
	free(e->k4);
	free(e->tmp);
}

void exposure_intensity(struct exposure *e, const double *M, double *irel)
{
	int n = e->tf.nz;
	double dz = e->tf.dz;
	if (!e->standing) {
		/* Beer-Lambert, trapezoidal optical depth: the same sublayer
		 * absorption the thin-film solver sees, without reflections */
		irel[0] = 1;
		double tau = 0;
		for (int j = 0; j + 1 < n; j++) {
			double alpha = e->A * 0.5 * (M[j] + M[j + 1]) + e->B;
			tau += alpha * dz;
			irel[j + 1] = exp(-tau);
		}
		return;
	}
	/* extinction k = alpha lambda / (4 pi) of each sublayer */
	double f = e->tf.lambda / (4 * M_PI);
	for (int j = 0; j + 1 < n; j++)
		e->kr[j] = (e->A * 0.5 * (M[j] + M[j + 1]) + e->B) * f;
	thinfilm_intensity(&e->tf, e->kr, irel);
}

void exposure_rhs(struct exposure *e, const double *M, double *dM)
{
	exposure_intensity(e, M, e->irel);
	for (int j = 0; j < e->tf.nz; j++)
		dM[j] = -e->C * e->irel[j] * M[j];
}

/* One RK4 step of size h from M (in place); k1 = f(M) on entry. */
static void rk4(struct exposure *e, double *M, double h)
{
	int n = e->tf.nz;
	double *t = e->tmp;
	for (int j = 0; j < n; j++)
		t[j] = M[j] + 0.5 * h * e->k1[j];
	exposure_rhs(e, t, e->k2);
	for (int j = 0; j < n; j++)
		t[j] = M[j] + 0.5 * h * e->k2[j];
	exposure_rhs(e, t, e->k3);
	for (int j = 0; j < n; j++)
		t[j] = M[j] + h * e->k3[j];
	exposure_rhs(e, t, e->k4);
	for (int j = 0; j < n; j++)
		M[j] += h / 6 * (e->k1[j] + 2 * e->k2[j] + 2 * e->k3[j] + e->k4[j]);
}

void exposure_column(struct exposure *e, double D, double *M)
{
	int n = e->tf.nz;
	for (int j = 0; j < n; j++)
		M[j] = 1;
	if (!(D > 0))
		return;
	double steps = ceil(D / e->h * (1 - 1e-12));
	if (steps < 1)
		steps = 1;
	double h = D / steps;
	for (long s = 0; s < (long)steps; s++) {
		exposure_rhs(e, M, e->k1);
		rk4(e, M, h);
	}
}

struct dose_table *dose_table_build(struct exposure *e, double dmax)
{
	struct dose_table *t = xcalloc(1, sizeof *t);
	int n = e->tf.nz;
	t->nz = n;
	t->h = e->h;
	double nd = dmax > 0 ? ceil(dmax / e->h * (1 - 1e-12)) : 0;
	/* exposure_init bounded the steps; checked all the same */
	t->nd = ck_int(nd, 0, (int)EXPOSE_MAX_STEPS, "exposure steps");
	size_t rows = (size_t)t->nd + 1;
	t->M = xreallocarray(NULL, rows * (size_t)n, sizeof *t->M);
	t->dM = xreallocarray(NULL, rows * (size_t)n, sizeof *t->dM);
	double *M = t->M;
	for (int j = 0; j < n; j++)
		M[j] = 1;
	for (int r = 0;; r++) {
		double *row = t->M + (size_t)r * n;
		exposure_rhs(e, row, e->k1);
		memcpy(t->dM + (size_t)r * n, e->k1, (size_t)n * sizeof *e->k1);
		if (r == t->nd)
			break;
		double *next = row + n;
		memcpy(next, row, (size_t)n * sizeof *row);
		rk4(e, next, t->h);
	}
	return t;
}

void dose_table_eval(const struct dose_table *t, double D, double *out)
{
	int n = t->nz;
	double u = D / t->h;
	if (!(u > 0))
		u = 0;
	if (u > t->nd)
		u = t->nd;
	int r = (int)u;
	if (r >= t->nd) {
		memcpy(out, t->M + (size_t)t->nd * n, (size_t)n * sizeof *out);
		return;
	}
	double s = u - r;
	/* cubic Hermite basis on [0, 1], derivatives scaled by h */
	double s2 = s * s, s3 = s2 * s;
	double h00 = 2 * s3 - 3 * s2 + 1, h10 = (s3 - 2 * s2 + s) * t->h;
	double h01 = -2 * s3 + 3 * s2, h11 = (s3 - s2) * t->h;
	const double *m0 = t->M + (size_t)r * n, *m1 = m0 + n;
	const double *d0 = t->dM + (size_t)r * n, *d1 = d0 + n;
	for (int j = 0; j < n; j++)
		out[j] = h00 * m0[j] + h10 * d0[j] + h01 * m1[j] + h11 * d1[j];
}

double dose_table_node(const struct dose_table *t, double D, int j)
{
	int n = t->nz;
	double u = D / t->h;
	if (!(u > 0))
		u = 0;
	if (u > t->nd)
		u = t->nd;
	int r = (int)u;
	if (r >= t->nd)
		return t->M[(size_t)t->nd * n + j];
	double s = u - r;
	double s2 = s * s, s3 = s2 * s;
	double h00 = 2 * s3 - 3 * s2 + 1, h10 = (s3 - 2 * s2 + s) * t->h;
	double h01 = -2 * s3 + 3 * s2, h11 = (s3 - s2) * t->h;
	size_t at = (size_t)r * n + j;
	return h00 * t->M[at] + h10 * t->dM[at] + h01 * t->M[at + n] + h11 * t->dM[at + n];
}

void dose_table_free(struct dose_table *t)
{
	if (!t)
		return;
	free(t->M);
	free(t->dM);
	free(t);
}
