/*
 * num.c - see num.h.
 *
 * The printer.  The output is defined by num_fmt_ref (print %.15g, read it
 * back with strtod, print %.17g if that did not give v back), and num_fmt
 * must match it byte for byte; it only gets there without printf and
 * strtod, in the manner of Ryu and Schubfach (Adams 2018, Giulietti 2020):
 * one multiplication of the binary significand by a 128-bit power of ten
 * (num_pow10.h) gives v * 10^k as a fixed-point number F with 18 or 19
 * integer digits and 64 fraction bits, from which both roundings follow.
 *
 *   - %.15g is F rounded to 15 significant digits (half to even, as glibc
 *     rounds).  It reads back to v exactly when it lies inside v's rounding
 *     interval (half an ulp each side, a quarter below a power of two; the
 *     ends included when the significand is even, as strtod rounds ties to
 *     even).  The interval's half width scaled by 10^k is the same power of
 *     ten times 2^(e-1), so the test is a comparison of two fixed-point
 *     numbers.
 *   - Otherwise %.17g is F rounded to 17 digits.
 *
 * The fixed-point F is below the true v * 10^k by less than 2^-63 (the
 * table's rounding and the dropped bits), so a comparison that falls within
 * a few units of 2^-64 of a decision threshold (an exact or near tie, a
 * decimal on the edge of the interval) is not trusted: those, subnormals,
 * infinities and NaNs go to num_fmt_ref.  That happens for numbers with
 * exactly 18 significant digits ending in 5 and the like; tests/formats/num.c
 * compares the two over millions of doubles.
 */
#include "num.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int num_parse(const char *s, double *out)
{
	char *end;
	if (!*s)
		return 0;
	errno = 0;
	double v = strtod(s, &end);
	if (*end || !isfinite(v))
		return 0;
	/* strtod reports ERANGE for subnormal underflow too; accept those
	 * values but reject overflow (already caught by isfinite) */
	*out = v;
	return 1;
}

int num_parse_count(const char *s, long min, long max, long *out)
{
	double v;
	if (!num_parse(s, &v))
		return 0;
	double r = floor(v);
	if (r != v || v < (double)min || v > (double)max)
		return 0;
	*out = (long)r;
	return 1;
}

char *num_fmt_ref(char *buf, double v)
{
	if (v == 0.0)
		v = 0.0; /* folds -0 into 0 */
	snprintf(buf, NUM_BUFSZ, "%.15g", v);
	if (strtod(buf, NULL) != v)
		snprintf(buf, NUM_BUFSZ, "%.17g", v);
	return buf;
}

#ifdef __SIZEOF_INT128__

#include "num_pow10.h"

typedef unsigned __int128 u128;

static const uint64_t pow10_u64[20] = {
	1u, 10u, 100u, 1000u, 10000u, 100000u, 1000000u, 10000000u, 100000000u,
	1000000000u, 10000000000u, 100000000000u, 1000000000000u,
	10000000000000u, 100000000000000u, 1000000000000000u,
	10000000000000000u, 100000000000000000u, 1000000000000000000u,
	10000000000000000000u
};

/* Margins, in units of 2^-64 of F: F is low by less than 2 units, the
 * interval's half width by less than 2 (table rounding plus the shift). */
enum { TIE_MARGIN = 4, EDGE_MARGIN = 8 };

/* floor(log10(2^e)) for |e| < 1650 (78913 / 2^18 is log10(2) closely
 * enough; num_pow10.py's range and the test check it). */
static int floor_log10_pow2(int e)
{
	return e >= 0 ? (e * 78913) >> 18 : -((-e * 78913 + (1 << 18) - 1) >> 18);
}

static const char digit_pairs[] =
	"00010203040506070809101112131415161718192021222324252627282930313233343536373839"
	"40414243444546474849505152535455565758596061626364656667686970717273747576777879"
	"8081828384858687888990919293949596979899";

/* Writes the n decimal digits of q (leading zeros included) at p. */
static void put_digits(char *p, uint64_t q, int n)
{
	while (n >= 2) {
		unsigned d = (unsigned)(q % 100);
		q /= 100;
		n -= 2;
		memcpy(p + n, digit_pairs + 2 * d, 2);
	}
	if (n)
		p[0] = (char)('0' + q % 10);
}

/* %.Pg of the decimal q * 10^(X - P + 1), q of P digits: style e when
 * X < -4 or X >= P, else style f, trailing zeros removed either way. */
