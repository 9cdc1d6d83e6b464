/*
 * bake_iir.c - the x-y bake of a fine grid by a recursive Gaussian.
 *
 * bake.c smooths x and y with the exact periodic heat kernel cut to the
 * taps that matter: about 17 sigma / dx taps a point.  On a fine grid
 * (a 5 um window on 2048 points, sigma 0.08 um: 561 taps) that is the
 * whole cost of bleach.  Here the Gaussian is instead the fourth-order
 * sum of damped cosines of R. Deriche ("Recursively implementing the
 * Gaussian and its derivatives", INRIA RR-1893, 1993):
 *
 *   g(n) ~ (a0 cos(w0 n/s) + a1 sin(w0 n/s)) exp(-b0 n/s)
 *        + (c0 cos(w1 n/s) + c1 sin(w1 n/s)) exp(-b1 n/s),   n >= 0,
 *
 * s = sigma in samples, run as a causal filter (lags 0, 1, ...) plus an
 * anti-causal one (lags -1, -2, ...), both fourth order: about 32 flops
 * a point whatever sigma.  The recursion coefficients are derived here
 * from the four complex poles exp((-b +- i w)/s) rather than typed in,
 * and the pair is normalised to unit sum (the mean of M is kept).  The
 * periodic window is handled by running the recursion over the row
 * wrapped W = 23 s samples on either side, long enough that the start
 * transient has decayed below 1e-17.
 *
 * The approximation differs from the exact Gaussian by a few 1e-4 of the
 * field's range (tests/bleach/bake.c states the bound); bake_xy uses it
 * only where the exact taps would be many (BAKE_IIR_TAPS), so small
 * grids, and every example up to now, keep their exact bake.  Every row
 * and block is independent: the result is the same for any thread count.
 */
#include "bleach.h"
#include "par.h"
#include "util.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Deriche's fit of the Gaussian (RR-1893, Table 1). */
static const double A0 = 1.680, A1 = 3.735, B0 = 1.783, B1 = 1.723,
		    W0 = 0.6318, W1 = 1.997, C0 = -0.6803, C1 = -0.2598;

struct iir {
	double n[4];            /* causal numerator, lags 0..3 */
	double m[5];            /* anti-causal numerator, leads 1..4 (m[0] = 0) */
	double d[5];            /* denominator, d[0] = 1 */
	int W;                  /* wrap margin, samples */
};

/* Coefficients of prod (1 - z_j u) over the poles j != skip, degree up
 * to 4, into p[0..4]. */
static void poly_poles(const double complex z[4], int skip, double complex p[5])
{
	for (int i = 0; i < 5; i++)
		p[i] = 0;
	p[0] = 1;
	int deg = 0;
	for (int j = 0; j < 4; j++) {
		if (j == skip)
			continue;
		for (int i = deg + 1; i >= 1; i--)
			p[i] -= z[j] * p[i - 1];
		deg++;
	}
}

static void iir_init(struct iir *f, double s)
{
	double complex z[4] = {
		cexp((-B0 + I * W0) / s), cexp((-B0 - I * W0) / s),
		cexp((-B1 + I * W1) / s), cexp((-B1 - I * W1) / s)};
	/* g(n) = sum alpha_k z_k^n: a cos + b sin = Re((a - i b) e^{i t}) */
	double complex al[4] = {(A0 - I * A1) / 2, (A0 + I * A1) / 2,
				(C0 - I * C1) / 2, (C0 + I * C1) / 2};
	double complex D[5], N[5] = {0, 0, 0, 0, 0}, P[5];
	poly_poles(z, -1, D);
	for (int k = 0; k < 4; k++) {
		poly_poles(z, k, P);
		for (int i = 0; i < 4; i++)
			N[i] += al[k] * P[i];
	}
	double g0 = A0 + C0;    /* g(0) */
	double d[5], n[5], m[5], sd = 0, sn = 0, sm = 0;
	for (int i = 0; i < 5; i++) {
		d[i] = creal(D[i]);
		n[i] = creal(N[i]);
		/* lags >= 1: sum alpha_k z_k u / (1 - z_k u) = N - g(0) D */
		m[i] = n[i] - g0 * d[i];
		sd += d[i], sn += n[i], sm += m[i];
	}
	/* unit sum: (N(1) + M(1)) / D(1) */
	double scale = sd / (sn + sm);
	for (int i = 0; i < 5; i++) {
		f->d[i] = d[i];
		f->m[i] = m[i] * scale;
		if (i < 4)
			f->n[i] = n[i] * scale;
	}
	f->m[0] = 0;
	/* the slowest decay is exp(-B1 n / s): 1e-17 after 39.1 s / B1 */
	f->W = (int)ceil(39.2 * s / B1);
}

