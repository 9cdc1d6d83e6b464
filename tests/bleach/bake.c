/*
 * bake.c - the post-exposure bake (src/bleach/bake.c) against the heat
 * equation's exact solution.
 *
 * 1. z (no flux at top and bottom): M = 0.5 + 0.2 cos(2 pi z / p), a
 *    cosine that fits the film (p = 2 T / 5), loses amplitude by exactly
 *    exp(-2 pi^2 sigma^2 / p^2); checked pointwise to 1e-6 for sigma =
 *    0.08 um (Table 9.1's diffusion length) and 0.03 um.
 * 2. The trapezoidal total of an arbitrary (non-smooth) profile is
 *    conserved to 1e-12, and sigma = 0 is the identity (1e-12).
 * 3. x and y (periodic window, last node repeating the first): a
 *    sinusoid of period p = L / 3 decays by the same factor to 1e-6, the
 *    end node still equals the first, and the mean is conserved.
 * 4. A fine grid (sigma of 20 and 6 samples), where bake_xy smooths by
 *    the recursive Gaussian (bake_iir.c): a sharp-edged field (a contact
 *    and a line) against the exact periodic kernel applied as a full
 *    matrix, within TOL_IIR of the field's range of 1; the mean conserved
 *    to 1e-12; and the result byte-identical for 1, 2 and 3 threads.
 */
#include "bleach.h"
#include "par.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOL_DECAY 1e-6
#define TOL_CONSERVE 1e-12
/* Deriche's fourth-order fit of the Gaussian against the exact kernel,
 * on a unit step: measured 2.5e-4 */
#define TOL_IIR 5e-4

static int failures;

static void fail(const char *what, double got, double want)
{
	printf("FAIL %s: got %.15g want %.15g\n", what, got, want);
	failures++;
}

static void z_decay(double sigma)
{
	int n = 301;
	double T = 0.7, d = T / (n - 1), p = 2 * T / 5;
	double *v = malloc(n * sizeof *v);
	for (int j = 0; j < n; j++)
		v[j] = 0.5 + 0.2 * cos(2 * M_PI * j * d / p);
	bake_rows(v, 1, n, d, sigma);
	double f = exp(-2 * M_PI * M_PI * sigma * sigma / (p * p)), worst = 0;
	for (int j = 0; j < n; j++) {
		double want = 0.5 + 0.2 * f * cos(2 * M_PI * j * d / p);
		if (fabs(v[j] - want) > worst)
			worst = fabs(v[j] - want);
	}
	printf("z bake sigma %g: amplitude factor %.6f, max error %.3g\n", sigma, f, worst);
	if (!(worst <= TOL_DECAY))
		fail("z decay", worst, 0);
	free(v);
}

static double trap(const double *v, int n)
{
	double s = 0.5 * (v[0] + v[n - 1]);
	for (int j = 1; j + 1 < n; j++)
		s += v[j];
	return s;
}

static double field(int i, int j, int nx, int ny)
{
	double x = (double)i / (nx - 1), y = (double)j / (ny - 1);
	double c = (fabs(x - 0.3) < 0.1 && fabs(y - 0.5) < 0.2) ? 1.0 : 0.0;
	double l = (x > 0.7 && x < 0.75) ? 0.6 : 0.0;
	return 0.1 + 0.9 * (c > l ? c : l) * 0.999 + 0.0001 * (i % 3);
}

