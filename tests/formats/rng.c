/*
 * rng.c - the counter-based generator of src/lib/numerics/rng.c against
 * closed forms:
 *   - a stream is a function of (seed, key) alone: the same pair gives the
 *     same words, another key or seed other words;
 *   - uniform draws: mean 1/2 and variance 1/12 within 5 standard errors
 *     over 10^6 draws;
 *   - Poisson at means 0.3, 4, 9.9 (inversion) and 10, 37.5, 1e4 (PTRS):
 *     sample mean within 5 standard errors sqrt(mean / N) of the mean,
 *     sample variance within 5 standard errors of the mean (variance =
 *     mean), and a chi-square of the histogram against the Poisson
 *     probabilities (bins of expected count 20 or more, the tails lumped)
 *     below its 1 - 1e-6 quantile;
 *   - binomial at (n, p) = (1, 0.3), (7, 0.5), (40, 0.1), (100, 0.37),
 *     (5000, 0.9): the same checks against n p and n p (1 - p);
 *   - ln k! against lgamma (1e-12 relative, k to 10^6).
 * 5 standard errors: a correct generator fails one such check in ~10^6
 * (the draws are fixed by the seed, so the test is reproducible).
 */
#include "rng.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int nfail;

static void check(int ok, const char *fmt, double a, double b)
{
	if (!ok) {
		printf("FAIL ");
		printf(fmt, a, b);
		printf("\n");
		nfail++;
	}
}

enum { NDRAW = 200000 };

/* Mean, variance and chi-square of draws against pmf (k = 0..kmax). */
static void distribution(const char *what, const long *x, double mean, double var,
			 const double *pmf, int kmax)
{
	double s = 0, s2 = 0;
	for (int i = 0; i < NDRAW; i++)
		s += (double)x[i];
	double m = s / NDRAW;
	for (int i = 0; i < NDRAW; i++)
		s2 += ((double)x[i] - m) * ((double)x[i] - m);
	double v = s2 / (NDRAW - 1);
	check(fabs(m - mean) <= 5 * sqrt(var / NDRAW), "%g: sample mean off by %g", mean, m - mean);
	/* the variance of a sample variance is about (mu4 - var^2) / N;
	 * mu4 <= 3 var^2 + var for these laws */
	double sev = sqrt((2 * var * var + var) / NDRAW);
	check(fabs(v - var) <= 5 * sev, "%g: sample variance off by %g", var, v - var);
	/* histogram, bins of expected count >= 20 from the mode out; the
	 * rest lumped into the two tails */
	long *cnt = calloc((size_t)kmax + 2, sizeof *cnt);
	for (int i = 0; i < NDRAW; i++)
		cnt[x[i] > kmax ? kmax + 1 : x[i] < 0 ? kmax + 1 : x[i]]++;
	double chi = 0, o = 0, e = 0, etot = 0;
	int df = -1;
	for (int k = 0; k <= kmax; k++) {
		o += (double)cnt[k];
		e += pmf[k] * NDRAW;
		if (e >= 20) {
			chi += (o - e) * (o - e) / e;
			etot += e;
			df++;
			o = e = 0;
		}
	}
	o += (double)cnt[kmax + 1];
	e = NDRAW - etot;
	if (e >= 1) {
		chi += (o - e) * (o - e) / e;
		df++;
	}
	/* the chi-square's 1 - 1e-6 quantile (Wilson-Hilferty, z = 4.75) */
	double w = 2.0 / (9 * df), lim = df * pow(1 - w + 4.75 * sqrt(w), 3);
	check(df >= 1 && chi <= lim, "chi-square %g on %g degrees of freedom", chi, (double)df);
	printf("%s: mean %.6g (%.6g), variance %.6g (%.6g), chi-square %.1f on %d\n", what, m,
	       mean, v, var, chi, df);
	free(cnt);
}