static char *fmt_g(char *buf, int neg, uint64_t q, int prec, int x)
{
	int n = prec;
	while (q % 10000 == 0) {
		q /= 10000;
		n -= 4;
	}
	while (q % 10 == 0) {
		q /= 10;
		n--;
	}
	char dig[20];
	put_digits(dig, q, n);
	char *p = buf;
	if (neg)
		*p++ = '-';
	if (x < -4 || x >= prec) {
		*p++ = dig[0];
		if (n > 1) {
			*p++ = '.';
			memcpy(p, dig + 1, (size_t)n - 1);
			p += n - 1;
		}
		*p++ = 'e';
		*p++ = x < 0 ? '-' : '+';
		int a = x < 0 ? -x : x;
		if (a >= 100) {
			*p++ = (char)('0' + a / 100);
			a %= 100;
		}
		memcpy(p, digit_pairs + 2 * a, 2);
		p += 2;
	} else if (x >= 0) {
		if (n <= x + 1) {
			memcpy(p, dig, (size_t)n);
			memset(p + n, '0', (size_t)(x + 1 - n));
			p += x + 1;
		} else {
			memcpy(p, dig, (size_t)x + 1);
			p += x + 1;
			*p++ = '.';
			memcpy(p, dig + x + 1, (size_t)(n - x - 1));
			p += n - x - 1;
		}
	} else {
		*p++ = '0';
		*p++ = '.';
		for (int i = 0; i < -x - 1; i++)
			*p++ = '0';
		memcpy(p, dig, (size_t)n);
		p += n;
	}
	*p = '\0';
	return p;
}

/* F = I + f / 2^64 rounded to prec digits, I having nd digits: the
 * digits in *q and the decimal exponent of the result in *x.  Returns -1
 * when too close to a tie to decide, else 1 if it rounded up, 0 if down;
 * *rem gets F's distance above q's lower neighbour, in units of 2^-64. */
static int round_to(uint64_t i, uint64_t f, int nd, int k, int prec,
		    uint64_t *q, int *x, u128 *rem)
{
	uint64_t d = pow10_u64[nd - prec];
	uint64_t r = i % d;
	*q = i / d;
	*rem = (u128)r << 64 | f;
	u128 half = (u128)(d / 2) << 64;
	u128 gap = *rem > half ? *rem - half : half - *rem;
	if (gap < TIE_MARGIN)
		return -1;
	int up = *rem > half;
	*q += (uint64_t)up;
	*x = nd - 1 - k;
	if (*q == pow10_u64[prec]) {
		*q = pow10_u64[prec - 1];
		++*x;
	}
	return up;
}

static char *ref_end(char *buf, double v)
{
	num_fmt_ref(buf, v);
	return buf + strlen(buf);
}

char *num_put(char *buf, double v)
{
	uint64_t bits;
	memcpy(&bits, &v, sizeof bits);
	int neg = (int)(bits >> 63);
	int be = (int)(bits >> 52 & 0x7ff);
	uint64_t m = bits & ((UINT64_C(1) << 52) - 1);
	if (be == 0 && m == 0) {
		buf[0] = '0';
		buf[1] = '\0';
		return buf + 1;
	}
	if (be == 0 || be == 0x7ff)
		return ref_end(buf, v);
	m |= UINT64_C(1) << 52;
	int e = be - 1075;                      /* v = m * 2^e */
	int k = 17 - floor_log10_pow2(be - 1023);
	/* v * 10^k is in [10^17, 2 * 10^18): 18 or 19 digits before the point */
	const int t = k - NUM_POW10_MIN;
	int j = -(e + num_pow10[t].s) - 64;     /* 55 to 60 */
	u128 lo = (u128)m * num_pow10[t].lo, hi = (u128)m * num_pow10[t].hi;
	u128 fx = (hi << (64 - j)) + (lo >> j);
	uint64_t ip = (uint64_t)(fx >> 64), fp = (uint64_t)fx;
	int nd = ip >= pow10_u64[18] ? 19 : 18;

	uint64_t q;
	int x;
	u128 rem;
	int up = round_to(ip, fp, nd, k, 15, &q, &x, &rem);
	if (up < 0)
		return ref_end(buf, v);
	/* does the 15-digit decimal lie in v's rounding interval? */
	u128 dist = up ? ((u128)pow10_u64[nd - 15] << 64) - rem : rem;
	u128 p = (u128)num_pow10[t].hi << 64 | num_pow10[t].lo;
	int narrow = !up && m == UINT64_C(1) << 52 && be > 1;
	u128 halfw = p >> (j + 1 + narrow);
	u128 gap = dist > halfw ? dist - halfw : halfw - dist;
	if (gap < EDGE_MARGIN)
		return ref_end(buf, v);
	if (dist < halfw)
		return fmt_g(buf, neg, q, 15, x);
	if (round_to(ip, fp, nd, k, 17, &q, &x, &rem) < 0)
		return ref_end(buf, v);
	return fmt_g(buf, neg, q, 17, x);
}

#else /* no 128-bit integers: the reference is the printer */

char *num_put(char *buf, double v)
{
	num_fmt_ref(buf, v);
	return buf + strlen(buf);
}

#endif

char *num_fmt(char *buf, double v)
{
	num_put(buf, v);
	return buf;
}

void num_print(FILE *f, double v)
{
	char buf[NUM_BUFSZ];
	fwrite(buf, 1, (size_t)(num_put(buf, v) - buf), f);
}

void num_print_row(FILE *f, const double *v, int n)
{
	char buf[NUM_BUFSZ + 1];
	for (int i = 0; i < n; i++) {
		char *e = num_put(buf, v[i]);
		*e++ = i + 1 < n ? ' ' : '\n';
		fwrite(buf, 1, (size_t)(e - buf), f);
	}
	if (n <= 0)
		fputc('\n', f);
}
