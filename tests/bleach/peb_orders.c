/*
 * peb_orders.c - the bake of src/bleach/peb.c at reaction orders other
 * than 1, where the integral of h^p over a step has closed forms (no
 * quencher; p = 2; equal acid and quencher) or graded Gauss quadrature
 * with closed-form tails:
 *   - one point, no diffusion, the reaction over a 60 s step
 *     (peb_react): the integral of h^p against composite Simpson
 *     (400000 intervals) on the closed form of h (h - q = d constant,
 *     h = d / (1 - (q0/h0) e^{-kq d t}), or h0 / (1 + kq h0 t) when
 *     d = 0) for p = 0.5, 1.5, 2, 3 and acid below, at and above the
 *     quencher, relative 1e-7 (Simpson's own error is below 1e-10; the
 *     tails are cut at 1e-6 of h and err by far less than that);
 *     without quencher the integral is h0^p t (1e-14);
 *   - the clear-field column of a standing-wave exposure (401 z nodes,
 *     0.4 um, 30 nm acid diffusion length), order 2 with and without
 *     quencher and order 1.5 with quencher: m with the step count
 *     peb_choose_steps picks against m with 16 times as many steps (the
 *     converged solution: second order, so 256 times closer), within
 *     PEB_TOL = 1e-3, the accuracy the bake promises.
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
		printf("FAIL %s: error %.3g above %.3g\n", what, err, tol);
		failures++;
	} else {
		printf("ok %s: error %.3g (tolerance %.3g)\n", what, err, tol);
	}
}

static struct peb_params params(double p, double q0)
{
	struct peb_params pp;
	memset(&pp, 0, sizeof pp);
	pp.q0 = q0;
	pp.kamp = 0.2;
	pp.p = p;
	pp.kq = 10;
	pp.t = 60;
	pp.dh = 7.5e-6;
	pp.dq = 1e-6;
	return pp;
}

/* Simpson on the closed-form h of the acid-quencher reaction */
static double simpson(double h0, double q0, double kq, double p, double t)
{
	int n = 400000;
	double d = h0 - q0, r = q0 / h0, c = kq * d, sum = 0;
	for (int s = 0; s <= n; s++) {
		double u = t * s / n;
		double h = d == 0 ? h0 / (1 + kq * h0 * u) : d / (1 - r * exp(-c * u));
		sum += (s == 0 || s == n ? 1 : s % 2 ? 4 : 2) * pow(h, p);
	}
	return sum * t / n / 3;
}

static void one_point(void)
{
	static const double ps[] = {0.5, 1.5, 2, 3};
	static const double h0s[] = {0.05, 0.15, 0.3, 1.0};
	double err = 0, err0 = 0;
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++) {
			struct peb_params pp = params(ps[i], 0.15);
			double h = h0s[j], q = pp.q0;
			double got = peb_react(&pp, pp.t, &h, &q);
			double want = simpson(h0s[j], pp.q0, pp.kq, ps[i], pp.t);
			double e = fabs(got - want) / want;
			if (e > err)
				err = e;
			pp.q0 = 0;
			h = h0s[j];
			q = 0;
			got = peb_react(&pp, pp.t, &h, &q);
			want = pow(h0s[j], ps[i]) * pp.t;
			e = fabs(got - want) / want;
			if (e > err0)
				err0 = e;
		}
	check("integral of h^p with quencher against Simpson", err, 1e-7);
	check("integral of h^p without quencher, h0^p t", err0, 1e-14);
}

#define NZ 401

static double column_error(double p, double q0, int *steps)
{
	struct peb_params pp = params(p, q0);
	double h0[NZ], a[NZ], b[NZ], change;
	/* standing waves over 0.4 um, period 0.07 um, absorbed with depth */
	for (int k = 0; k < NZ; k++) {
		double z = 0.4 * k / (NZ - 1);
		double I = (1 + 0.8 * cos(2 * M_PI * z / 0.07)) * exp(-1.5 * z);
		h0[k] = 1 - exp(-0.6 * I);
	}
	double dz = 0.4 / (NZ - 1);
	int n = peb_choose_steps(&pp, h0, 1, NZ, dz, &change);
	memcpy(a, h0, sizeof a);
	memcpy(b, h0, sizeof b);
	peb_columns(&pp, a, 1, NZ, dz, n);
	peb_columns(&pp, b, 1, NZ, dz, 16 * n);
	double e = 0;
	for (int k = 0; k < NZ; k++)
		if (fabs(a[k] - b[k]) > e)
			e = fabs(a[k] - b[k]);
	*steps = n;
	return e;
}

int main(void)
{
	one_point();
	static const double cases[][2] = {{2, 0}, {2, 0.15}, {1.5, 0.15}};
	for (int c = 0; c < 3; c++) {
		int n;
		double e = column_error(cases[c][0], cases[c][1], &n);
		char what[120];
		snprintf(what, sizeof what,
			 "clear-field column, order %g, quencher %g: m at %d steps against 16 times as many",
			 cases[c][0], cases[c][1], n);
		check(what, e, PEB_TOL);
	}
	if (failures)
		printf("%d failures\n", failures);
	return failures ? 1 : 0;
}
