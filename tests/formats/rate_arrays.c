/*
 * rate_arrays.c - fmt_rate_read_arrays (src/lib/fmt_rate.c), the reader
 * that keeps only some arrays and streams binary files from disk, against
 * what was written: a 7 x 5 x 4 grid with arrays rate, M and B, written
 * binary and ASCII, read back (a) with want = NULL (everything, as
 * fmt_rate_read), (b) with want = {"B"}: rate and B in file order, M not
 * kept, (c) with want = {NULL}: the rate alone.  Values and header
 * compared exactly (both forms round-trip doubles exactly).  The error
 * paths are those of fmt_rate_read, covered by tests/formats/002.
 */
#include "fmt_rate.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int nfail;

static void expect(int ok, const char *what)
{
	if (!ok && nfail++ < 20)
		fprintf(stderr, "rate_arrays: %s\n", what);
}

static void compare(const struct ratefile *got, const struct ratefile *src,
		    const char *const *names, int n, const char *what)
{
	char msg[200];
	snprintf(msg, sizeof msg, "%s: header or array count differs", what);
	expect(got->nx == src->nx && got->ny == src->ny && got->nz == src->nz &&
	       got->xmin == src->xmin && got->zmax == src->zmax && got->narrays == n, msg);
	size_t np = (size_t)src->nx * src->ny * src->nz;
	for (int a = 0; a < n && a < got->narrays; a++) {
		snprintf(msg, sizeof msg, "%s: array %d is %s, want %s", what, a,
			 got->arrays[a].name, names[a]);
		expect(strcmp(got->arrays[a].name, names[a]) == 0, msg);
		const double *w = fmt_rate_array(src, names[a]);
		snprintf(msg, sizeof msg, "%s: values of %s differ", what, names[a]);
		expect(w && memcmp(got->arrays[a].v, w, np * sizeof *w) == 0, msg);
	}
}

int main(void)
{
	const double b[6] = {-1, 1, -0.5, 0.5, -1.2, 0};
	struct ratefile *r = fmt_rate_new(7, 5, 4, b);
	double *m = fmt_rate_add_array(r, "M"), *bb = fmt_rate_add_array(r, "B");
	size_t np = 7 * 5 * 4;
	for (size_t i = 0; i < np; i++) {
		r->arrays[0].v[i] = 0.001 * (double)i + 1.0 / 3;
		m[i] = 1.0 / (double)(i + 7);
		bb[i] = -(double)(i + 1) * 0.1; /* no -0: files fold it to 0 */
	}
	fmt_rate_write("r.bin", r, 0);
	fmt_rate_write("r.txt", r, 1);
	const char *files[2] = {"r.bin", "r.txt"};
	for (int f = 0; f < 2; f++) {
		char what[64];
		const char *all[] = {"rate", "M", "B"};
		snprintf(what, sizeof what, "%s, all", files[f]);
		struct ratefile *g = fmt_rate_read_arrays(files[f], NULL);
		compare(g, r, all, 3, what);
		fmt_rate_free(g);
		const char *want_b[] = {"B", NULL}, *got_b[] = {"rate", "B"};
		snprintf(what, sizeof what, "%s, want B", files[f]);
		g = fmt_rate_read_arrays(files[f], want_b);
		compare(g, r, got_b, 2, what);
		fmt_rate_free(g);
		const char *none[] = {NULL}, *rate[] = {"rate"};
		snprintf(what, sizeof what, "%s, rate only", files[f]);
		g = fmt_rate_read_arrays(files[f], none);
		compare(g, r, rate, 1, what);
		fmt_rate_free(g);
	}
	fmt_rate_free(r);
	return nfail != 0;
}
