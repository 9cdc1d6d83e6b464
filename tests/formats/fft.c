/*
 * fft.c - the library's FFT (src/lib/fft.c) against a direct DFT,
 *   X[k] = sum_j x[j] exp(sign 2 pi i j k / n),
 * with the angle of j k reduced modulo n exactly, on random data for
 * lengths 1, 2, 3, 5, 7, 12, 30, 100, 97, 800 and others (powers of two,
 * radices 4, 11, 13, Bluestein lengths 17, 97, 194, 1009), both signs;
 * then forward and backward give n x back, and the 2D transform of a
 * 30 x 97 array equals the rows' then the columns' direct DFTs.
 * Tolerance: 1e-12 of the largest |X| (rounding is about 1e-15 here).
 */
#include "fft.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int nfail;

static double complex cis(double a)
{
	return cos(a) + I * sin(a);
}

static void dft(const double complex *x, double complex *X, size_t n, int sign)
{
	for (size_t k = 0; k < n; k++) {
		double complex s = 0;
		for (size_t j = 0; j < n; j++)
			s += x[j] * cis(sign * 2 * M_PI * (double)(j * k % n) / (double)n);
		X[k] = s;
	}
}

static double maxdiff(const double complex *a, const double complex *b, size_t n,
		      double *scale)
{
	double d = 0, s = 0;
	for (size_t i = 0; i < n; i++) {
		if (cabs(a[i] - b[i]) > d)
			d = cabs(a[i] - b[i]);
		if (cabs(b[i]) > s)
			s = cabs(b[i]);
	}
	*scale = s > 0 ? s : 1;
	return d;
}

static double rnd(void)
{
	return (double)rand() / RAND_MAX - 0.5;
}

static void check1(size_t n, int sign)
{
	double complex *x = xreallocarray(NULL, n, sizeof *x);
	double complex *y = xreallocarray(NULL, n, sizeof *y);
	double complex *X = xreallocarray(NULL, n, sizeof *X);
	for (size_t i = 0; i < n; i++)
		x[i] = y[i] = rnd() + I * rnd();
	struct fft_plan *p = fft_plan_new(n, sign), *b = fft_plan_new(n, -sign);
	size_t nw = fft_work_size(p) > fft_work_size(b) ? fft_work_size(p) : fft_work_size(b);
	double complex *w = xreallocarray(NULL, nw, sizeof *w);
	dft(x, X, n, sign);
	fft_exec(p, y, w);
	double s, d = maxdiff(y, X, n, &s);
	if (!(d <= 1e-12 * s) && nfail++ < 20)
		fprintf(stderr, "fft: length %zu sign %d: off the direct DFT by %.3g of %.3g\n",
			n, sign, d, s);
	fft_exec(b, y, w);
	for (size_t i = 0; i < n; i++)
		y[i] /= (double)n;
	d = maxdiff(y, x, n, &s);
	if (!(d <= 1e-12 * s) && nfail++ < 20)
		fprintf(stderr, "fft: length %zu sign %d: round trip off by %.3g\n", n, sign, d);
	fft_plan_free(p);
	fft_plan_free(b);
	free(x);
	free(y);
	free(X);
	free(w);
}

static void check2(size_t nx, size_t ny)
{
	size_t n = nx * ny;
	double complex *a = xreallocarray(NULL, n, sizeof *a);
	double complex *r = xreallocarray(NULL, n, sizeof *r);
	double complex *t = xreallocarray(NULL, nx > ny ? nx : ny, sizeof *t);
	double complex *u = xreallocarray(NULL, nx > ny ? nx : ny, sizeof *u);
	for (size_t i = 0; i < n; i++)
		a[i] = r[i] = rnd() + I * rnd();
	for (size_t j = 0; j < ny; j++) {
		dft(r + j * nx, t, nx, -1);
		for (size_t i = 0; i < nx; i++)
			r[j * nx + i] = t[i];
	}
	for (size_t i = 0; i < nx; i++) {
		for (size_t j = 0; j < ny; j++)
			u[j] = r[j * nx + i];
		dft(u, t, ny, -1);
		for (size_t j = 0; j < ny; j++)
			r[j * nx + i] = t[j];
	}
	struct fft_plan *px = fft_plan_new(nx, -1), *py = fft_plan_new(ny, -1);
	double complex *w = xreallocarray(NULL, fft_work2_size(px, py), sizeof *w);
	fft_exec2(px, py, a, w);
	double s, d = maxdiff(a, r, n, &s);
	if (!(d <= 1e-12 * s) && nfail++ < 20)
		fprintf(stderr, "fft: 2D %zu x %zu: off the direct DFT by %.3g of %.3g\n",
			nx, ny, d, s);
	fft_plan_free(px);
	fft_plan_free(py);
	free(a);
	free(r);
	free(t);
	free(u);
	free(w);
}

int main(void)
{
	util_setprog("fft");
	srand(15);
	static const size_t len[] = {1, 2, 3, 4, 5, 7, 8, 11, 12, 13, 16, 17, 30, 64, 97,
				     100, 128, 143, 194, 243, 800, 1009};
	for (size_t i = 0; i < sizeof len / sizeof *len; i++) {
		check1(len[i], -1);
		check1(len[i], 1);
	}
	check2(30, 97);
	check2(1, 5);
	if (nfail) {
		fprintf(stderr, "fft: %d failures\n", nfail);
		return 1;
	}
	return 0;
}
