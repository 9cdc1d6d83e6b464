/* num.c - see num.h. */
#include "num.h"

#include <errno.h>
#include <math.h>
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

char *num_fmt(char *buf, double v)
{
	if (v == 0.0)
		v = 0.0; /* folds -0 into 0 */
	snprintf(buf, NUM_BUFSZ, "%.15g", v);
	if (strtod(buf, NULL) != v)
		snprintf(buf, NUM_BUFSZ, "%.17g", v);
	return buf;
}

void num_print(FILE *f, double v)
{
	char buf[NUM_BUFSZ];
	fputs(num_fmt(buf, v), f);
}

void num_print_row(FILE *f, const double *v, int n)
{
	char buf[NUM_BUFSZ];
	for (int i = 0; i < n; i++) {
		if (i)
			fputc(' ', f);
		fputs(num_fmt(buf, v[i]), f);
	}
	fputc('\n', f);
}
