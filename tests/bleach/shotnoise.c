/*
 * shotnoise.c - the shot noise of bleach's stochastic statement
 * (src/bleach/shotnoise.c) on a test field: 101 x 101 nodes (a period of
 * 100 x 100 voxels) by 6 planes, plane k at the deterministic photoacid
 * 1 - M_k with -ln M_k = 0.05, 0.2, 0.5, 1, 2, 4.  Checked against closed
 * forms, each plane of 10^4 voxels on its own:
 *   - absorbed photons (photon noise alone, n = G0 dx dy dz = 16 PAG a
 *     voxel): Poisson of mean n (-ln M) - the sample mean within 5
 *     standard errors, the sample variance within 5 standard errors of the
 *     mean (variance = mean), the chi-square of the histogram against the
 *     Poisson probabilities below its 1 - 1e-6 quantile;
 *   - the acid is unbiased: its sample mean within 5 standard errors of
 *     1 - M for photon noise alone, acid noise alone and both, at n = 16
 *     and at n = 0.3 (a voxel of fewer than one PAG: the count is drawn);
 *   - the PAG count has mean n; the quencher (counts over n) has mean q0
 *     and variance q0 / n (Poisson), within 5 standard errors;
 *   - the same seed gives the same bytes at 1, 2 and 3 threads; another
 *     seed differs; the last x node and y row repeat the first (the
 *     periodic window).
 */
#include "bleach.h"
#include "par.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int nfail;

#define FAILF(...) do { printf("FAIL "); printf(__VA_ARGS__); printf("\n"); nfail++; } while (0)

enum { NX = 101, NY = 101, NZ = 6, PX = NX - 1, PY = NY - 1, NP = NX * NY * NZ };
static const double LNM[NZ] = {0.05, 0.2, 0.5, 1, 2, 4};
/* voxel side 2 nm: 8 nm^3 */
static const double DXY = 0.002;

static void field(double *h)
{
	for (int k = 0; k < NZ; k++)
		for (int q = 0; q < NX * NY; q++)
			h[k * NX * NY + q] = -expm1(-LNM[k]);
}

struct stats {
	double mean, var;
	int n;
};

/* Mean and variance of plane k of v (the period only). */
static struct stats plane(const double *v, const long *c, int k)
{
	double s = 0, s2 = 0;
	int n = 0;
	for (int j = 0; j < PY; j++)
		for (int i = 0; i < PX; i++) {
			size_t at = ((size_t)k * NY + j) * NX + i;
			s += v ? v[at] : (double)c[at];
			n++;
		}
	double m = s / n;
	for (int j = 0; j < PY; j++)
		for (int i = 0; i < PX; i++) {
			size_t at = ((size_t)k * NY + j) * NX + i;
			double d = (v ? v[at] : (double)c[at]) - m;
			s2 += d * d;
		}
	return (struct stats){m, s2 / (n - 1), n};
}

static void input(struct bleach_input *in, double g0, int photons, int acid, long seed)
{
	memset(in, 0, sizeof *in);
	in->wavelength = 0.0135;
	in->B = 4.5;
	in->C = 0.03;
	in->q0 = 0.2;
	in->pag = g0;
	in->stochastic = 1;
	in->seed = seed;
	in->noise_photons = photons;
	in->noise_acid = acid;
}

/* Photons alone at n = 16: Poisson of mean n (-ln M). */
static void photons(void)
{
	struct bleach_input in;
	input(&in, 2, 1, 0, 3);
	double *h = malloc(NP * sizeof *h);
	long *c = calloc(4 * (size_t)NP, sizeof *c);
	struct shotnoise_info si = {0, 0, 0, 0, c, c + NP, c + 2 * NP, c + 3 * NP};
	field(h);
	double *q = shotnoise_apply(&in, h, NX, NY, NZ, DXY, DXY, DXY, &si);
	if (q)
		FAILF("a quencher field without acid noise");
	if (fabs(si.npag - 16) > 1e-9)
		FAILF("n = %g PAG a voxel, expected 16", si.npag);
	for (int k = 0; k < NZ; k++) {
		double mu = 16 * LNM[k];
		struct stats s = plane(NULL, si.photons, k);
		if (!(fabs(s.mean - mu) <= 5 * sqrt(mu / s.n)))
			FAILF("plane %d: photons mean %g, expected %g", k, s.mean, mu);
		/* the sample variance of a Poisson sample: variance (mu + 2 mu^2) / n */
		if (!(fabs(s.var - mu) <= 5 * sqrt((mu + 2 * mu * mu) / s.n)))
			FAILF("plane %d: photons variance %g, expected %g", k, s.var, mu);
		/* chi-square against the Poisson probabilities, bins of 20+ */
		int kmax = (int)(mu + 12 * sqrt(mu) + 20);
		long *cnt = calloc((size_t)kmax + 2, sizeof *cnt);
		for (int j = 0; j < PY; j++)
			for (int i = 0; i < PX; i++) {
				long v = si.photons[((size_t)k * NY + j) * NX + i];
				cnt[v > kmax ? kmax + 1 : v]++;
			}
		double chi = 0, o = 0, e = 0, et = 0;
		int df = -1;
		for (int m = 0; m <= kmax; m++) {
			o += (double)cnt[m];
			e += exp(-mu + m * log(mu) - lgamma(m + 1.0)) * s.n;
			if (e >= 20) {
				chi += (o - e) * (o - e) / e;
				et += e;
				df++;
				o = e = 0;
			}
		}
		o += (double)cnt[kmax + 1];
		e = s.n - et;
		if (e >= 1) {
			chi += (o - e) * (o - e) / e;
			df++;
		}
		double w = 2.0 / (9 * df), lim = df * pow(1 - w + 4.75 * sqrt(w), 3);
		if (!(df >= 1 && chi <= lim))
			FAILF("plane %d: photons chi-square %g on %d, above %g", k, chi, df, lim);
		printf("photons at mean %g: mean %.5g variance %.5g chi-square %.1f on %d\n", mu,
		       s.mean, s.var, chi, df);
		free(cnt);
	}
	free(h);
	free(c);
}