/* Smooths L samples of w interleaved lanes (x[e * w + l]), the recursion
 * running along e, into y (same layout); t is L * w scratch. */
static void iir_run(const struct iir *f, const double *x, double *y, double *t, int L, int w)
{
	size_t sw = (size_t)w;
	const double n0 = f->n[0], n1 = f->n[1], n2 = f->n[2], n3 = f->n[3];
	const double m1 = f->m[1], m2 = f->m[2], m3 = f->m[3], m4 = f->m[4];
	const double d1 = f->d[1], d2 = f->d[2], d3 = f->d[3], d4 = f->d[4];
	/* causal: t[e] = n0 x[e] + ... + n3 x[e-3] - d1 t[e-1] - ... - d4 t[e-4] */
	for (int e = 0; e < L; e++) {
		const double *x0 = x + (size_t)e * sw;
		double *t0 = t + (size_t)e * sw;
		if (e >= 4) {
			const double *x1 = x0 - sw, *x2 = x1 - sw, *x3 = x2 - sw;
			const double *t1 = t0 - sw, *t2 = t1 - sw, *t3 = t2 - sw, *t4 = t3 - sw;
			for (size_t l = 0; l < sw; l++)
				t0[l] = n0 * x0[l] + n1 * x1[l] + n2 * x2[l] + n3 * x3[l] -
					d1 * t1[l] - d2 * t2[l] - d3 * t3[l] - d4 * t4[l];
		} else {
			for (size_t l = 0; l < sw; l++) {
				double s = 0;
				for (int q = 0; q <= 3 && q <= e; q++)
					s += f->n[q] * x[(size_t)(e - q) * sw + l];
				for (int q = 1; q <= 4 && q <= e; q++)
					s -= f->d[q] * t[(size_t)(e - q) * sw + l];
				t0[l] = s;
			}
		}
	}
	/* anti-causal into y: y[e] = m1 x[e+1] + ... + m4 x[e+4] - d1 y[e+1] - ...,
	 * then y += t */
	for (int e = L - 1; e >= 0; e--) {
		double *y0 = y + (size_t)e * sw;
		if (e + 4 < L) {
			const double *x1 = x + (size_t)(e + 1) * sw, *x2 = x1 + sw, *x3 = x2 + sw,
				     *x4 = x3 + sw;
			const double *y1 = y0 + sw, *y2 = y1 + sw, *y3 = y2 + sw, *y4 = y3 + sw;
			for (size_t l = 0; l < sw; l++)
				y0[l] = m1 * x1[l] + m2 * x2[l] + m3 * x3[l] + m4 * x4[l] -
					d1 * y1[l] - d2 * y2[l] - d3 * y3[l] - d4 * y4[l];
		} else {
			for (size_t l = 0; l < sw; l++) {
				double s = 0;
				for (int q = 1; q <= 4 && e + q < L; q++)
					s += f->m[q] * x[(size_t)(e + q) * sw + l] -
					     f->d[q] * y[(size_t)(e + q) * sw + l];
				y0[l] = s;
			}
		}
	}
	size_t all = (size_t)L * sw;
	for (size_t i = 0; i < all; i++)
		y[i] += t[i];
}

