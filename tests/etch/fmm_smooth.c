/*
 * fmm_smooth.c - the fast-marching engine on smooth rates: does the
 * front keep its place when the rate is curved between rate-grid nodes?
 *
 * Convention.  A rate file samples a smooth field (bleach evaluates the
 * exposure, bake and development rate at the nodes); what the rate is
 * between samples is part of the model (etch(1)).  Taken as linear
 * between nodes the solve is ahead where the rate is convex (the linear
 * interpolant lies above the field) and behind where it is concave, by
 * the cell mean of the interpolation error of 1/R, about h^2 R''/(12 R^2)
 * per cell crossed, which no refinement of the same nodal data removes.
 * The exact answer of the nodal data is taken to be that of the smooth
 * field the nodes sample (to the O(h^3) of reconstructing it from them),
 * so both checks measure against that field, never an interpolant:
 *
 *  1. An off-centre Gaussian exposure focused inside the resist,
 *     R = R0 + R1 exp(-((x-a)^2 + (y-b)^2)/w^2) exp(-((z-z0)/L)^2),
 *     sampled at 0.1 um in x and y and 0.05 um in z (dz), solved plain
 *     and refined 4x per axis, against a solve of the same analytic
 *     field sampled 4 times finer per axis (its own interpolation error
 *     16 times smaller).  Over the nodes of the coarse grid the front
 *     reaches by REACH_T below the top plane, the front position error
 *     (T - Tref) R / dz, positive where the coarse front lies behind:
 *     the signed mean within MEAN_TOL and the 95th percentile (nearest
 *     rank) of its absolute value within P95_TOL.  With the rate linear
 *     between nodes: plain mean -0.085 dz (p95 0.16), refined -0.083
 *     (0.15); with the curvature reconstruction (src/etch/fmm.c) +0.005
 *     (0.018) and +0.002 (0.004).
 *  2. A z-only attenuation R = R0 exp(z/L) sampled at 0.05 um nodes
 *     against the closed form T(z) = L (exp(-z/L) - 1)/R0, the integral
 *     of 1/R of the field itself, plain and refined 4x in z: the largest
 *     depth error (T - Texact) R / dz within ZONLY_TOL (linear between
 *     nodes: 0.0163 dz, both; reconstructed: 0.0016, refined 0.0015).
 *  3. The reconstruction is limited where the rate is not smooth: on a
 *     step in x (1 to 0.1 um/s between two nodes) under standing waves
 *     in z sampled 4 nodes a period, the rates of a solve refined 4x per
 *     axis stay, along every x and z line between each pair of rate-grid
 *     nodes, within the range of the two (no overshoot), to 1e-12.
 */
#include "fmm.h"
#include "fmmcheck.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Tolerances, in dz.  The reference's own error is about 1/16 of the
 * coarse grid's model error; what the reconstruction leaves is the
 * marching's discretisation of the fronts that cross the Gaussian's
 * flanks obliquely at 0.1 um in x-y (0.005 dz measured).  MEAN_TOL is
 * under a fifth of the linear model's 0.085, over twice what is left;
 * P95_TOL a third of its 0.16.  ZONLY_TOL: a third of the linear
 * model's 0.0163, three times what is left. */
#define MEAN_TOL 0.015
#define P95_TOL 0.05
#define ZONLY_TOL 0.005
#define REACH_T 3.0

/* 1: the Gaussian exposure (um, um/s) */
static const double G_R0 = 0.05, G_R1 = 1.0, G_A = 0.83, G_B = 1.07, G_W = 2.0, G_Z0 = -0.5,
		    G_L = 0.3;

static double gauss_rate(double x, double y, double z)
{
	double dx = x - G_A, dy = y - G_B, dz = (z - G_Z0) / G_L;
	return G_R0 + G_R1 * exp(-(dx * dx + dy * dy) / (G_W * G_W)) * exp(-dz * dz);
}

static struct ratefile *sample(int n[3], const double b[6], double (*rate)(double, double, double))
{
	struct ratefile *r = fmt_rate_new(n[0], n[1], n[2], b);
	for (int k = 0; k < n[2]; k++)
		for (int j = 0; j < n[1]; j++)
			for (int i = 0; i < n[0]; i++)
				r->arrays[0].v[fmt_rate_index(r, i, j, k)] =
					rate(fmt_rate_x(r, i), fmt_rate_y(r, j), fmt_rate_z(r, k));
	return r;
}

static int cmp_abs(const void *a, const void *b)
{
	double x = fabs(*(const double *)a), y = fabs(*(const double *)b);
	return x < y ? -1 : x > y;
}

/* The index of rate-grid node (i, j, k) in solve f refined per times. */
static size_t at(const struct fmm *f, int per, int i, int j, int k)
{
	return ((size_t)k * per * (size_t)f->n[1] + (size_t)j * per) * (size_t)f->n[0] +
	       (size_t)i * per;
}

/* The front position error of solve f (refined fper times) against ref
 * (refined rper times), at the nodes of the rate grid r that ref reaches
 * by REACH_T, below the top plane: mean and p95 in units of dz. */
static void front_error(const struct ratefile *r, const struct fmm *f, int fper,
			const struct fmm *ref, int rper, double dz, double *mean, double *p95)
{
	size_t n = (size_t)r->nx * (size_t)r->ny * (size_t)r->nz, m = 0;
	double *e = xreallocarray(NULL, n, sizeof *e), sum = 0;
	for (int k = 0; k + 1 < r->nz; k++)
		for (int j = 0; j < r->ny; j++)
			for (int i = 0; i < r->nx; i++) {
				double tref = ref->t[at(ref, rper, i, j, k)];
				if (!(tref <= REACH_T))
					continue;
				double rate = r->arrays[0].v[fmt_rate_index(r, i, j, k)];
				e[m] = (f->t[at(f, fper, i, j, k)] - tref) * rate / dz;
				sum += e[m++];
			}
	qsort(e, m, sizeof *e, cmp_abs);
	size_t i95 = (size_t)ceil(0.95 * (double)m);
	*mean = m ? sum / (double)m : 0;
	*p95 = m ? fabs(e[(i95 < 1 ? 1 : i95) - 1]) : 0;
	free(e);
}

