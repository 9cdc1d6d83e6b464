/*
 * par.c - par_for (src/lib/par.c) against its contract, for 1 to 4
 * threads, n from 0 to 12345 and minimum chunks 1, 7 and 256:
 *  - every index of [0, n) is visited exactly once;
 *  - the ranges are contiguous, each at least min_chunk long (unless one
 *    range holds all), numbered by worker in order of lo, fewer than
 *    par_threads();
 *  - the same n, min_chunk and thread count give the same ranges twice;
 *  - a par_for inside fn runs its whole range in the calling thread.
 * Exact checks.
 */
#include "par.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAXN = 12345 };

static int visits[MAXN];
static size_t lo_of[PAR_MAX_THREADS], hi_of[PAR_MAX_THREADS];
static int used[PAR_MAX_THREADS];
static int nfail;

static void fail(const char *what, int t, size_t n, size_t chunk)
{
	if (nfail++ < 20)
		fprintf(stderr, "par: %s (threads %d, n %zu, min_chunk %zu)\n", what, t, n, chunk);
}

static void inner(void *ctx, size_t lo, size_t hi, int worker)
{
	int *ok = ctx;
	if (lo != 0 || hi != 3 || worker != 0)
		*ok = 0;
}

static void visit(void *ctx, size_t lo, size_t hi, int worker)
{
	(void)ctx;
	for (size_t i = lo; i < hi; i++)
		visits[i]++;
	lo_of[worker] = lo;
	hi_of[worker] = hi;
	used[worker]++;
	int ok = 1;
	par_for(3, 1, inner, &ok);
	if (!ok)
		visits[lo] += 1000;     /* flags the nested call */
}

int main(void)
{
	const size_t ns[] = {0, 1, 2, 5, 100, 1000, MAXN};
	const size_t chunks[] = {1, 7, 256};
	for (int t = 1; t <= 4; t++) {
		par_set_threads(t);
		for (size_t a = 0; a < sizeof ns / sizeof ns[0]; a++)
			for (size_t c = 0; c < sizeof chunks / sizeof chunks[0]; c++) {
				size_t n = ns[a], ch = chunks[c];
				size_t first[PAR_MAX_THREADS][2];
				for (int rep = 0; rep < 2; rep++) {
					memset(visits, 0, sizeof visits);
					memset(used, 0, sizeof used);
					par_for(n, ch, visit, NULL);
					for (size_t i = 0; i < n; i++)
						if (visits[i] != 1)
							fail("an index not visited exactly once, or a nested call split", t, n, ch);
					int nr = 0;
					while (nr < PAR_MAX_THREADS && used[nr])
						nr++;
					for (int w = nr; w < PAR_MAX_THREADS; w++)
						if (used[w])
							fail("worker numbers not consecutive", t, n, ch);
					if (n == 0 && nr != 0)
						fail("work for n = 0", t, n, ch);
					if (nr > par_threads())
						fail("more ranges than threads", t, n, ch);
					for (int w = 0; w < nr; w++) {
						if (used[w] != 1)
							fail("a worker called twice", t, n, ch);
						if (lo_of[w] != (w ? hi_of[w - 1] : 0))
							fail("ranges not contiguous in worker order", t, n, ch);
						if (nr > 1 && hi_of[w] - lo_of[w] < ch)
							fail("a range shorter than min_chunk", t, n, ch);
						if (rep == 0) {
							first[w][0] = lo_of[w];
							first[w][1] = hi_of[w];
						} else if (first[w][0] != lo_of[w] || first[w][1] != hi_of[w]) {
							fail("ranges differ between two identical calls", t, n, ch);
						}
					}
					if (nr && hi_of[nr - 1] != n)
						fail("ranges do not end at n", t, n, ch);
				}
			}
	}
	return nfail != 0;
}
