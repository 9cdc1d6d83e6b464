/*
 * peb_xy.c - the x-y diffusion of the chemically amplified resist's bake
 * (peb.c): on the periodic window every Fourier mode of a plane is
 * multiplied by its exact heat factor e^{-D kappa^2 t}.  Long periods go
 * through the library's FFT (any length); a period of at most
 * PEB_XY_CIRC_MAX samples is applied as the same operator written as a
 * circulant matrix (its kernel the inverse transform of the factors,
 * computed here directly), p additions and p / 2 + 1 multiplications a
 * point (the kernel is even), since a short FFT
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
 * c[j] = sum over m of g[m] cos(2 pi m j / p), j <= p / 2 (the rest by
 * symmetry, circ_row). */
static double *circulant(const double *g, int p)
{
	double *c = xreallocarray(NULL, (size_t)p / 2 + 1, sizeof *c);
	for (int j = 0; j <= p / 2; j++) {
		double s = 0;
		for (int m = 0; m < p; m++)
			s += g[m] * cos(2 * M_PI * (double)((long)m * j % p) / p);
		c[j] = s;
	}
	return c;
}

/* The kernel is even (c[k] = c[p - k], the factors are even in the
 * wavenumber), so a product takes the two values k either side of an
 * output together, c[k] (a[i - k] + a[i + k]) for k = 1 .. (p - 1) / 2,
 * and for even p the one value p / 2 away once: half the multiplies of
 * the plain sum.  Indices wrap modulo p. */

/* out[i] = sum over k of c[k] a[(i - k) mod p], i < p: a copied with
 * h = p / 2 values wrapped on either side (ext: p + 2 h values), four
 * outputs at a time, each its own running sum. */
static void circ_row(const double *c, int p, const double *a, double *out, double *ext)
{
	int h = p / 2, odd = p % 2;
	memcpy(ext, a + p - h, (size_t)h * sizeof *ext);
	memcpy(ext + h, a, (size_t)p * sizeof *ext);
	memcpy(ext + h + p, a, (size_t)h * sizeof *ext);
	const double *e = ext + h;
	int kmax = odd ? h : h - 1;
	int i = 0;
	for (; i + 4 <= p; i += 4) {
		double s0 = c[0] * e[i], s1 = c[0] * e[i + 1], s2 = c[0] * e[i + 2], s3 = c[0] * e[i + 3];
		for (int k = 1; k <= kmax; k++) {
			double ck = c[k];
			s0 += ck * (e[i - k] + e[i + k]);
			s1 += ck * (e[i + 1 - k] + e[i + 1 + k]);
			s2 += ck * (e[i + 2 - k] + e[i + 2 + k]);
			s3 += ck * (e[i + 3 - k] + e[i + 3 + k]);
		}
		if (!odd) {
			double ch = c[h];
			s0 += ch * e[i + h];
			s1 += ch * e[i + 1 + h];
			s2 += ch * e[i + 2 + h];
			s3 += ch * e[i + 3 + h];
		}
		out[i] = s0;
		out[i + 1] = s1;
		out[i + 2] = s2;
		out[i + 3] = s3;
	}
	for (; i < p; i++) {
		double s0 = c[0] * e[i];
		for (int k = 1; k <= kmax; k++)
			s0 += c[k] * (e[i - k] + e[i + k]);
		if (!odd)
			s0 += c[h] * e[i + h];
		out[i] = s0;
	}
}

/* The same along y on whole rows of n values: row j of out = sum over k
 * of c[k] row (j - k) mod p of pl (rows n apart), four values of a row
 * at a time, each its own running sum over k. */
static void circ_rows(const double *c, int p, const double *pl, int n, double *out)
{
	int h = p / 2, odd = p % 2, kmax = odd ? h : h - 1;
	for (int j = 0; j < p; j++) {
		const double *r0 = pl + (size_t)j * n;
		double *o = out + (size_t)j * n;
		/* the rows k before and after j, and p / 2 away for even p */
		int jh = j + h < p ? j + h : j + h - p;
		const double *rh = pl + (size_t)jh * n;
		int i = 0;
		for (; i + 4 <= n; i += 4) {
			double s0 = c[0] * r0[i], s1 = c[0] * r0[i + 1];
			double s2 = c[0] * r0[i + 2], s3 = c[0] * r0[i + 3];
			for (int k = 1; k <= kmax; k++) {
				int jm = j - k >= 0 ? j - k : j - k + p, jp = j + k < p ? j + k : j + k - p;
				const double *rm = pl + (size_t)jm * n + i, *rp = pl + (size_t)jp * n + i;
				double ck = c[k];
				s0 += ck * (rm[0] + rp[0]);
				s1 += ck * (rm[1] + rp[1]);
				s2 += ck * (rm[2] + rp[2]);
				s3 += ck * (rm[3] + rp[3]);
			}
			if (!odd) {
				s0 += c[h] * rh[i];
				s1 += c[h] * rh[i + 1];
				s2 += c[h] * rh[i + 2];
				s3 += c[h] * rh[i + 3];
			}
			o[i] = s0;
			o[i + 1] = s1;
			o[i + 2] = s2;
			o[i + 3] = s3;
		}
		for (; i < n; i++) {
			double s0 = c[0] * r0[i];
			for (int k = 1; k <= kmax; k++) {
				int jm = j - k >= 0 ? j - k : j - k + p, jp = j + k < p ? j + k : j + k - p;
				s0 += c[k] * (pl[(size_t)jm * n + i] + pl[(size_t)jp * n + i]);
			}
			if (!odd)
				s0 += c[h] * rh[i];
			o[i] = s0;
		}
	}
}

/* scratch values a worker needs: a plane's product along y (py rows), or
 * a row's along x and circ_row's wrapped copy (3 nx) */
#define XY_TMP(nx, ny) ((size_t)((ny) - 1 > 1 ? (ny) - 1 : 1) * (size_t)(nx) + 2 * (size_t)(nx))

struct xy_pass {
	double *f;
	int nx, ny;
	const double *gx, *gy;          /* NULL: that direction is not done */
	const double *cx, *cy;          /* circulant kernels, or NULL: by FFT */
	double *tmp;                    /* per worker: XY_TMP(nx, ny) */
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
	double *t = x->tmp + (size_t)worker * XY_TMP(nx, ny);
	for (size_t k = lo; k < hi; k++) {
		double *pl = x->f + k * (size_t)nx * ny;
		if (x->cx)
			for (int j = 0; j < ny; j++) {
				/* out[i] = sum over i2 of c[(i - i2) mod px] a[i2] */
				double *a = pl + (size_t)j * nx;
				circ_row(x->cx, px, a, t, t + nx);
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
	x.tmp = xreallocarray(NULL, (size_t)nw, XY_TMP(nx, ny) * sizeof *x.tmp);
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

