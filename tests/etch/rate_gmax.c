/*
 * rate_gmax.c - rfield_init's max|grad R| and max R (src/etch/rate.c,
 * computed per grid point from the six edge slopes around it, planes
 * split among threads) against the direct form of thesis 7.4.1 (every
 * corner of every trilinear cell, gx^2 + gy^2 + gz^2 along the cell's
 * edges), on 200 random grids from 2 x 2 x 2 to 9 x 8 x 7 with random
 * spacings and rates (uniform, with repeats and zeros, and spiky), at 1,
 * 2 and 3 threads.  Exact equality: the two are the same rounded sums.
 */
#include "fmt_rate.h"
#include "par.h"
#include "rfield.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

static uint64_t state = 99;
static double uniform(void)
{
	uint64_t z = (state += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return (double)((z ^ (z >> 31)) >> 11) / 9007199254740992.0;
}

/* thesis 7.4.1 as the cells' corners */
static double direct_gmax(const struct rfield *f)
{
	const int *n = f->n;
	size_t sx = 1, sy = (size_t)n[0], sz = (size_t)n[0] * n[1];
	double gmax2 = 0;
	for (int k = 0; k + 1 < n[2]; k++)
		for (int j = 0; j + 1 < n[1]; j++)
			for (int i = 0; i + 1 < n[0]; i++) {
				const double *v = f->v + k * sz + j * sy + i;
				for (int c = 0; c < 8; c++) {
					size_t ox = c & 1, oy = (c >> 1) & 1, oz = (c >> 2) & 1;
					double gx = (v[sx + oy * sy + oz * sz] - v[oy * sy + oz * sz]) / f->h[0];
					double gy = (v[ox + sy + oz * sz] - v[ox + oz * sz]) / f->h[1];
					double gz = (v[ox + oy * sy + sz] - v[ox + oy * sy]) / f->h[2];
					double g2 = gx * gx + gy * gy + gz * gz;
					if (g2 > gmax2)
						gmax2 = g2;
				}
			}
	return sqrt(gmax2);
}

int main(void)
{
	int nfail = 0;
	for (int c = 0; c < 200; c++) {
		int nx = 2 + (int)(uniform() * 8), ny = 2 + (int)(uniform() * 7), nz = 2 + (int)(uniform() * 6);
		double b[6] = {0, 0.1 + uniform(), -1, uniform() * 3, -uniform() - 0.01, 0};
		struct ratefile *r = fmt_rate_new(nx, ny, nz, b);
		double *v = fmt_rate_values(r);
		size_t np = (size_t)nx * ny * nz;
		double rmax = 0;
		for (size_t i = 0; i < np; i++) {
			double u = uniform();
			v[i] = c % 3 == 0 ? u : c % 3 == 1 ? floor(u * 3) * 0.25 : (u < 0.1 ? 100 * u : 1e-3 * u);
			if (v[i] > rmax)
				rmax = v[i];
		}
		for (int t = 1; t <= 3; t++) {
			par_set_threads(t);
			struct rfield f;
			fmt_rate_field(&f, r, "random");
			double want = direct_gmax(&f);
			if ((f.gmax != want || f.rmax != rmax) && nfail++ < 10)
				fprintf(stderr, "rate_gmax: grid %d (%dx%dx%d, %d threads): gmax %.17g, "
					"direct %.17g; rmax %.17g, direct %.17g\n", c, nx, ny, nz, t,
					f.gmax, want, f.rmax, rmax);
		}
		fmt_rate_free(r);
	}
	return nfail != 0;
}
