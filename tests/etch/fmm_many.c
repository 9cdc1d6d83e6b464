/*
 * fmm_many.c - fmm_distance_many (the cut cells of T = t indexed once
 * for all points, the points shared among threads) against fmm_distance
 * (each point's block of cells extracted afresh): the same triangles in
 * the same block coordinates, so the distances must be the same to the
 * last bit (compared with memcmp, no tolerance), at 1 and 3 threads.
 *
 *  1. Two seeds (thesis Figure 8.13), T = 0.6 and T = 1: spheres that
 *     meet, a kink of T on the ridge where the gradient line misses the
 *     nearest surface and the block search decides; two points on the
 *     ridge and 1000 scattered over a box larger than the grid's
 *     (clamped queries).
 *  2. A resist developed through in its fast half (R = 1 for x < 0.5,
 *     0.15 beyond, depth 1, t = 1.5): the substrate counts as surface,
 *     the front has a step; 600 points.
 *  3. A grid one node thick in y, developed through in its fast half:
 *     no cells, so no search, the substrate alone; the same values
 *     through either path.
 */
#include "fmm.h"
#include "par.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

static struct ratefile *field(int nx, int ny, int nz, const double b[6], double slow)
{
	struct ratefile *r = fmt_rate_new(nx, ny, nz, b);
	for (int k = 0; k < nz; k++)
		for (int j = 0; j < ny; j++)
			for (int i = 0; i < nx; i++) {
				double x = b[0] + (b[1] - b[0]) * i / (nx > 1 ? nx - 1 : 1);
				r->arrays[0].v[((size_t)k * ny + j) * nx + i] = x < 0.5 ? 1 : slow;
			}
	return r;
}

/* n points scattered over b widened by a fifth of its size each way */
static double *scatter(const double b[6], size_t n)
{
	double *p = xreallocarray(NULL, n, 3 * sizeof *p);
	unsigned long s = 7;
	for (size_t i = 0; i < 3 * n; i++) {
		int d = (int)(i % 3);
		s = s * 6364136223846793005ul + 1442695040888963407ul;
		double u = (double)(s >> 11) / 9007199254740992.0, w = b[2 * d + 1] - b[2 * d];
		p[i] = b[2 * d] - 0.2 * w + u * 1.4 * w;
	}
	return p;
}

static void compare(const char *name, const struct fmm *f, const double *p, size_t n, double t)
{
	double *want = xreallocarray(NULL, n, sizeof *want);
	double *got = xreallocarray(NULL, n, sizeof *got);
	size_t finite = 0;
	for (size_t i = 0; i < n; i++) {
		want[i] = fmm_distance(f, p + 3 * i, t);
		finite += want[i] < 0.5 * FMM_UNREACHED;
	}
	for (int th = 1; th <= 3; th += 2) {
		par_set_threads(th);
		fmm_distance_many(f, p, n, t, got);
		size_t bad = 0;
		for (size_t i = 0; i < n; i++)
			bad += memcmp(want + i, got + i, sizeof *got) != 0;
		printf("%s, t = %g, %d thread(s): %zu of %zu distances differ (%zu reached)\n", name,
		       t, th, bad, n, finite);
		if (bad) {
			failures++;
			printf("FAIL %s: fmm_distance_many differs from fmm_distance\n", name);
		}
	}
	/* a test that cannot fail is none: the points must reach the surface */
	if (finite < n / 4) {
		failures++;
		printf("FAIL %s: only %zu of %zu points reached\n", name, finite, n);
	}
	par_set_threads(0);
	free(want);
	free(got);
}

int main(void)
{
	const double b1[6] = {-1.2, 1.2, -1.2, 2.2, -1.2, 1.2};
	const double seeds[6] = {0, 0, 0, 0, 1, 0};
	struct ratefile *r = field(25, 35, 25, b1, 1);
	struct fmm *f = fmm_solve_points(r, NULL, seeds, 2);
	double *p = scatter(b1, 1000);
	const double ridge[6] = {0, 0.5, 0, 0.1, 0.5, 0.05};
	memcpy(p, ridge, sizeof ridge);
	compare("two seeds", f, p, 1000, 0.6);
	compare("two seeds", f, p, 1000, 1.0);
	free(p);
	fmm_free(f);
	fmt_rate_free(r);

	const double b2[6] = {0, 1, 0, 0.6, -1, 0};
	r = field(21, 13, 21, b2, 0.15);
	f = fmm_solve(r, NULL);
	p = scatter(b2, 600);
	compare("developed through", f, p, 600, 1.5);
	free(p);
	fmm_free(f);
	fmt_rate_free(r);

	const double b3[6] = {0, 1, 0, 0, -1, 0};
	r = field(11, 1, 11, b3, 0.5);
	f = fmm_solve(r, NULL);
	p = scatter(b3, 200);
	compare("one node thick", f, p, 200, 1.5);
	free(p);
	fmm_free(f);
	fmt_rate_free(r);
	return failures != 0;
}
