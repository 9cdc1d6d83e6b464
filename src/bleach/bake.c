/*
 * bake.c - the post-exposure bake (thesis 8.6, Figure 8.17): the PAC
 * diffuses, which smooths M by a Gaussian whose standard deviation is the
 * diffusion length sqrt(2 D t).  The thesis smoothed in z only ("bake");
 * "bake3d" smooths in x and y too.
 *
 * Smoothing is done exactly in the cosine/Fourier basis of the grid:
 * the heat equation multiplies a mode of wavenumber kappa by
 * exp(-sigma^2 kappa^2 / 2).  In z the modes are cosines (DCT-I: no flux
 * through the resist top nor the substrate, and the trapezoidal total of
 * M is conserved exactly); in x and y they are the Fourier modes of the
 * periodic splat window.  Each is written as a small dense matrix, built
 * once and applied along its axis.  The grids are short (nz ~ 300,
 * nx ~ 50), so a matrix is both simpler and, vectorised, faster than an
 * FFT of awkward length.  main.c smooths the dose table's rows in z
 * rather than the full array: z smoothing is linear and commutes with
 * the interpolation over dose, so it costs one table, not every column.
 */
#include "bleach.h"
#include "par.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

double *bake_matrix_neumann(int n, double d, double sigma)
{
	size_t nn = (size_t)n;
	double *S = xcalloc(nn * nn, sizeof *S);
	if (n == 1) {
		S[0] = 1;
		return S;
	}
	int N1 = n - 1, per = 2 * N1;
	double L = N1 * d;
	/* cos(pi q / N1) for q mod 2 N1 */
	double *c = xreallocarray(NULL, (size_t)per, sizeof *c);
	for (int q = 0; q < per; q++)
		c[q] = cos(M_PI * q / N1);
	double *g = xreallocarray(NULL, nn, sizeof *g);
	for (int m = 0; m < n; m++) {
		double kappa = M_PI * m / L;
		double w = (m == 0 || m == N1) ? 0.5 : 1.0;
		g[m] = w * exp(-0.5 * sigma * sigma * kappa * kappa) * 2.0 / N1;
	}
	/* S[j][l] = (2/N1) sum_m w_m g_m cos(pi m j/N1) w_l cos(pi m l/N1) */
	for (int j = 0; j < n; j++) {
		for (int l = j; l < n; l++) {
			double s = 0;
			int qj = 0, ql = 0;     /* m j and m l, mod 2 N1 */
			for (int m = 0; m < n; m++) {
				if (g[m] == 0)
					break;  /* modes beyond underflow contribute nothing */
				s += g[m] * c[qj] * c[ql];
				qj += j;
				if (qj >= per)
					qj -= per;
				ql += l;
				if (ql >= per)
					ql -= per;
			}
			S[(size_t)j * nn + l] = s;
			S[(size_t)l * nn + j] = s;
		}
	}
	/* the end weight w_l on the column: conservation of the trapezoid */
	for (int j = 0; j < n; j++) {
		S[(size_t)j * nn] *= 0.5;
		S[(size_t)j * nn + N1] *= 0.5;
	}
	free(c);
	free(g);
	return S;
}

double *bake_matrix_periodic(int p, double d, double sigma)
{
	size_t pp = (size_t)p;
	double *S = xcalloc(pp * pp, sizeof *S);
	double L = p * d;
	double *row = xcalloc(pp, sizeof *row);
	/* circulant: row[q] = (1/p) sum_m g(m) cos(2 pi m q / p), m folded
	 * into (-p/2, p/2] so that each mode has its true wavenumber */
	for (int q = 0; q < p; q++) {
		double s = 0;
		for (int m = 0; m < p; m++) {
			int mf = m <= p / 2 ? m : m - p;
			double kappa = 2 * M_PI * mf / L;
			double gm = exp(-0.5 * sigma * sigma * kappa * kappa);
			s += gm * cos(2 * M_PI * (double)((long)m * q % p) / p);
		}
		row[q] = s / p;
	}
	for (int i = 0; i < p; i++)
		for (int l = 0; l < p; l++)
			S[(size_t)i * pp + l] = row[((i - l) % p + p) % p];
	free(row);
	return S;
}

void bake_apply(const double *S, int n, double *v, size_t stride, double *work)
{
	for (int i = 0; i < n; i++) {
		const double *r = S + (size_t)i * (size_t)n;
		double s = 0;
		for (int l = 0; l < n; l++)
			s += r[l] * v[(size_t)l * stride];
		work[i] = s;
	}
	for (int i = 0; i < n; i++)
		v[(size_t)i * stride] = work[i];
}

