/*
 * image.c - the aerial image from its spectrum,
 *   I(x, y) = sum_{dm, dn} A(dm, dn) exp(2 pi i (dm x / Lx + dn y / Ly)),
 * summed directly: the output grid includes both window ends and need not
 * match the period, so an FFT would not fit, and the separable sum (first
 * over dn for each grid row, then over dm) costs only
 * (4M+1)(4N+1) ny + (4M+1) nx ny complex products; the rows are shared
 * among threads, each row computed alone.  Rounding can leave
 * -1e-17 where the intensity |E|^2 is zero; it is clamped to 0.
 */
#include "splat.h"
#include "par.h"
#include "progress.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>

static double complex cis(double a)
{
	return cos(a) + I * sin(a);
}

double image_at(const struct spectrum *sp, double x, double y)
{
	int w = 4 * sp->mmax + 1, h = 4 * sp->nmax + 1;
	double sum = 0;
	for (int jn = 0; jn < h; jn++) {
		int dn = jn - 2 * sp->nmax;
		double complex row = 0;
		for (int im = 0; im < w; im++) {
			int dm = im - 2 * sp->mmax;
			double complex a = sp->a[(size_t)jn * w + im];
			if (a != 0)
				row += a * cis(2 * M_PI * dm * x / sp->lx);
		}
		sum += creal(row * cis(2 * M_PI * dn * y / sp->ly));
	}
	return sum > 0 ? sum : 0;
}

struct grid_job {
	const struct spectrum *sp;
	double ymin, ymax;
	int nx, ny;
	const double complex *ex;
	double complex *scratch;        /* per worker: ey (h) and b (w) */
	double *z;
	size_t row0;                    /* first row of the block */
};

/* rows row0 + lo .. row0 + hi - 1: each row alone, so the values do not
 * depend on how the rows are shared among threads */
static void grid_rows(void *ctx, size_t lo, size_t hi, int worker)
{
	const struct grid_job *g = ctx;
	const struct spectrum *sp = g->sp;
	size_t w = 4 * (size_t)sp->mmax + 1, h = 4 * (size_t)sp->nmax + 1;
	double complex *ey = g->scratch + (size_t)worker * (w + h), *b = ey + h;
	int nx = g->nx, ny = g->ny;
	for (size_t jj = lo; jj < hi; jj++) {
		size_t j = g->row0 + jj;
		double y = g->ymin + (g->ymax - g->ymin) * (double)j / (ny - 1);
		for (size_t jn = 0; jn < h; jn++)
			ey[jn] = cis(2 * M_PI * ((double)jn - 2 * sp->nmax) * y / sp->ly);
		for (size_t im = 0; im < w; im++) {
			double complex s = 0;
			for (size_t jn = 0; jn < h; jn++)
				s += sp->a[jn * w + im] * ey[jn];
			b[im] = s;
		}
		for (int i = 0; i < nx; i++) {
			const double complex *e = g->ex + (size_t)i * w;
			double s = 0;
			for (size_t im = 0; im < w; im++)
				s += creal(b[im]) * creal(e[im]) - cimag(b[im]) * cimag(e[im]);
			g->z[j * nx + i] = s > 0 ? s : 0;
		}
	}
}

void image_grid(const struct spectrum *sp, double xmin, double xmax, double ymin,
		double ymax, int nx, int ny, double *z)
{
	size_t w = 4 * (size_t)sp->mmax + 1, h = 4 * (size_t)sp->nmax + 1;
	double complex *ex = xreallocarray(NULL, w * (size_t)nx, sizeof *ex);
	int nt = par_threads();
	double complex *scratch = xreallocarray(NULL, (size_t)nt * (w + h), sizeof *scratch);
	for (int i = 0; i < nx; i++) {
		double x = xmin + (xmax - xmin) * i / (nx - 1);
		for (size_t im = 0; im < w; im++)
			ex[(size_t)i * w + im] = cis(2 * M_PI * ((double)im - 2 * sp->mmax) * x / sp->lx);
	}
	struct grid_job g = {sp, ymin, ymax, nx, ny, ex, scratch, z, 0};
	struct progress prog;
	progress_begin(&prog, "image rows", splat_quiet);
	/* blocks of rows between progress lines, the rows of a block shared
	 * among the threads */
	size_t block = 16 * (size_t)nt;
	for (size_t j = 0; j < (size_t)ny; j += block) {
		progress_step(&prog, (double)j, ny);
		g.row0 = j;
		size_t n = (size_t)ny - j < block ? (size_t)ny - j : block;
		par_for(n, 1, grid_rows, &g);
	}
	free(ex);
	free(scratch);
}
