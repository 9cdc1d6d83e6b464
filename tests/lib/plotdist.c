/*
 * plotdist - test tool: how far the profiles of one 2D plot file lie from
 * those of another, set by set (etch2d's methods against a refined
 * fast-marching reference: tests/bench/etch2d.sh).
 *
 *   plotdist test.plot reference.plot
 *
 * For every set (paired in order) prints one line "set median p95 max":
 * the distances (um) of the test set's points to the reference set's
 * polylines.  Exits 1 if the files do not pair up.
 */
#include "fmt_plot.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static double dist(const struct plot_set *s, const double *p)
{
	double best = INFINITY;
	for (int c = 0; c < s->ncurves; c++) {
		const struct plot_curve *cv = &s->curves[c];
		for (int k = 0; k + 1 < cv->npts; k++) {
			const double *a = cv->p + 2 * k, *b = a + 2;
			double dx = b[0] - a[0], dz = b[1] - a[1], l2 = dx * dx + dz * dz;
			double u = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dz) / l2 : 0;
			u = u < 0 ? 0 : u > 1 ? 1 : u;
			double d = hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dz);
			if (d < best)
				best = d;
		}
	}
	return best;
}

static int cmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return x < y ? -1 : x > y;
}

int main(int argc, char **argv)
{
	util_setprog(argv[0]);
	if (argc != 3)
		die_status(EXIT_USAGE, "usage: plotdist test.plot reference.plot");
	struct plot_file *a = fmt_plot_read(argv[1], 2), *b = fmt_plot_read(argv[2], 2);
	if (a->nsets != b->nsets)
		die("%s has %d sets, %s %d", argv[1], a->nsets, argv[2], b->nsets);
	for (int s = 0; s < a->nsets; s++) {
		size_t n = 0, cap = 0;
		double *d = NULL;
		for (int c = 0; c < a->sets[s].ncurves; c++)
			for (int k = 0; k < a->sets[s].curves[c].npts; k++) {
				xgrow(&d, &cap, n + 1, sizeof *d);
				d[n++] = dist(&b->sets[s], a->sets[s].curves[c].p + 2 * k);
			}
		if (n == 0) {
			printf("%d - - -\n", s + 1);
			continue;
		}
		qsort(d, n, sizeof *d, cmp);
		printf("%d %.4f %.4f %.4f\n", s + 1, d[n / 2], d[(size_t)floor(0.95 * (double)(n - 1) + 0.5)],
		       d[n - 1]);
		free(d);
	}
	fmt_plot_free(a);
	fmt_plot_free(b);
	return 0;
}
