/*
 * rng.h - counter-based random numbers for stochastic models: every
 * stream is a pure function of (seed, key), the key naming the thing drawn
 * for (a voxel's index), so a result does not depend on which thread drew
 * it or in what order: output stays byte-identical at any thread count.
 *
 * The generator is splitmix64 (Steele, Lea and Flood 2014; the finaliser
 * of Stafford's variant 13) started at a hash of seed and key: each draw
 * adds the golden-ratio increment to the state and returns its mix.  A
 * stream holds 2^64 draws; streams of different keys start at unrelated
 * points, and a voxel takes a handful of draws, so they do not overlap in
 * practice.
 *
 * Poisson and binomial variates are exact in distribution: inversion for
 * small means, Hormann's transformed rejection (PTRS, BTRS; Hormann 1993)
 * above.  tests/formats/rng.c checks means, variances and histograms
 * against the closed forms.
 */
#ifndef S3D_RNG_H
#define S3D_RNG_H

#include <stdint.h>

struct rng {
	uint64_t s;
};

/* The stream of key under seed. */
void rng_init(struct rng *r, uint64_t seed, uint64_t key);
uint64_t rng_u64(struct rng *r);
/* Uniform on [0, 1), 53 random bits. */
double rng_uniform(struct rng *r);
/* Poisson with the given mean (0 for a mean that is not positive). */
long rng_poisson(struct rng *r, double mean);
/* Binomial: successes in n trials of probability p (p clamped to [0, 1]). */
long rng_binomial(struct rng *r, long n, double p);
/* ln(k!) to 1e-12 relative, without lgamma's global sign (thread safe). */
double rng_log_factorial(long k);

#endif