void bake_rows(double *rows, int nrows, int n, double d, double sigma)
{
	bake_rows2(rows, NULL, nrows, n, d, sigma);
}

void bake_rows2(double *a, double *b, int nrows, int n, double d, double sigma)
{
	double *S = bake_matrix_neumann(n, d, sigma);
	double *w = xreallocarray(NULL, (size_t)n, sizeof *w);
	for (int r = 0; r < nrows; r++) {
		bake_apply(S, n, a + (size_t)r * n, 1, w);
		if (b)
			bake_apply(S, n, b + (size_t)r * n, 1, w);
	}
	free(w);
	free(S);
}

/* The circulant row of bake_matrix_periodic cut to the taps that
 * matter: c[o + hw] for offsets o in [-hw, hw].  A Gaussian of sigma
 * 0.08 um on a 0.1 um grid needs 15 taps, not the 50 of a full row;
 * dropped taps are below BAKE_TAP_CUT of the centre one, so the result
 * moves by less than rounding. */
#define BAKE_TAP_CUT 1e-17

static double *taps(int p, double d, double sigma, int *hw)
{
	double *S = bake_matrix_periodic(p, d, sigma);
	int h = p / 2;
	while (h > 0 && fabs(S[h]) < BAKE_TAP_CUT * S[0] &&
	       fabs(S[(p - h) % p]) < BAKE_TAP_CUT * S[0])
		h--;
	if (2 * h + 1 > p) {
		/* the whole period: keep every tap exactly once */
		h = p / 2;
	}
	double *c = xcalloc((size_t)(2 * h + 1), sizeof *c);
	for (int o = -h; o <= h; o++) {
		/* for even p and h = p/2, offsets +h and -h are one tap */
		if (2 * h == p && o == h)
			continue;
		c[o + h] = S[(size_t)((o % p + p) % p)];
	}
	free(S);
	*hw = h;
	return c;
}

/* The x pass of bake_xy on rows [lo, hi) of nx points (period px),
 * with per-worker scratch: each row depends only on itself. */
struct xpass {
	double *f;
	int nx, px, h;
	const double *c;
	double *scratch;                /* per worker: px + 2h, then px */
};

static void bake_x_rows(void *ctx, size_t lo, size_t hi, int worker)
{
	struct xpass *x = ctx;
	int px = x->px, h = x->h;
	double *ext = x->scratch + (size_t)worker * (2 * (size_t)px + 2 * (size_t)h);
	double *w = ext + (size_t)px + 2 * (size_t)h;
	/* the row wrapped h samples on either side, so that the taps run over
	 * contiguous memory */
	for (size_t r = lo; r < hi; r++) {
		double *row = x->f + r * (size_t)x->nx;
		for (int i = -h; i < px + h; i++)
			ext[i + h] = row[((i % px) + px) % px];
		memset(w, 0, (size_t)px * sizeof *w);
		for (int o = 0; o <= 2 * h; o++) {
			const double *e = ext + o;
			double co = x->c[o];
			for (int i = 0; i < px; i++)
				w[i] += co * e[i];
		}
		memcpy(row, w, (size_t)px * sizeof *w);
		row[px] = row[0];
	}
}

/* The y pass on planes [lo, hi): whole rows at once, so the inner loop
 * runs along x, contiguous. */
struct ypass {
	double *f;
	int nx, py, h;
	const double *c;
	double *scratch;                /* per worker: py * nx */
};

static void bake_y_planes(void *ctx, size_t lo, size_t hi, int worker)
{
	struct ypass *y = ctx;
	int nx = y->nx, py = y->py, h = y->h;
	size_t plane = (size_t)nx * (size_t)(py + 1);
	double *w = y->scratch + (size_t)worker * (size_t)py * (size_t)nx;
	for (size_t k = lo; k < hi; k++) {
		double *p = y->f + k * plane;
		memset(w, 0, (size_t)py * nx * sizeof *w);
		for (int j = 0; j < py; j++) {
			double *o = w + (size_t)j * nx;
			for (int q = 0; q <= 2 * h; q++) {
				int l = ((j + q - h) % py + py) % py;
				const double *in = p + (size_t)l * nx;
				double s = y->c[q];
				for (int i = 0; i < nx; i++)
					o[i] += s * in[i];
			}
		}
		memcpy(p, w, (size_t)py * nx * sizeof *w);
		memcpy(p + (size_t)py * nx, p, (size_t)nx * sizeof *p);
	}
}