static void fine_grid(void)
{
	int nx = 513, ny = 129, nz = 2;
	double Lx = 2.0, Ly = 1.6, sigma = 0.08, dx = Lx / (nx - 1), dy = Ly / (ny - 1);
	if (!bake_iir_wanted(nx - 1, dx, sigma) || !bake_iir_wanted(ny - 1, dy, sigma))
		fail("the fine grid is smoothed recursively", 0, 1);
	size_t n = (size_t)nx * ny * nz;
	double *f = malloc(n * sizeof *f), *g = malloc(n * sizeof *g), *h = malloc(n * sizeof *h);
	double mean0 = 0;
	for (int k = 0; k < nz; k++)
		for (int j = 0; j < ny; j++)
			for (int i = 0; i < nx; i++) {
				int ii = i == nx - 1 ? 0 : i, jj = j == ny - 1 ? 0 : j;
				f[((size_t)k * ny + j) * nx + i] = g[((size_t)k * ny + j) * nx + i] =
					field(ii, jj, nx, ny);
				if (i < nx - 1 && j < ny - 1)
					mean0 += field(ii, jj, nx, ny);
			}
	/* the exact bake: the periodic kernel as a full matrix, x then y */
	double *Sx = bake_matrix_periodic(nx - 1, dx, sigma);
	double *Sy = bake_matrix_periodic(ny - 1, dy, sigma);
	double *w = malloc((size_t)(nx > ny ? nx : ny) * sizeof *w);
	for (int k = 0; k < nz; k++) {
		double *pl = g + (size_t)k * nx * ny;
		for (int j = 0; j < ny; j++) {
			bake_apply(Sx, nx - 1, pl + (size_t)j * nx, 1, w);
			pl[(size_t)j * nx + nx - 1] = pl[(size_t)j * nx];
		}
		for (int i = 0; i < nx; i++) {
			bake_apply(Sy, ny - 1, pl + i, (size_t)nx, w);
			pl[(size_t)(ny - 1) * nx + i] = pl[i];
		}
	}
	par_set_threads(1);
	memcpy(h, f, n * sizeof *h);
	bake_xy(f, nx, ny, nz, dx, dy, sigma);
	double worst = 0, mean = 0;
	for (int k = 0; k < nz; k++)
		for (int j = 0; j < ny; j++)
			for (int i = 0; i < nx; i++) {
				size_t q = ((size_t)k * ny + j) * nx + i;
				if (fabs(f[q] - g[q]) > worst)
					worst = fabs(f[q] - g[q]);
				if (i < nx - 1 && j < ny - 1)
					mean += f[q];
			}
	printf("fine-grid xy bake (recursive): max difference to the exact kernel %.3g, "
	       "mean %.15g -> %.15g\n", worst, mean0 / nz / (nx - 1) / (ny - 1),
	       mean / nz / (nx - 1) / (ny - 1));
	if (!(worst <= TOL_IIR))
		fail("recursive x-y bake against the exact kernel", worst, 0);
	if (!(fabs(mean - mean0) <= TOL_CONSERVE * mean))
		fail("recursive x-y bake conserves the mean", mean, mean0);
	for (int t = 2; t <= 3; t++) {
		par_set_threads(t);
		memcpy(g, h, n * sizeof *g);
		bake_xy(g, nx, ny, nz, dx, dy, sigma);
		if (memcmp(f, g, n * sizeof *f) != 0)
			fail("recursive x-y bake identical for any thread count", t, 1);
	}
	free(Sx);
	free(Sy);
	free(w);
	free(f);
	free(g);
	free(h);
}

int main(void)
{
	z_decay(0.08);
	z_decay(0.03);

	/* conservation and identity on a rough profile */
	int n = 157;
	double v[157], w[157];
	for (int j = 0; j < n; j++)
		v[j] = w[j] = (j % 7 == 0) ? 1.0 : 0.1 + 0.001 * j + (j > 100 ? 0.5 : 0);
	double before = trap(v, n);
	bake_rows(v, 1, n, 0.005, 0.08);
	double after = trap(v, n);
	printf("conservation: %.17g -> %.17g\n", before, after);
	if (!(fabs(after - before) <= TOL_CONSERVE * before))
		fail("total M conserved", after, before);
	double u[157];
	for (int j = 0; j < n; j++)
		u[j] = w[j];
	bake_rows(u, 1, n, 0.005, 0);
	for (int j = 0; j < n; j++)
		if (!(fabs(u[j] - w[j]) <= TOL_CONSERVE)) {
			fail("sigma = 0 is the identity", u[j], w[j]);
			break;
		}

	/* periodic x and y */
	int nx = 51, ny = 41, nz = 2;
	double Lx = 2.0, Ly = 1.6, sigma = 0.08;
	double *f = malloc((size_t)nx * ny * nz * sizeof *f);
	for (int k = 0; k < nz; k++)
		for (int j = 0; j < ny; j++)
			for (int i = 0; i < nx; i++)
				f[(k * ny + j) * nx + i] = 0.5 + 0.2 * cos(2 * M_PI * i * (Lx / (nx - 1)) / (Lx / 3))
					+ 0.1 * sin(2 * M_PI * j * (Ly / (ny - 1)) / (Ly / 3));
	bake_xy(f, nx, ny, nz, Lx / (nx - 1), Ly / (ny - 1), sigma);
	double fx = exp(-2 * M_PI * M_PI * sigma * sigma / (Lx / 3 * Lx / 3));
	double fy = exp(-2 * M_PI * M_PI * sigma * sigma / (Ly / 3 * Ly / 3));
	double worst = 0, mean = 0;
	for (int k = 0; k < nz; k++)
		for (int j = 0; j < ny; j++)
			for (int i = 0; i < nx; i++) {
				double want = 0.5 + 0.2 * fx * cos(2 * M_PI * i * (Lx / (nx - 1)) / (Lx / 3))
					+ 0.1 * fy * sin(2 * M_PI * j * (Ly / (ny - 1)) / (Ly / 3));
				double g = f[(k * ny + j) * nx + i];
				if (fabs(g - want) > worst)
					worst = fabs(g - want);
				if (i < nx - 1 && j < ny - 1)
					mean += g;
			}
	mean /= (double)nz * (nx - 1) * (ny - 1);
	printf("xy bake: max error %.3g, mean %.15g\n", worst, mean);
	if (!(worst <= TOL_DECAY))
		fail("x-y decay", worst, 0);
	if (!(fabs(mean - 0.5) <= TOL_CONSERVE))
		fail("x-y mean conserved", mean, 0.5);
	free(f);
	fine_grid();
	if (failures)
		printf("%d failures\n", failures);
	return failures != 0;
}
