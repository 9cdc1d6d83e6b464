/*
 * peb_xy.c - the x-y diffusion of the chemically amplified resist's bake
 * (peb.c): on the periodic window every Fourier mode of a plane is
 * multiplied by its exact heat factor e^{-D kappa^2 t}.  Long periods go
 * through the library's FFT (any length); a period of at most
 * PEB_XY_CIRC_MAX samples is applied as the same operator written as a
 * circulant matrix (its kernel the inverse transform of the factors,
 * computed here directly), p multiply-adds a point, since a short FFT
 * costs mostly its calls: the bake applies this up to a few hundred
 * times, and on examples/car-krf-lines' window (periods 24 and 4) the
 * transforms were a third of the bake.
 */
#include "bleach.h"
#include "fft.h"
#include "par.h"
#include "util.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- x-y diffusion: exact in the Fourier basis, by the library's FFT ---- */

/* The periods here are the window's nx - 1 samples (99 = 3 * 3 * 11 for
 * 100 points), which fft.h takes at any length. */
struct dft {
	struct fft_plan *fwd, *bwd;     /* read-only, shared by the workers */
};

static void dft_init(struct dft *d, int n)
{
	d->fwd = fft_plan_new((size_t)n, -1);
	d->bwd = fft_plan_new((size_t)n, +1);
}

static void dft_free(struct dft *d)
{
	fft_plan_free(d->fwd);
	fft_plan_free(d->bwd);
}

/* work values a worker needs for d */
static size_t dft_work(const struct dft *d)
{
	size_t a = fft_work_size(d->fwd), b = fft_work_size(d->bwd);
	return a > b ? a : b;
}

/* The heat-equation factors e^{-D kappa^2 t} of the p Fourier modes of a
 * period of p samples spacing h, divided by p (the inverse's scale). */
static double *heat_factors(int p, double h, double Dt)
{
	double *g = xreallocarray(NULL, (size_t)p, sizeof *g);
	double L = p * h;
	for (int m = 0; m < p; m++) {
		int mf = m <= p / 2 ? m : m - p;
		double kappa = 2 * M_PI * mf / L;
		g[m] = exp(-Dt * kappa * kappa) / p;
	}
	return g;
}

/* The circulant kernel of the factors g (heat_factors: already over p):
 * c[j] = sum over m of g[m] cos(2 pi m j / p), stored twice over (c2[k]
 * = c[k mod p], k < 2p) so that a row's product needs no index mod p. */
static double *circulant(const double *g, int p)
{
	double *c2 = xreallocarray(NULL, 2 * (size_t)p, sizeof *c2);
	for (int j = 0; j < p; j++) {
		double s = 0;
		for (int m = 0; m < p; m++)
			s += g[m] * cos(2 * M_PI * (double)((long)m * j % p) / p);
		c2[j] = c2[j + p] = s;
	}
	return c2;
}

/* out[i] = sum over i2 < p of c2[i - i2 + p] a[i2], i < p (a circulant
 * product; c2 the kernel stored twice over): four outputs at a time, each
 * its own running sum in the order of i2 (the same sums, value for value,
 * as one output at a time), so that the loop is bound by its loads and
 * not by a store and a reload per multiply-add. */
static void circ_row(const double *c2, int p, const double *a, double *out)
{
	int i = 0;
	for (; i + 4 <= p; i += 4) {
		double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
		const double *c = c2 + i + p;
		for (int i2 = 0; i2 < p; i2++) {
			double v = a[i2];
			s0 += c[-i2] * v;
			s1 += c[1 - i2] * v;
			s2 += c[2 - i2] * v;
			s3 += c[3 - i2] * v;
		}
		out[i] = s0;
		out[i + 1] = s1;
		out[i + 2] = s2;
		out[i + 3] = s3;
	}
	for (; i < p; i++) {
		double s0 = 0;
		for (int i2 = 0; i2 < p; i2++)
			s0 += c2[i - i2 + p] * a[i2];
		out[i] = s0;
	}
}

/* The same along y on whole rows of n values: row j of out = sum over
 * j2 < p of c2[j - j2 + p] row j2 of pl (rows n apart), four values of a
 * row at a time. */
static void circ_rows(const double *c2, int p, const double *pl, int n, double *out)
{
	for (int j = 0; j < p; j++) {
		const double *c = c2 + j + p;
		double *o = out + (size_t)j * n;
		int i = 0;
		for (; i + 4 <= n; i += 4) {
			double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
			for (int j2 = 0; j2 < p; j2++) {
				const double *r = pl + (size_t)j2 * n + i;
				double cc = c[-j2];
				s0 += cc * r[0];
				s1 += cc * r[1];
				s2 += cc * r[2];
				s3 += cc * r[3];
			}
			o[i] = s0;
			o[i + 1] = s1;
			o[i + 2] = s2;
			o[i + 3] = s3;
		}
		for (; i < n; i++) {
			double s0 = 0;
			for (int j2 = 0; j2 < p; j2++)
				s0 += c[-j2] * pl[(size_t)j2 * n + i];
			o[i] = s0;
		}
	}
}

struct xy_pass {
	double *f;
	int nx, ny;
	const double *gx, *gy;          /* NULL: that direction is not done */
	const double *cx, *cy;          /* circulant kernels, or NULL: by FFT */
	double *tmp;                    /* per worker: max(nx, py nx) */
	struct dft dx, dy;
	double complex *row;            /* per worker: max(px, py) */
	double complex *work;           /* per worker: nwork */
	size_t nwork;
};