static void poisson(double mean)
{
	struct rng r;
	long *x = malloc(NDRAW * sizeof *x);
	for (int i = 0; i < NDRAW; i++) {
		rng_init(&r, 11, (uint64_t)i);
		x[i] = rng_poisson(&r, mean);
	}
	int kmax = (int)(mean + 12 * sqrt(mean) + 20);
	double *pmf = malloc(((size_t)kmax + 1) * sizeof *pmf);
	for (int k = 0; k <= kmax; k++)
		pmf[k] = exp(-mean + k * log(mean) - lgamma(k + 1.0));
	char what[64];
	snprintf(what, sizeof what, "poisson %g", mean);
	distribution(what, x, mean, mean, pmf, kmax);
	free(pmf);
	free(x);
}

static void binomial(long n, double p)
{
	struct rng r;
	rng_init(&r, 5, 3);
	long *x = malloc(NDRAW * sizeof *x);
	for (int i = 0; i < NDRAW; i++)
		x[i] = rng_binomial(&r, n, p);      /* one stream, consecutive draws */
	double *pmf = malloc(((size_t)n + 1) * sizeof *pmf);
	for (long k = 0; k <= n; k++)
		pmf[k] = exp(lgamma(n + 1.0) - lgamma(k + 1.0) - lgamma(n - k + 1.0) +
			     k * log(p) + (n - k) * log1p(-p));
	char what[64];
	snprintf(what, sizeof what, "binomial %ld %g", n, p);
	distribution(what, x, n * p, n * p * (1 - p), pmf, (int)n);
	free(pmf);
	free(x);
}

int main(void)
{
	struct rng a, b;
	rng_init(&a, 7, 42);
	rng_init(&b, 7, 42);
	int same = 1;
	for (int i = 0; i < 100; i++)
		same &= rng_u64(&a) == rng_u64(&b);
	check(same, "same seed and key: streams differ%g%g", 0, 0);
	rng_init(&a, 7, 42);
	rng_init(&b, 7, 43);
	check(rng_u64(&a) != rng_u64(&b), "keys 42 and 43 give the same word%g%g", 0, 0);
	rng_init(&a, 7, 42);
	rng_init(&b, 8, 42);
	check(rng_u64(&a) != rng_u64(&b), "seeds 7 and 8 give the same word%g%g", 0, 0);

	enum { NU = 1000000 };
	double s = 0, s2 = 0;
	rng_init(&a, 1, 0);
	for (int i = 0; i < NU; i++) {
		double u = rng_uniform(&a);
		check(u >= 0 && u < 1, "uniform %g outside [0, 1)%g", u, 0);
		s += u;
		s2 += (u - 0.5) * (u - 0.5);
	}
	check(fabs(s / NU - 0.5) <= 5 * sqrt(1.0 / 12 / NU), "uniform mean %g, expected %g",
	      s / NU, 0.5);
	check(fabs(s2 / NU - 1.0 / 12) <= 5 * sqrt(1.0 / 180 / NU),
	      "uniform variance %g, expected %g", s2 / NU, 1.0 / 12);

	double means[] = {0.3, 4, 9.9, 10, 37.5, 1e4};
	for (size_t i = 0; i < sizeof means / sizeof *means; i++)
		poisson(means[i]);
	binomial(1, 0.3);
	binomial(7, 0.5);
	binomial(40, 0.1);
	binomial(100, 0.37);
	binomial(5000, 0.9);

	double worst = 0;
	for (long k = 0; k <= 1000000; k = k < 40 ? k + 1 : k * 3 / 2) {
		double ref = lgamma(k + 1.0), e = fabs(rng_log_factorial(k) - ref);
		if (ref > 1)
			e /= ref;
		if (e > worst)
			worst = e;
	}
	check(worst <= 1e-12, "ln k! off by %g relative (tolerance %g)", worst, 1e-12);
	if (nfail)
		printf("%d checks failed\n", nfail);
	return nfail != 0;
}
