/*
 * rng.c - counter-based splitmix64 and its Poisson and binomial variates
 * (see rng.h).
 */
#include "rng.h"

#include <math.h>

static const uint64_t GOLDEN = 0x9e3779b97f4a7c15u;

/* The splitmix64 finaliser: a bijection of 64-bit words that mixes every
 * input bit into every output bit. */
static uint64_t mix64(uint64_t z)
{
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

void rng_init(struct rng *r, uint64_t seed, uint64_t key)
{
	/* seed and key through the mix in turn: distinct (seed, key) pairs
	 * give unrelated starting states */
	r->s = mix64(mix64(seed ^ 0x243f6a8885a308d3u) ^ mix64(key + GOLDEN));
}

uint64_t rng_u64(struct rng *r)
{
	r->s += GOLDEN;
	return mix64(r->s);
}

double rng_uniform(struct rng *r)
{
	return (double)(rng_u64(r) >> 11) * 0x1.0p-53;
}

/* ln(k!) for k < 16, exact to the last bit (computed with lgamma). */
static const double LOG_FACT[16] = {
	0, 0, 0.69314718055994495, 1.7917594692280554, 3.1780538303479449,
	4.7874917427820467, 6.5792512120101021, 8.5251613610654147, 10.604602902745249,
	12.801827480081467, 15.104412573075514, 17.502307845873887, 19.987214495661885,
	22.552163853123421, 25.191221182738683, 27.89927138384089,
};

double rng_log_factorial(long k)
{
	if (k < 16)
		return k < 0 ? 0 : LOG_FACT[k];
	/* Stirling's series for ln Gamma(x), x = k + 1 >= 17: the first
	 * omitted term, 1 / (1680 x^7), is below 2e-12 */
	double x = (double)k + 1, x2 = x * x;
	return (x - 0.5) * log(x) - x + 0.91893853320467274 +
	       (1.0 / 12 - (1.0 / 360 - 1.0 / (1260 * x2)) / x2) / x;
}

/* Means below this by inversion, above by transformed rejection (PTRS
 * needs a mean of 10 or more). */
#define POISSON_INVERSION 10.0

long rng_poisson(struct rng *r, double mean)
{
	if (!(mean > 0))
		return 0;
	if (mean < POISSON_INVERSION) {
		/* sequential search of the cumulative distribution */
		double u = rng_uniform(r), p = exp(-mean), F = p;
		long k = 0;
		while (u > F && k < 1000) {
			k++;
			p *= mean / k;
			F += p;
			if (p == 0)
				break;  /* rounding left u above the total */
		}
		return k;
	}
	/* PTRS, Hormann (1993), "The transformed rejection method for
	 * generating Poisson random variables" */
	double slam = sqrt(mean), loglam = log(mean);
	double b = 0.931 + 2.53 * slam, a = -0.059 + 0.02483 * b;
	double invalpha = 1.1239 + 1.1328 / (b - 3.4), vr = 0.9277 - 3.6224 / (b - 2);
	for (;;) {
		double U = rng_uniform(r) - 0.5, V = rng_uniform(r);
		double us = 0.5 - fabs(U);
		double kd = floor((2 * a / us + b) * U + mean + 0.43);
		if (us >= 0.07 && V <= vr)
			return (long)kd;
		if (kd < 0 || (us < 0.013 && V > us))
			continue;
		if (log(V) + log(invalpha) - log(a / (us * us) + b) <=
		    -mean + kd * loglam - rng_log_factorial((long)kd))
			return (long)kd;
	}
}

/* n p below this by inversion, above by BTRS (it needs n p >= 10). */
#define BINOMIAL_INVERSION 10.0

/* Binomial for p <= 1/2. */
static long binomial_low(struct rng *r, long n, double p)
{
	double q = 1 - p;
	if ((double)n * p < BINOMIAL_INVERSION) {
		/* inversion: the probabilities by the recurrence
		 * P(k + 1) = P(k) (n - k) p / ((k + 1) q) */
		double u = rng_uniform(r), P = pow(q, (double)n), s = p / q;
		long k = 0;
		while (u > P && k < n) {
			u -= P;
			P *= s * (double)(n - k) / (double)(k + 1);
			k++;
			if (P == 0)
				break;
		}
		return k;
	}
	/* BTRS, Hormann (1993), "The generation of binomial random
	 * variates" */
	double spq = sqrt((double)n * p * q);
	double b = 1.15 + 2.53 * spq, a = -0.0873 + 0.0248 * b + 0.01 * p;
	double c = (double)n * p + 0.5, vr = 0.92 - 4.2 / b;
	double alpha = (2.83 + 5.1 / b) * spq, lpq = log(p / q);
	long m = (long)floor((double)(n + 1) * p);
	double h = rng_log_factorial(m) + rng_log_factorial(n - m);
	for (;;) {
		double U = rng_uniform(r) - 0.5, V = rng_uniform(r);
		double us = 0.5 - fabs(U);
		double kd = floor((2 * a / us + b) * U + c);
		if (kd < 0 || kd > (double)n)
			continue;
		long k = (long)kd;
		if (us >= 0.07 && V <= vr)
			return k;
		V = log(V * alpha / (a / (us * us) + b));
		if (V <= h - rng_log_factorial(k) - rng_log_factorial(n - k) + (double)(k - m) * lpq)
			return k;
	}
}

long rng_binomial(struct rng *r, long n, double p)
{
	if (n <= 0 || !(p > 0))
		return 0;
	if (p >= 1)
		return n;
	return p <= 0.5 ? binomial_low(r, n, p) : n - binomial_low(r, n, 1 - p);
}
