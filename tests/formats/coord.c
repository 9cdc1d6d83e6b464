/*
 * coord.c - draw_coord_text (src/lib/draw.c, the PostScript and SVG
 * coordinate printer) against the printf form it replaced (copied below):
 * round to 0.01, printf "%.2f", trailing zeros and point dropped, "-0"
 * folded.  Byte equality over 0, -0, tiny values, every k / 200 for |k| up
 * to 200000 (the ties of the rounding), 1 million random values in
 * [-1e4, 1e4] and 100 000 up to 1e16 (past the integer form's limit),
 * infinities and NaN.
 */
#include "draw.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static void old_coord(char *buf, size_t size, double v)
{
	double r = round(v * 100) / 100;
	if (fabs(r) < 0.005)
		r = 0;
	snprintf(buf, size, "%.2f", r);
	char *dot = strchr(buf, '.');
	if (dot) {
		char *e = buf + strlen(buf) - 1;
		while (e > dot && *e == '0')
			*e-- = '\0';
		if (e == dot)
			*e = '\0';
	}
}

static int nfail;

static void check(double v)
{
	char a[400], b[400];
	draw_coord_text(a, sizeof a, v);
	old_coord(b, sizeof b, v);
	if (strcmp(a, b) != 0 && nfail++ < 20)
		fprintf(stderr, "coord: %.17g: got \"%s\", want \"%s\"\n", v, a, b);
}

static uint64_t state = 7;
static double uniform(void) /* [0, 1) */
{
	uint64_t z = (state += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return (double)((z ^ (z >> 31)) >> 11) / 9007199254740992.0;
}

int main(void)
{
	const double edge[] = {0.0, -0.0, 0.004999, -0.004999, 0.005, -0.005, 0.0051,
			       -0.0051, 1e-300, -1e-300, 0.1, 0.29, 1e13, 9.99999999999e12,
			       INFINITY, -INFINITY, NAN};
	for (size_t i = 0; i < sizeof edge / sizeof edge[0]; i++)
		check(edge[i]);
	for (int k = -200000; k <= 200000; k++)
		check(k / 200.0);
	for (int i = 0; i < 1000000; i++)
		check((uniform() - 0.5) * 2e4);
	for (int i = 0; i < 100000; i++)
		check((uniform() - 0.5) * pow(10, 16 * uniform()));
	return nfail != 0;
}
