/* checked.c - see checked.h. */
#include "checked.h"
#include "util.h"

#include <limits.h>
#include <stdint.h>

int ck_mul_ok(size_t a, size_t b, size_t *out)
{
	if (b && a > SIZE_MAX / b)
		return 0;
	*out = a * b;
	return 1;
}

size_t ck_mul(size_t a, size_t b, const char *what)
{
	size_t r;
	if (!ck_mul_ok(a, b, &r))
		die("%s: %zu x %zu is too large (overflows)", what, a, b);
	return r;
}

size_t ck_mul3(size_t a, size_t b, size_t c, const char *what)
{
	return ck_mul(ck_mul(a, b, what), c, what);
}

size_t ck_add(size_t a, size_t b, const char *what)
{
	if (a > SIZE_MAX - b)
		die("%s: %zu + %zu is too large (overflows)", what, a, b);
	return a + b;
}

int ck_fits(double v, double lo, double hi)
{
	return v >= lo && v <= hi;
}

long ck_long(double v, long lo, long hi, const char *what)
{
	/* (double)LONG_MAX rounds up to 2^63, which does not fit: compare
	 * against the half-open range */
	if (!(v >= (double)lo && v < (double)hi + 1.0))
		die("%s: %g is out of range [%ld, %ld]", what, v, lo, hi);
	long r = (long)v;
	if (r > hi)
		die("%s: %g is out of range [%ld, %ld]", what, v, lo, hi);
	return r;
}

int ck_int(double v, int lo, int hi, const char *what)
{
	return (int)ck_long(v, lo, hi, what);
}