/* The acid's mean is 1 - M in every mode; PAG and quencher counts. */
static void unbiased(double g0, int ph, int ac)
{
	struct bleach_input in;
	input(&in, g0, ph, ac, 5);
	double *h = malloc(NP * sizeof *h);
	long *c = calloc(4 * (size_t)NP, sizeof *c);
	struct shotnoise_info si = {0, 0, 0, 0, c, c + NP, c + 2 * NP, c + 3 * NP};
	field(h);
	double *q = shotnoise_apply(&in, h, NX, NY, NZ, DXY, DXY, DXY, &si);
	double n = si.npag;
	for (int k = 0; k < NZ; k++) {
		double want = -expm1(-LNM[k]);
		struct stats s = plane(h, NULL, k);
		if (!(fabs(s.mean - want) <= 5 * sqrt(s.var / s.n)))
			FAILF("n %g photons %d acid %d, plane %d: acid mean %g, expected %g (se %g)",
			      n, ph, ac, k, s.mean, want, sqrt(s.var / s.n));
		if (!ac)
			continue;
		struct stats p = plane(NULL, si.pag, k);
		double fr = n - floor(n);
		if (!(fabs(p.mean - n) <= 5 * sqrt(fr * (1 - fr) / p.n) + 1e-12))
			FAILF("plane %d: PAG mean %g, expected %g", k, p.mean, n);
		struct stats sq = plane(q, NULL, k);
		double vq = in.q0 / n;
		if (!(fabs(sq.mean - in.q0) <= 5 * sqrt(vq / sq.n)))
			FAILF("plane %d: quencher mean %g, expected %g", k, sq.mean, in.q0);
		double mu = in.q0 * n;      /* the count's Poisson mean */
		if (!(fabs(sq.var - vq) <= 5 * sqrt((mu + 2 * mu * mu) / sq.n) / (n * n)))
			FAILF("plane %d: quencher variance %g, expected %g", k, sq.var, vq);
	}
	printf("n %g, photons %s, acid %s: acid means within 5 standard errors of 1 - M\n", n,
	       ph ? "on" : "off", ac ? "on" : "off");
	free(q);
	free(h);
	free(c);
}

static void determinism(void)
{
	struct bleach_input in;
	input(&in, 0.3, 1, 1, 77);
	double *ref = NULL, *refq = NULL;
	for (int t = 1; t <= 3; t++) {
		par_set_threads(t);
		double *h = malloc(NP * sizeof *h);
		field(h);
		double *q = shotnoise_apply(&in, h, NX, NY, NZ, DXY, DXY, DXY, NULL);
		if (!ref) {
			ref = h;
			refq = q;
			continue;
		}
		if (memcmp(h, ref, NP * sizeof *h) || memcmp(q, refq, NP * sizeof *q))
			FAILF("%d threads: not the bytes of 1 thread", t);
		free(h);
		free(q);
	}
	for (int k = 0; k < NZ; k++)
		for (int j = 0; j < NY; j++)
			for (int i = 0; i < NX; i++) {
				size_t at = ((size_t)k * NY + j) * NX + i;
				size_t src = ((size_t)k * NY + j % PY) * NX + i % PX;
				if (ref[at] != ref[src] || refq[at] != refq[src]) {
					FAILF("node %d %d %d does not repeat %d %d", i, j, k, i % PX, j % PY);
					k = NZ;
					j = NY;
					break;
				}
			}
	in.seed = 78;
	double *h = malloc(NP * sizeof *h);
	field(h);
	double *q = shotnoise_apply(&in, h, NX, NY, NZ, DXY, DXY, DXY, NULL);
	if (!memcmp(h, ref, NP * sizeof *h))
		FAILF("seeds 77 and 78 give the same acid");
	free(h);
	free(q);
	free(ref);
	free(refq);
	par_set_threads(0);
}

int main(void)
{
	photons();
	for (int g = 0; g < 2; g++) {
		double g0 = g == 0 ? 2 : 0.3 / 8;   /* n = 16 and n = 0.3 */
		unbiased(g0, 1, 0);
		unbiased(g0, 0, 1);
		unbiased(g0, 1, 1);
	}
	determinism();
	if (nfail)
		printf("%d checks failed\n", nfail);
	return nfail != 0;
}
