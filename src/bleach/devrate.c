/*
 * devrate.c - development rate R(M, depth) in um/s (thesis 2.1, Figure
 * 2.3, Table 9.1, 9.3.2).  Four models:
 *   kim        Kim, Oldham, Neureuther, IEEE TED ED-31 (1984): bulk
 *              R_B = 1 / [(1 - M e^{-R3(1-M)}) / R1 + M e^{-R3(1-M)} / R2]
 *              times the surface retardation
 *              S = 1 - [1 - (R5 (1-M) + R6 M)] e^{-d/R4}
 *   mack       Mack (1987): R = Rmax (a+1)(1-M)^n / (a + (1-M)^n) + Rmin,
 *              a = (n+1)/(n-1) (1-Mth)^n
 *   dill       Dill et al. (1975): R = exp(E1 + E2 M + E3 M^2) nm/s, as
 *              Dill fitted it, returned here in um/s
 *   canegative acid-hardened chemically amplified negative resist
 *              (thesis 9.3.2): acid a = 1 - M after the bake, crosslink
 *              X = 1 - exp(-k(T) t a^m), k(T) = k0 exp(-Ea / kB T),
 *              R = Rmax (1 - X)^p + Rmin
 *   enhanced   Mack's enhanced kinetic model (Mack 1992, as PROLITH
 *              defines it): R = Rresin [1 + kenh (1-M)^n] / [1 + kinh M^l],
 *              kenh = Rmax/Rresin - 1, kinh = Rresin/Rmin - 1, so that
 *              R(0) = Rmax and R(1) = Rmin
 *   notch      the notch model (PROLITH): R = Rmax (1-M)^n (a+1)(1-M)^nn
 *              / (a + (1-M)^nn) + Rmin, a = (nn+1)/(nn-1) (1-Mth_notch)^nn
 * M is clamped to [0, 1] first: the spectral bake and the interpolation
 * over dose may overshoot it by rounding-sized amounts.
 */
#include "bleach.h"

#include <math.h>

void devrate_init(struct devrate *d, const struct bleach_input *in)
{
	d->model = in->model;
	d->npar = in->npar;
	for (int i = 0; i < 6; i++)
		d->par[i] = i < in->npar ? in->par[i] : 0;
	d->kt = 0;
	d->order = 1;
	if (in->model == BLEACH_CANEG) {
		double T = in->temp + 273.15;    /* kelvin */
		d->kt = in->k0 * exp(-in->ea / (BOLTZMANN_EV * T)) * in->time;
		d->order = in->order;
	}
}

double devrate_kim_surface(const double *par, int npar, double M, double depth)
{
	if (npar < 6)
		return 1;
	double rel = par[4] * (1 - M) + par[5] * M;
	return 1 - (1 - rel) * exp(-depth / par[3]);
}

double devrate(const struct devrate *d, double M, double depth)
{
	if (!(M > 0))
		M = 0;
	if (M > 1)
		M = 1;
	const double *r = d->par;
	switch (d->model) {
	case BLEACH_KIM: {
		double e = M * exp(-r[2] * (1 - M));
		double rb = 1 / ((1 - e) / r[0] + e / r[1]);
		return rb * devrate_kim_surface(r, d->npar, M, depth);
	}
	case BLEACH_MACK: {
		double n = r[3];
		double a = (n + 1) / (n - 1) * pow(1 - r[2], n);
		double u = pow(1 - M, n);
		if (!(a + u > 0))
			return r[1];    /* both underflowed: far below threshold */
		return r[0] * (a + 1) * u / (a + u) + r[1];
	}
	case BLEACH_MACKENH: {
		double kenh = r[0] / r[2] - 1, kinh = r[2] / r[1] - 1;
		return r[2] * (1 + kenh * pow(1 - M, r[3])) / (1 + kinh * pow(M, r[4]));
	}
	case BLEACH_NOTCH: {
		double nn = r[4];
		double a = (nn + 1) / (nn - 1) * pow(1 - r[3], nn);
		double u = pow(1 - M, nn);
		if (!(a + u > 0))
			return r[1];    /* both underflowed: far below the notch */
		return r[0] * pow(1 - M, r[2]) * (a + 1) * u / (a + u) + r[1];
	}
	case BLEACH_DILL:
		return 1e-3 * exp(r[0] + r[1] * M + r[2] * M * M);
	case BLEACH_CANEG: {
		double a = 1 - M;
		/* (1 - X)^p = exp(-p k t a^m), without forming X */
		return r[0] * exp(-r[2] * d->kt * pow(a, d->order)) + r[1];
	}
	}
	return 0;
}
