/*
 * peb_extrap.c - the extrapolated bake (peb_choose_extrapolated and
 * peb_extrapolate, src/bleach/peb_steps.c) on an x-z slice of a 0.6 um
 * line image (61 x 101 nodes, 0.4 um thick, standing waves in z) in
 * examples/car-krf-lines' resist (order 1, quencher 0.15, quenching 10/s,
 * loss 0.001/s, 30 nm acid diffusion length in 60 s), against the same
 * bake in 512 steps (the converged m: the scheme is second order, and
 * the error at 32 steps is below 1e-3, so at 512 below 1e-5):
 *   - peb_extrapolate: (4 fine - coarse) / 3, clamped to [0, 1]
 *     (exact to rounding, 1e-15);
 *   - m from 16 and 32 steps extrapolated is within PEB_TOL = 1e-3 of the
 *     converged m, and at least 3 times closer than m from 32 steps alone
 *     (so that the extrapolation is what brings it there; 32 steps alone
 *     err by about 1e-3 here);
 *   - peb_choose_extrapolated from 64 steps (x-y at every step) picks the
 *     pair (16, 32) with its x-y counts, its estimate below PEB_TOL and
 *     within a factor 4 of the real error of the pair;
 *   - from 32 steps it picks the pair (8, 16) if and only if that pair
 *     is within PEB_TOL of the converged m (here it is not);
 *   - from a bake whose x-y splitting cannot refine with the steps (one
 *     x-y step) it picks nothing.
 */
#include "bleach.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

static void check(const char *what, double err, double tol)
{
	if (!(err <= tol)) {
		printf("FAIL %s: %.3g above %.3g\n", what, err, tol);
		failures++;
	} else {
		printf("ok %s: %.3g (at most %.3g)\n", what, err, tol);
	}
}

enum { NX = 61, NZ = 101 };
static const double LX = 0.6, THICK = 0.4;

static void initial(double *f)
{
	for (int k = 0; k < NZ; k++)
		for (int i = 0; i < NX; i++) {
			double x = LX * i / (NX - 1), z = THICK * k / (NZ - 1);
			double img = 0.5 + 0.45 * cos(2 * M_PI * x / LX);
			double sw = 1 + 0.3 * cos(4 * M_PI * 1.76 * z / 0.248);
			f[(size_t)k * NX + i] = 1 - exp(-0.9 * img * sw);
		}
}

static void bake(const struct peb_params *pp, double *f, int n, int nouter)
{
	initial(f);
	peb_run(pp, f, NX, 1, NZ, LX / (NX - 1), 1, THICK / (NZ - 1), nouter, n / nouter, NULL);
}

static double maxdiff(const double *a, const double *b, size_t n)
{
	double e = 0;
	for (size_t k = 0; k < n; k++)
		if (fabs(a[k] - b[k]) > e)
			e = fabs(a[k] - b[k]);
	return e;
}

/* peb_choose_extrapolated from n steps, n in x-y, on the slice */
static int choose(const struct peb_params *pp, int n, int nouter, int counts[4], double *est)
{
	double *h0 = malloc((size_t)NX * NZ * sizeof *h0);
	initial(h0);
	int nf = peb_choose_extrapolated(pp, h0, NX, 1, NZ, LX / (NX - 1), 1, THICK / (NZ - 1), n,
					 nouter, counts, est);
	free(h0);
	return nf;
}

int main(void)
{
	check("extrapolate (0.2, 0.5) = 0.6", fabs(peb_extrapolate(0.2, 0.5) - 0.6), 1e-15);
	check("extrapolate (0.3, 0.05) clamped to 0", fabs(peb_extrapolate(0.3, 0.05)), 0);
	check("extrapolate (0.8, 0.99) clamped to 1", fabs(peb_extrapolate(0.8, 0.99) - 1), 0);

	struct peb_params pp;
	memset(&pp, 0, sizeof pp);
	pp.q0 = 0.15;
	pp.kamp = 0.4;
	pp.p = 1;
	pp.kloss = 0.001;
	pp.kq = 10;
	pp.t = 60;
	pp.dh = 7.5e-6;
	pp.dq = 1e-6;
	size_t np = (size_t)NX * NZ;
	double *ref = malloc(np * sizeof *ref), *c = malloc(np * sizeof *c);
	double *f = malloc(np * sizeof *f);
	bake(&pp, ref, 512, 512);
	/* 32 steps err by about 1e-3 here: the count peb_choose_steps takes
	 * is 64, the pair below it (16, 32) */
	bake(&pp, c, 16, 16);
	bake(&pp, f, 32, 32);
	double e32 = maxdiff(f, ref, np);
	for (size_t k = 0; k < np; k++)
		f[k] = peb_extrapolate(c[k], f[k]);
	double ex = maxdiff(f, ref, np);
	check("m from 16 and 32 steps extrapolated, against 512 steps", ex, PEB_TOL);
	check("the same over m from 32 steps alone", ex / e32, 1.0 / 3);
	int counts[4] = {0};
	double est = -1;
	int nf = choose(&pp, 64, 64, counts, &est);
	int right = nf == 32 && counts[0] == 32 && counts[1] == 32 && counts[2] == 16 &&
		    counts[3] == 16;
	printf("%s chosen from 64 steps: %d, counts %d %d %d %d\n", right ? "ok" : "FAIL", nf,
	       counts[0], counts[1], counts[2], counts[3]);
	failures += !right;
	if (right) {
		check("its estimate", est, PEB_TOL);
		check("its estimate against the real error, ratio", fmax(est / ex, ex / est), 4);
	}
	/* the pair (8, 16) errs by more than PEB_TOL: not chosen from 32 */
	bake(&pp, c, 8, 8);
	bake(&pp, f, 16, 16);
	for (size_t k = 0; k < np; k++)
		f[k] = peb_extrapolate(c[k], f[k]);
	double ex8 = maxdiff(f, ref, np);
	nf = choose(&pp, 32, 32, counts, &est);
	printf("%s from 32 steps: %d chosen; the pair (8, 16) errs by %.3g\n",
	       (nf == 0) == (ex8 > PEB_TOL) ? "ok" : "FAIL", nf, ex8);
	failures += (nf == 0) != (ex8 > PEB_TOL);
	nf = choose(&pp, 64, 1, counts, &est);
	printf("%s nothing chosen with one x-y step: %d\n", nf == 0 ? "ok" : "FAIL", nf);
	failures += nf != 0;
	free(ref);
	free(c);
	free(f);
	return failures ? 1 : 0;
}
