/*
 * rate_planes.c - fmt_rate_write_planes (src/lib/fmt_rate.c), the writer
 * that makes an array plane by plane as it writes it (bleach's rate array,
 * never held whole), against fmt_rate_write of the same values: a
 * 7 x 5 x 4 grid with arrays rate and M, the rate made by the callback
 * (which must be called once per plane, in order), written binary and
 * ASCII: both files byte-identical to the held-array writer's.  The binary
 * planes (280 bytes) are shorter than the writer's 8 kB chunk and the
 * CRC runs across them, which a per-plane CRC restart would break.
 */
#include "fmt_rate.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int nfail, calls, nextk;

static void expect(int ok, const char *what)
{
	if (!ok && nfail++ < 20)
		fprintf(stderr, "rate_planes: %s\n", what);
}

static double value(int i, int j, int k) { return 0.001 * i + 0.37 * j - 1.25 * k + 1.0 / 3; }

static void gen(void *ctx, int array, int k, double *plane)
{
	const struct ratefile *r = ctx;
	expect(array == 0, "callback asked for another array than the rate");
	expect(k == nextk, "planes not asked for in order");
	nextk = k + 1;
	calls++;
	for (int j = 0; j < r->ny; j++)
		for (int i = 0; i < r->nx; i++)
			plane[j * r->nx + i] = value(i, j, k);
}

static char *slurp(const char *path, long *n)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return NULL;
	fseek(f, 0, SEEK_END);
	*n = ftell(f);
	rewind(f);
	char *b = malloc((size_t)*n + 1);
	if (fread(b, 1, (size_t)*n, f) != (size_t)*n)
		*n = -1;
	fclose(f);
	return b;
}

int main(void)
{
	double b[6] = {-1, 1, -0.5, 0.5, -0.7, 0};
	struct ratefile *held = fmt_rate_new(7, 5, 4, b);
	double *M = fmt_rate_add_array(held, "M");
	for (int k = 0; k < 4; k++)
		for (int j = 0; j < 5; j++)
			for (int i = 0; i < 7; i++) {
				size_t q = fmt_rate_index(held, i, j, k);
				held->arrays[0].v[q] = value(i, j, k);
				M[q] = 0.5 + 0.01 * (double)q;
			}
	struct ratefile *streamed = fmt_rate_new(7, 5, 4, b);
	memcpy(fmt_rate_add_array(streamed, "M"), M, 7 * 5 * 4 * sizeof *M);
	free(streamed->arrays[0].v);
	streamed->arrays[0].v = NULL;
	for (int ascii = 0; ascii <= 1; ascii++) {
		fmt_rate_write("held.rate", held, ascii);
		calls = nextk = 0;
		fmt_rate_write_planes("streamed.rate", streamed, ascii, gen, streamed);
		expect(calls == 4, "the callback was not called once per plane");
		long n1, n2;
		char *a = slurp("held.rate", &n1), *c = slurp("streamed.rate", &n2);
		expect(a && c && n1 > 0 && n1 == n2 && memcmp(a, c, (size_t)n1) == 0,
		       ascii ? "ASCII files differ" : "binary files differ");
		free(a);
		free(c);
	}
	remove("held.rate");
	remove("streamed.rate");
	fmt_rate_free(held);
	fmt_rate_free(streamed);
	if (nfail)
		fprintf(stderr, "rate_planes: %d failures\n", nfail);
	return nfail != 0;
}