/* Two real rows at once as the real and imaginary parts of one complex
 * row: the factors are real and even in the wavenumber, so the two never
 * mix. */
static void xy_planes(void *ctx, size_t lo, size_t hi, int worker)
{
	struct xy_pass *x = ctx;
	int nx = x->nx, ny = x->ny, px = nx - 1, py = ny - 1;
	double complex *z = x->row + (size_t)worker * (size_t)(px > py ? px : py);
	double complex *w = x->work + (size_t)worker * x->nwork;
	double *t = x->tmp + (size_t)worker * (size_t)(py > 1 ? py : 1) * nx;
	for (size_t k = lo; k < hi; k++) {
		double *pl = x->f + k * (size_t)nx * ny;
		if (x->cx)
			for (int j = 0; j < ny; j++) {
				/* out[i] = sum over i2 of c[(i - i2) mod px] a[i2] */
				double *a = pl + (size_t)j * nx;
				circ_row(x->cx, px, a, t);
				memcpy(a, t, (size_t)px * sizeof *t);
				a[px] = a[0];
			}
		else if (x->gx)
			for (int j = 0; j < ny; j += 2) {
				double *a = pl + (size_t)j * nx;
				double *b = j + 1 < ny ? a + nx : NULL;
				for (int i = 0; i < px; i++)
					z[i] = a[i] + I * (b ? b[i] : 0);
				fft_exec(x->dx.fwd, z, w);
				for (int i = 0; i < px; i++)
					z[i] *= x->gx[i];
				fft_exec(x->dx.bwd, z, w);
				for (int i = 0; i < px; i++) {
					a[i] = creal(z[i]);
					if (b)
						b[i] = cimag(z[i]);
				}
				a[px] = a[0];
				if (b)
					b[px] = b[0];
			}
		if (x->cy) {
			/* row j = sum over j2 of c[(j - j2) mod py] row j2, whole rows */
			circ_rows(x->cy, py, pl, nx, t);
			memcpy(pl, t, (size_t)py * nx * sizeof *t);
			memcpy(pl + (size_t)py * nx, pl, (size_t)nx * sizeof *t);
		} else if (x->gy)
			for (int i = 0; i < nx; i += 2) {
				int i2 = i + 1 < nx ? i + 1 : -1;
				for (int j = 0; j < py; j++)
					z[j] = pl[(size_t)j * nx + i] + I * (i2 >= 0 ? pl[(size_t)j * nx + i2] : 0);
				fft_exec(x->dy.fwd, z, w);
				for (int j = 0; j < py; j++)
					z[j] *= x->gy[j];
				fft_exec(x->dy.bwd, z, w);
				for (int j = 0; j < py; j++) {
					pl[(size_t)j * nx + i] = creal(z[j]);
					if (i2 >= 0)
						pl[(size_t)j * nx + i2] = cimag(z[j]);
				}
				pl[(size_t)py * nx + i] = pl[i];
				if (i2 >= 0)
					pl[(size_t)py * nx + i2] = pl[i2];
			}
	}
}

/* f (nz planes of nx * ny, periodic with the last node repeating the
 * first) after diffusing D for t in x and y: each Fourier mode times
 * e^{-D kappa^2 t}, exactly. */
void peb_diffuse_xy(double *f, int nx, int ny, int nz, double hx, double hy, double D, double t)
{
	int px = nx - 1, py = ny - 1;
	if (!(D > 0) || !(t > 0) || (px < 2 && py < 2))
		return;
	int nw = par_threads();
	struct xy_pass x = {f, nx, ny, px >= 2 ? heat_factors(px, hx, D * t) : NULL,
			    py >= 2 ? heat_factors(py, hy, D * t) : NULL, NULL, NULL, NULL,
			    {NULL, NULL}, {NULL, NULL},
			    xreallocarray(NULL, (size_t)nw * (size_t)(px > py ? px : py),
					  sizeof(double complex)), NULL, 0};
	if (x.gx && px <= PEB_XY_CIRC_MAX)
		x.cx = circulant(x.gx, px);
	if (x.gy && py <= PEB_XY_CIRC_MAX)
		x.cy = circulant(x.gy, py);
	x.tmp = xreallocarray(NULL, (size_t)nw * (size_t)(py > 1 ? py : 1), (size_t)nx * sizeof *x.tmp);
	if (x.gx && !x.cx) {
		dft_init(&x.dx, px);
		x.nwork = dft_work(&x.dx);
	}
	if (x.gy && !x.cy) {
		dft_init(&x.dy, py);
		if (dft_work(&x.dy) > x.nwork)
			x.nwork = dft_work(&x.dy);
	}
	x.work = xreallocarray(NULL, (size_t)nw * (x.nwork ? x.nwork : 1), sizeof(double complex));
	par_for((size_t)nz, 1, xy_planes, &x);
	if (x.gx && !x.cx)
		dft_free(&x.dx);
	if (x.gy && !x.cy)
		dft_free(&x.dy);
	free(x.tmp);
	free((void *)x.cx);
	free((void *)x.cy);
	free(x.work);
	free(x.row);
	free((void *)x.gx);
	free((void *)x.gy);
}