void bake_xy(double *f, int nx, int ny, int nz, double dx, double dy, double sigma)
{
	int px = nx - 1, py = ny - 1;
	size_t nw = (size_t)par_threads();
	if (bake_iir_wanted(px, dx, sigma)) {
		bake_iir_x(f, nx, ny, nz, dx, sigma);
	} else if (px >= 2) {
		int h;
		double *c = taps(px, dx, sigma, &h);
		struct xpass x = {f, nx, px, h, c,
				  xcalloc(nw * (2 * (size_t)px + 2 * (size_t)h), sizeof(double))};
		par_for((size_t)nz * ny, 16, bake_x_rows, &x);
		free(x.scratch);
		free(c);
	}
	if (bake_iir_wanted(py, dy, sigma)) {
		bake_iir_y(f, nx, ny, nz, dy, sigma);
	} else if (py >= 2) {
		int h;
		double *c = taps(py, dy, sigma, &h);
		struct ypass y = {f, nx, py, h, c,
				  xreallocarray(NULL, nw * (size_t)py, (size_t)nx * sizeof(double))};
		par_for((size_t)nz, 1, bake_y_planes, &y);
		free(y.scratch);
		free(c);
	}
}

/* Columns smoothed together: the block's rows are contiguous, so the inner
 * loops run along memory and vectorise. */
#define BAKE_Z_BLOCK 256
/* Cosine modes whose Gaussian factor falls below this are dropped: they
 * move M by less than rounding.  A 0.08 um bake in 0.7 um of resist keeps
 * 25 of 300 modes, which makes the smoothing of the whole array cheap. */
#define BAKE_MODE_CUT 1e-17

void bake_z_columns(double *f, size_t ncol, int nz, double dz, double sigma)
{
	if (nz < 2)
		return;
	/* the DCT-I form of bake_matrix_neumann: S[j][l] = sum_m g_m
	 * cos(pi m j/N1) cos(pi m l/N1) e_l (e_l = 1/2 at the ends), taken as
	 * a projection on the modes kept and back, 2 nz nm products a column
	 * instead of nz^2.  It is symmetric under k -> nz - 1 - k, so the rate
	 * file's upward planes take it as the downward nodes do. */
	int N1 = nz - 1, per = 2 * N1;
	double L = N1 * dz;
	int nm = 0;
	while (nm < nz && exp(-0.5 * sigma * sigma * (M_PI * nm / L) * (M_PI * nm / L)) >= BAKE_MODE_CUT)
		nm++;
	size_t n = (size_t)nz, m = (size_t)nm;
	double *cs = xreallocarray(NULL, m * n, sizeof *cs);     /* cos(pi m l/N1) */
	double *g = xreallocarray(NULL, m, sizeof *g);
	for (int k = 0; k < nm; k++) {
		double kappa = M_PI * k / L, w = (k == 0 || k == N1) ? 0.5 : 1.0;
		g[k] = w * exp(-0.5 * sigma * sigma * kappa * kappa) * 2.0 / N1;
		for (int l = 0; l < nz; l++)
			cs[(size_t)k * n + l] = cos(M_PI * (double)((long)k * l % per) / N1);
	}
	double *in = xreallocarray(NULL, n * BAKE_Z_BLOCK, sizeof *in);
	double *a = xreallocarray(NULL, m * BAKE_Z_BLOCK, sizeof *a);
	for (size_t q0 = 0; q0 < ncol; q0 += BAKE_Z_BLOCK) {
		size_t b = ncol - q0 < BAKE_Z_BLOCK ? ncol - q0 : BAKE_Z_BLOCK;
		for (size_t l = 0; l < n; l++) {
			double e = (l == 0 || l == n - 1) ? 0.5 : 1.0;
			const double *src = f + l * ncol + q0;
			double *dst = in + l * b;
			for (size_t i = 0; i < b; i++)
				dst[i] = e * src[i];
		}
		for (size_t k = 0; k < m; k++) {
			double *ak = a + k * b;
			const double *c = cs + k * n;
			memset(ak, 0, b * sizeof *ak);
			for (size_t l = 0; l < n; l++) {
				const double *v = in + l * b;
				double s = c[l];
				for (size_t i = 0; i < b; i++)
					ak[i] += s * v[i];
			}
			for (size_t i = 0; i < b; i++)
				ak[i] *= g[k];
		}
		for (size_t j = 0; j < n; j++) {
			double *o = f + j * ncol + q0;
			memset(o, 0, b * sizeof *o);
			for (size_t k = 0; k < m; k++) {
				const double *ak = a + k * b;
				double s = cs[k * n + j];
				for (size_t i = 0; i < b; i++)
					o[i] += s * ak[i];
			}
		}
	}
	free(in);
	free(a);
	free(cs);
	free(g);
}
