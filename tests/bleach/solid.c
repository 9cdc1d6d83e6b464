/*
 * solid.c - mxyz.solid.3D (src/bleach/solid.c): the surface M = level
 * written through the plot writer must read back as one pdraw set of
 * closed 4-point triangles, with the count the writer returned, inside
 * the bounds, and watertight: every directed edge (a, b) is matched by
 * exactly one (b, a), vertices compared after rounding to 1e-9 um (a
 * shared vertex is interpolated from either end of its grid edge, so
 * its copies may differ in the last bits; the grid step is 0.05 um).  The field is a
 * contact-like well M = min(1, 0.3 + r^2) cut open by the resist top,
 * so the closing by the box faces is exercised as well.
 */
#include "bleach.h"
#include "fmt_plot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct edge { double a[3], b[3]; };

static int cmp3(const double *p, const double *q)
{
	for (int i = 0; i < 3; i++) {
		if (p[i] < q[i]) return -1;
		if (p[i] > q[i]) return 1;
	}
	return 0;
}

static int cmp_edge(const void *x, const void *y)
{
	const struct edge *e = x, *f = y;
	int c = cmp3(e->a, f->a);
	return c ? c : cmp3(e->b, f->b);
}

int main(void)
{
	int nx = 21, ny = 17, nz = 15;
	double b[6] = {-1, 1, -0.8, 0.8, -0.7, 0};
	double *f = malloc((size_t)nx * ny * nz * sizeof *f);
	for (int k = 0; k < nz; k++)
		for (int j = 0; j < ny; j++)
			for (int i = 0; i < nx; i++) {
				double x = b[0] + i * (b[1] - b[0]) / (nx - 1);
				double y = b[2] + j * (b[3] - b[2]) / (ny - 1);
				double z = b[4] + k * (b[5] - b[4]) / (nz - 1);
				double r2 = x * x + y * y + 0.5 * z * z;
				f[((size_t)k * ny + j) * nx + i] = fmin(1, 0.3 + r2);
			}
	long n = solid_write("solid.3D", f, nx, ny, nz, b, 0.8);
	struct plot_file *pf = fmt_plot_read("solid.3D", 3);
	int bad = 0;
	if (pf->nsets != 1 || pf->sets[0].ncurves != n || n < 100) {
		printf("FAIL: %d sets, %d curves, writer said %ld\n", pf->nsets,
		       pf->nsets ? pf->sets[0].ncurves : -1, n);
		return 1;
	}
	struct plot_set *s = &pf->sets[0];
	struct edge *e = malloc((size_t)n * 3 * sizeof *e);
	for (long t = 0; t < n; t++) {
		struct plot_curve *c = &s->curves[t];
		if (c->npts != 4 || cmp3(c->p, c->p + 9) != 0) {
			printf("FAIL: curve %ld is not a closed triangle\n", t);
			return 1;
		}
		for (int v = 0; v < 3; v++) {
			for (int q = 0; q < 3; q++)
				if (c->p[3 * v + q] < b[2 * q] - 1e-12 || c->p[3 * v + q] > b[2 * q + 1] + 1e-12)
					bad++;
			for (int q = 0; q < 3; q++) {
				e[3 * t + v].a[q] = (double)lround(c->p[3 * v + q] * 1e9);
				e[3 * t + v].b[q] = (double)lround(c->p[3 * ((v + 1) % 3) + q] * 1e9);
			}
		}
	}
	if (bad) {
		printf("FAIL: %d coordinates outside the bounds\n", bad);
		return 1;
	}
	qsort(e, (size_t)n * 3, sizeof *e, cmp_edge);
	long unmatched = 0;
	for (long q = 0; q < n * 3; q++) {
		struct edge r;
		memcpy(r.a, e[q].b, sizeof r.a);
		memcpy(r.b, e[q].a, sizeof r.b);
		struct edge *m = bsearch(&r, e, (size_t)n * 3, sizeof *e, cmp_edge);
		int dup = (q > 0 && cmp_edge(&e[q], &e[q - 1]) == 0) ||
			  (q + 1 < n * 3 && cmp_edge(&e[q], &e[q + 1]) == 0);
		if (!m || dup)
			unmatched++;
	}
	printf("%ld triangles, %ld unmatched edges\n", n, unmatched);
	free(e);
	free(f);
	fmt_plot_free(pf);
	remove("solid.3D");
	return unmatched != 0;
}