/* Lanes smoothed together: rows of the x pass, columns of the y pass. */
#define IIR_LANES 16

/* One pass: p samples (a period) of lanes at stride 'step' apart along
 * the recursion, lane l at offset l * lstride; nlanes lanes per plane. */
struct pass {
	const struct iir *f;
	double *a;
	int nx, ny, p;          /* the grid; the period along the pass */
	int along_x;
	size_t nblocks;         /* blocks of IIR_LANES lanes per plane */
	size_t plane;
	double *scratch;        /* per worker: 3 (p + 2W) IIR_LANES */
};

static void pass_blocks(void *ctx, size_t lo, size_t hi, int worker)
{
	struct pass *ps = ctx;
	int p = ps->p, W = ps->f->W, L = p + 2 * W;
	size_t per = (size_t)L * IIR_LANES;
	double *x = ps->scratch + (size_t)worker * 3 * per, *y = x + per, *t = y + per;
	int nlanes = ps->along_x ? ps->ny : ps->nx;
	for (size_t b = lo; b < hi; b++) {
		size_t k = b / ps->nblocks;
		int l0 = (int)(b % ps->nblocks) * IIR_LANES;
		int w = nlanes - l0 < IIR_LANES ? nlanes - l0 : IIR_LANES;
		double *pl = ps->a + k * ps->plane;
		/* sample e of the wrapped run is grid index (e - W) mod p */
		size_t step = ps->along_x ? 1 : (size_t)ps->nx;
		size_t lstride = ps->along_x ? (size_t)ps->nx : 1;
		for (int e = 0; e < L; e++) {
			int g = ((e - W) % p + p) % p;
			const double *src = pl + (size_t)g * step + (size_t)l0 * lstride;
			double *dst = x + (size_t)e * (size_t)w;
			for (int l = 0; l < w; l++)
				dst[l] = src[(size_t)l * lstride];
		}
		iir_run(ps->f, x, y, t, L, w);
		for (int g = 0; g <= p; g++) {
			/* index p is the periodic copy of 0 */
			const double *src = y + (size_t)((g % p) + W) * (size_t)w;
			double *dst = pl + (size_t)g * step + (size_t)l0 * lstride;
			for (int l = 0; l < w; l++)
				dst[(size_t)l * lstride] = src[l];
		}
	}
}

int bake_iir_wanted(int p, double d, double sigma)
{
	double s = sigma / d;
	/* the exact taps number about 17 s (at most the period p); below
	 * BAKE_IIR_TAPS they are as cheap, and exact.  Deriche's fit wants s
	 * of a few samples. */
	return p >= 2 && s >= 4 && 17 * s > BAKE_IIR_TAPS && 17 * s < p;
}

/* The pass along x (along_x 1: rows of period nx - 1) or along y (0:
 * columns of period ny - 1) of every plane, IIR_LANES lines at a time. */
static void iir_axis(double *f, int nx, int ny, int nz, double h, double sigma, int along_x)
{
	struct iir c;
	iir_init(&c, sigma / h);
	int p = (along_x ? nx : ny) - 1;
	size_t nb = ((size_t)(along_x ? ny : nx) + IIR_LANES - 1) / IIR_LANES;
	size_t per = 3 * (size_t)(p + 2 * c.W) * IIR_LANES;
	struct pass ps = {&c, f, nx, ny, p, along_x, nb, (size_t)nx * (size_t)ny,
			  xreallocarray(NULL, (size_t)par_threads() * per, sizeof(double))};
	par_for((size_t)nz * nb, 1, pass_blocks, &ps);
	free(ps.scratch);
}

void bake_iir_x(double *f, int nx, int ny, int nz, double dx, double sigma)
{
	iir_axis(f, nx, ny, nz, dx, sigma, 1);
}

void bake_iir_y(double *f, int nx, int ny, int nz, double dy, double sigma)
{
	iir_axis(f, nx, ny, nz, dy, sigma, 0);
}