static void test_gauss(void)
{
	const double b[6] = {0, 2, 0, 2, -1, 0}, dz = 0.05;
	int nc[3] = {21, 21, 21}, nf[3] = {81, 81, 81}, ref[3] = {4, 4, 4};
	struct ratefile *rc = sample(nc, b, gauss_rate), *rf = sample(nf, b, gauss_rate);
	struct fmm *ff = fmm_solve(rf, NULL);
	for (int refined = 0; refined <= 1; refined++) {
		struct fmm *fc = fmm_solve(rc, refined ? ref : NULL);
		double mean, p95;
		front_error(rc, fc, refined ? 4 : 1, ff, 4, dz, &mean, &p95);
		const char *what = refined ? "refined 4x" : "plain";
		printf("gauss: %s against the field sampled 4x finer: mean %+.4f p95 %.4f dz\n", what,
		       mean, p95);
		CHECK(fabs(mean) <= MEAN_TOL && p95 <= P95_TOL,
		      "gauss: %s: mean %+.4f, p95 %.4f dz against the finer-sampled field "
		      "(tolerance %g, %g)", what, mean, p95, MEAN_TOL, P95_TOL);
		fmm_free(fc);
	}
	fmm_free(ff);
	fmt_rate_free(rc);
	fmt_rate_free(rf);
}

/* 2: the z-only exponential */
static const double Z_R0 = 1.0, Z_L = 0.25;

static double z_rate(double x, double y, double z)
{
	(void)x, (void)y;
	return Z_R0 * exp(z / Z_L);
}

/* The largest depth error of f (refined per times in z), in dz, against
 * the closed form. */
static double zonly_error(const struct ratefile *r, const struct fmm *f, int per, double dz)
{
	double worst = 0;
	for (int k = 0; k < r->nz; k++) {
		double z = fmt_rate_z(r, k), exact = Z_L * (exp(-z / Z_L) - 1) / Z_R0;
		size_t q = (size_t)k * per * (size_t)f->n[0] * (size_t)f->n[1];
		worst = fmax(worst, fabs(f->t[q] - exact) * z_rate(0, 0, z) / dz);
	}
	return worst;
}

static void test_zonly(void)
{
	const double b[6] = {0, 0.1, 0, 0.1, -1, 0}, dz = 0.05;
	int n[3] = {3, 3, 21};
	struct ratefile *r = sample(n, b, z_rate);
	int ref[3] = {1, 1, 4};
	struct fmm *f = fmm_solve(r, NULL), *fr = fmm_solve(r, ref);
	double e = zonly_error(r, f, 1, dz), er = zonly_error(r, fr, 4, dz);
	printf("z-only: depth error against the closed form %.4f dz, refined z x4 %.4f\n", e, er);
	CHECK(e <= ZONLY_TOL, "z-only: %.4f dz from the closed form (tolerance %g)", e, ZONLY_TOL);
	CHECK(er <= ZONLY_TOL, "z-only refined: %.4f dz from the closed form (tolerance %g)", er,
	      ZONLY_TOL);
	fmm_free(f);
	fmm_free(fr);
	fmt_rate_free(r);
}

/* 3: no overshoot at a step and at coarsely sampled standing waves */
static double step_rate(double x, double y, double z)
{
	(void)y;
	return (x < 0.95 ? 1.0 : 0.1) * (1 + 0.8 * cos(2 * M_PI * z / 0.2 + 0.3));
}

static void test_limited(void)
{
	const double b[6] = {0, 2, 0, 0.2, -1, 0};
	int n[3] = {21, 3, 21}, ref[3] = {4, 4, 4};
	struct ratefile *r = sample(n, b, step_rate);
	struct fmm *f = fmm_solve(r, ref);
	double worst = 0;
	for (int k = 0; k < f->n[2]; k++)
		for (int j = 0; j < f->n[1]; j += 4)
			for (int i = 0; i < f->n[0]; i++) {
				/* along x between rate-grid nodes i0 and i0 + 1 */
				int i0 = i / 4 < r->nx - 1 ? i / 4 : r->nx - 2;
				if (k % 4 == 0) {
					double a = f->rate[at(f, 1, 4 * i0, j, k)];
					double c = f->rate[at(f, 1, 4 * i0 + 4, j, k)];
					double v = f->rate[at(f, 1, i, j, k)];
					worst = fmax(worst, fmax(v - fmax(a, c), fmin(a, c) - v));
				}
				/* along z between rate-grid nodes k0 and k0 + 1 */
				int k0 = k / 4 < r->nz - 1 ? k / 4 : r->nz - 2;
				if (i % 4 == 0) {
					double a = f->rate[at(f, 1, i, j, 4 * k0)];
					double c = f->rate[at(f, 1, i, j, 4 * k0 + 4)];
					double v = f->rate[at(f, 1, i, j, k)];
					worst = fmax(worst, fmax(v - fmax(a, c), fmin(a, c) - v));
				}
			}
	printf("limited: largest overshoot of a refined rate %.3g um/s\n", worst);
	CHECK(worst <= 1e-12, "limited: a refined rate %g um/s outside its nodes' range", worst);
	fmm_free(f);
	fmt_rate_free(r);
}

int main(void)
{
	test_gauss();
	test_zonly();
	test_limited();
	return check_status();
}
