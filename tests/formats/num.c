/*
 * num.c - num_fmt/num_put (src/lib/num.c, the fast printer) against num_fmt_ref
 * (printf %.15g, strtod, printf %.17g: the definition of the output),
 * byte for byte, over:
 *  1. edge cases: 0, -0, 1, powers of two and ten and their neighbours,
 *     DBL_MAX, DBL_MIN, the subnormals, infinities and NaN, integers up to
 *     and beyond 2^53, decimal fractions k/10^n;
 *  2. halfway cases: doubles whose exact value has exactly 16 or 18
 *     significant digits ending in 5 (ties of the 15- and 17-digit
 *     roundings), and significands with few bits set;
 *  3. a million doubles with uniformly random bits (every exponent) and
 *     500 000 random doubles in [-1e3, 1e3] (the coordinates the programs
 *     print), each with its neighbours one ulp away.
 * Any difference fails, with the value printed.  (About a second of CPU.)
 */
#include "num.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static long nfail, nchecked;

static void check(double v)
{
	char a[NUM_BUFSZ], b[NUM_BUFSZ];
	char *end = num_put(a, v);
	num_fmt_ref(b, v);
	nchecked++;
	if (end != a + strlen(a) && nfail++ < 20)
		fprintf(stderr, "num: %a: num_put returned the wrong end\n", v);
	if (strcmp(a, b) != 0 && nfail++ < 20) {
		uint64_t u;
		memcpy(&u, &v, 8);
		fprintf(stderr, "num: %a (0x%016llx): num_fmt \"%s\", reference \"%s\"\n",
			v, (unsigned long long)u, a, b);
	}
}

static void check_near(double v)
{
	check(v);
	check(-v);
	check(nextafter(v, INFINITY));
	check(nextafter(v, -INFINITY));
}

static uint64_t state = 0x853c49e6748fea9bu;
static uint64_t next(void) /* splitmix64 */
{
	uint64_t z = (state += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

static double from_bits(uint64_t u)
{
	double d;
	memcpy(&d, &u, 8);
	return d;
}

int main(void)
{
	/* 1. edge cases */
	check(0.0);
	check(-0.0);
	check(INFINITY);
	check(-INFINITY);
	check(NAN);
	check_near(DBL_MAX);
	check_near(DBL_MIN);
	check_near(DBL_TRUE_MIN);
	for (int e = -1074; e <= 1023; e++)
		check_near(ldexp(1.0, e));
	for (int e = -323; e <= 308; e++) {
		char s[32];
		snprintf(s, sizeof s, "1e%d", e);
		check_near(strtod(s, NULL));
		snprintf(s, sizeof s, "9.999999999999999e%d", e);
		check_near(strtod(s, NULL));
		snprintf(s, sizeof s, "5e%d", e);
		check_near(strtod(s, NULL));
	}
	for (uint64_t u = 1; u < 100000; u++)
		check(from_bits(u)); /* the smallest subnormals */
	for (int i = 0; i < 20000; i++)
		check(from_bits(next() & 0x000fffffffffffffu)); /* subnormals */
	for (double x = 0; x < 20000; x++)
		check_near(x);
	for (int b = 50; b <= 70; b++)
		for (int i = -300; i <= 300; i++)
			check_near(ldexp(1.0, b) + i);
	for (int n = 1; n <= 22; n++)
		for (int k = 1; k < 2000; k++)
			check_near(k / pow(10, n));

	/* 2. halfway cases: m * 2^e whose decimal expansion ends in 5 at the
	 * 16th or 18th significant digit; m odd and 5^-e-scaled */
	for (int e = -80; e <= -1; e++)
		for (int i = 0; i < 400; i++) {
			uint64_t m = (next() >> (11 + (unsigned)(next() % 40))) | 1;
			check_near(ldexp((double)m, e));
		}
	for (int i = 0; i < 100000; i++) {
		/* few significant bits: short decimal expansions */
		uint64_t m = next() >> (64 - 1 - (int)(next() % 20));
		int e = (int)(next() % 200) - 100;
		check(ldexp((double)(m | 1), e));
	}

	/* 3. random doubles */
	for (int i = 0; i < 1000000; i++) {
		double v = from_bits(next());
		if (isfinite(v))
			check(v);
	}
	for (int i = 0; i < 500000; i++) {
		double v = ((double)(next() >> 11) / 9007199254740992.0 - 0.5) * 2000;
		check(v);
	}
	if (nfail) {
		fprintf(stderr, "num: %ld of %ld values differ\n", nfail, nchecked);
		return 1;
	}
	return 0;
}
