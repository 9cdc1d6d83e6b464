/*
 * image.c - the aerial image from its spectrum,
 *   I(x, y) = sum_{dm, dn} A(dm, dn) exp(2 pi i (dm x / Lx + dn y / Ly)),
 * summed directly: the output grid includes both window ends and need not
 * match the period, so an FFT would not fit, and the separable sum (first
 * over dn for each grid row, then over dm) costs only
 * (4M+1)(4N+1) ny + (4M+1) nx ny complex products.  Rounding can leave
 * -1e-17 where the intensity |E|^2 is zero; it is clamped to 0.
 */
#include "splat.h"
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

void image_grid(const struct spectrum *sp, double xmin, double xmax, double ymin,
		double ymax, int nx, int ny, double *z)
{
	size_t w = 4 * (size_t)sp->mmax + 1, h = 4 * (size_t)sp->nmax + 1;
	double complex *ex = xreallocarray(NULL, w * (size_t)nx, sizeof *ex);
	double complex *ey = xreallocarray(NULL, h, sizeof *ey);
	double complex *b = xreallocarray(NULL, w, sizeof *b);
	for (int i = 0; i < nx; i++) {
		double x = xmin + (xmax - xmin) * i / (nx - 1);
		for (size_t im = 0; im < w; im++)
			ex[(size_t)i * w + im] = cis(2 * M_PI * ((double)im - 2 * sp->mmax) * x / sp->lx);
	}
	struct progress prog;
	progress_begin(&prog, "image rows", splat_quiet);
	for (int j = 0; j < ny; j++) {
		progress_step(&prog, j, ny);
		double y = ymin + (ymax - ymin) * j / (ny - 1);
		for (size_t jn = 0; jn < h; jn++)
			ey[jn] = cis(2 * M_PI * ((double)jn - 2 * sp->nmax) * y / sp->ly);
		for (size_t im = 0; im < w; im++) {
			double complex s = 0;
			for (size_t jn = 0; jn < h; jn++)
				s += sp->a[jn * w + im] * ey[jn];
			b[im] = s;
		}
		for (int i = 0; i < nx; i++) {
			const double complex *e = ex + (size_t)i * w;
			double s = 0;
			for (size_t im = 0; im < w; im++)
				s += creal(b[im]) * creal(e[im]) - cimag(b[im]) * cimag(e[im]);
			z[(size_t)j * nx + i] = s > 0 ? s : 0;
		}
	}
	free(ex);
	free(ey);
	free(b);
}
