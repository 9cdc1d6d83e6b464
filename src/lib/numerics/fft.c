/*
 * fft.c - see fft.h.  The mixed-radix transform is the recursive
 * decimation in time: a length n = p m splits into p interleaved
 * subsequences of length m (x[q + p j]), each transformed into its own
 * block of the output, then combined by n/p butterflies of radix p,
 *   X[u + m q1] = sum_q Y_q[u] w^(q (u + m q1)),  w = exp(sign 2 pi i / n).
 * The twiddles come from one table of n values computed with cos and sin
 * of the exact angle (no recurrence, so no growth of rounding with n).
 *
 * Bluestein: with jk = (j^2 + k^2 - (k - j)^2) / 2 and
 * c_j = exp(sign pi i j^2 / n),
 *   X[k] = c_k sum_j (x_j c_j) conj(c_{k-j}),
 * a convolution done by power-of-two transforms of length m >= 2n - 1;
 * the transform of conj(c) is made with the plan.  j^2 is reduced modulo
 * 2n before it is turned into an angle, so the chirp stays exact to
 * rounding for large n.
 */
#include "fft.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_FACTORS = 64 };

struct fft_plan {
	size_t n;
	int sign;
	int nfac;
	size_t fac[2 * MAX_FACTORS];     /* radix p, then the remaining length m */
	double complex *tw;              /* tw[i] = exp(sign 2 pi i / n), i < n */
	/* Bluestein (NULL tw and blue set) */
	struct fft_plan *fwd, *bwd;      /* length m power of two */
	double complex *chirp;           /* c_j, j < n */
	double complex *bhat;            /* transform of conj(c) padded, m values */
};

static double complex cis(double a)
{
	return cos(a) + I * sin(a);
}

/* exp(sign 2 pi i k / n), the angle reduced to the first octants' accuracy */
static double complex root(size_t k, size_t n, int sign)
{
	return cis(sign * 2 * M_PI * ((double)k / (double)n));
}

static int factorize(size_t n, size_t *fac)
{
	int nf = 0;
	size_t m = n;
	while (m > 1) {
		size_t p;
		if (m % 4 == 0)
			p = 4;
		else if (m % 2 == 0)
			p = 2;
		else {
			p = 3;
			while (p <= FFT_MAX_RADIX && m % p)
				p += 2;
			if (p > FFT_MAX_RADIX)
				return -1;
		}
		m /= p;
		fac[2 * nf] = p;
		fac[2 * nf + 1] = m;
		nf++;
	}
	return nf;
}

struct fft_plan *fft_plan_new(size_t n, int sign)
{
	if (n < 1 || (sign != 1 && sign != -1))
		die("internal error: fft plan of length %zu, sign %d", n, sign);
	struct fft_plan *p = xcalloc(1, sizeof *p);
	p->n = n;
	p->sign = sign;
	int nf = factorize(n, p->fac);
	if (nf >= 0) {
		p->nfac = nf;
		p->tw = xreallocarray(NULL, n, sizeof *p->tw);
		for (size_t i = 0; i < n; i++)
			p->tw[i] = root(i, n, sign);
		return p;
	}
	size_t m = 1;
	while (m < 2 * n - 1)
		m *= 2;
	p->fwd = fft_plan_new(m, -1);
	p->bwd = fft_plan_new(m, 1);
	p->chirp = xreallocarray(NULL, n, sizeof *p->chirp);
	for (size_t j = 0; j < n; j++) {
		/* j^2 mod 2n without overflow for any n that fits in memory */
		unsigned long long q = (unsigned long long)j * j % (2ULL * n);
		p->chirp[j] = cis(sign * M_PI * ((double)q / (double)n));
	}
	p->bhat = xcalloc(m, sizeof *p->bhat);
	p->bhat[0] = conj(p->chirp[0]);
	for (size_t j = 1; j < n; j++)
		p->bhat[j] = p->bhat[m - j] = conj(p->chirp[j]);
	double complex *w = xreallocarray(NULL, fft_work_size(p->fwd), sizeof *w);
	fft_exec(p->fwd, p->bhat, w);
	free(w);
	return p;
}

void fft_plan_free(struct fft_plan *p)
{
	if (!p)
		return;
	free(p->tw);
	fft_plan_free(p->fwd);
	fft_plan_free(p->bwd);
	free(p->chirp);
	free(p->bhat);
	free(p);
}

size_t fft_length(const struct fft_plan *p)
{
	return p->n;
}

size_t fft_work_size(const struct fft_plan *p)
{
	if (p->tw)
		return p->n;
	size_t m = fft_length(p->fwd);
	return m + fft_work_size(p->fwd);
}

/* re + i im (C11's CMPLX is missing from some compilers' headers; a
 * complex has the layout of two doubles) */
static inline double complex mkc(double re, double im)
{
	union { double complex z; double d[2]; } u;
	u.d[0] = re;
	u.d[1] = im;
	return u.z;
}

/* a b without the C library's care for infinities (the values here are
 * finite) */
static inline double complex cmul(double complex a, double complex b)
{
	double ar = creal(a), ai = cimag(a), br = creal(b), bi = cimag(b);
	return mkc(ar * br - ai * bi, ar * bi + ai * br);
}

/* sign i a */
static inline double complex rot(double complex a, double sg)
{
	return mkc(-sg * cimag(a), sg * creal(a));
}

/* out[0 .. n-1] = transform of in[0], in[s], .., in[(n-1) s], n = the
 * product of fac[0], fac[2], ..; fs the twiddle stride (N / n). */
static void work(const struct fft_plan *pl, double complex *out, const double complex *in,
		 size_t s, size_t fs, const size_t *fac)
{
	size_t p = fac[0], m = fac[1];
	if (m == 1) {
		for (size_t q = 0; q < p; q++)
			out[q] = in[q * s];
	} else {
		for (size_t q = 0; q < p; q++)
			work(pl, out + q * m, in + q * s, s * p, fs * p, fac + 2);
	}
	const double complex *tw = pl->tw;
	size_t N = pl->n;
	double sg = pl->sign;
	switch (p) {
	case 2:
		for (size_t u = 0; u < m; u++) {
			double complex a = out[u], b = cmul(out[u + m], tw[u * fs]);
			out[u] = a + b;
			out[u + m] = a - b;
		}
		return;
	case 3: {
		/* w = -1/2 + sign i sqrt(3)/2 */
		const double h = 0.86602540378443864676;
		for (size_t u = 0; u < m; u++) {
			double complex y0 = out[u];
			double complex y1 = cmul(out[u + m], tw[u * fs]);
			double complex y2 = cmul(out[u + 2 * m], tw[2 * u * fs]);
			double complex t = y1 + y2, mid = y0 - 0.5 * t;
			double complex d = h * rot(y1 - y2, sg);
			out[u] = y0 + t;
			out[u + m] = mid + d;
			out[u + 2 * m] = mid - d;
		}
		return;
	}
	case 4:
		for (size_t u = 0; u < m; u++) {
			double complex a0 = out[u];
			double complex a1 = cmul(out[u + m], tw[u * fs]);
			double complex a2 = cmul(out[u + 2 * m], tw[2 * u * fs]);
			double complex a3 = cmul(out[u + 3 * m], tw[3 * u * fs]);
			double complex s02 = a0 + a2, d02 = a0 - a2;
			double complex s13 = a1 + a3, r = rot(a1 - a3, sg);
			out[u] = s02 + s13;
			out[u + m] = d02 + r;
			out[u + 2 * m] = s02 - s13;
			out[u + 3 * m] = d02 - r;
		}
		return;
	case 5: {
		/* cos and sin of 2 pi / 5 and 4 pi / 5 */
		const double c1 = 0.30901699437494742410, c2 = -0.80901699437494742410;
		const double s1 = 0.95105651629515357212, s2 = 0.58778525229247312917;
		for (size_t u = 0; u < m; u++) {
			double complex y0 = out[u];
			double complex y1 = cmul(out[u + m], tw[u * fs]);
			double complex y2 = cmul(out[u + 2 * m], tw[2 * u * fs]);
			double complex y3 = cmul(out[u + 3 * m], tw[3 * u * fs]);
			double complex y4 = cmul(out[u + 4 * m], tw[4 * u * fs]);
			double complex a = y1 + y4, b = y2 + y3, c = y1 - y4, d = y2 - y3;
			double complex e1 = y0 + c1 * a + c2 * b, e2 = y0 + c2 * a + c1 * b;
			double complex f1 = rot(s1 * c + s2 * d, sg), f2 = rot(s2 * c - s1 * d, sg);
			out[u] = y0 + a + b;
			out[u + m] = e1 + f1;
			out[u + 4 * m] = e1 - f1;
			out[u + 2 * m] = e2 + f2;
			out[u + 3 * m] = e2 - f2;
		}
		return;
	}
	}
	/* general radix p (odd, at most FFT_MAX_RADIX) */
	double complex y[FFT_MAX_RADIX];
	size_t step = N / p;                /* tw[step] = exp(sign 2 pi i / p) */
	for (size_t u = 0; u < m; u++) {
		for (size_t q = 0; q < p; q++)
			y[q] = cmul(out[u + q * m], tw[q * u * fs]);
		for (size_t q1 = 0; q1 < p; q1++) {
			double complex acc = y[0];
			size_t e = 0;
			for (size_t q = 1; q < p; q++) {
				e += q1 * step;
				if (e >= N)
					e -= N;
				acc += cmul(y[q], tw[e]);
			}
			out[u + q1 * m] = acc;
		}
	}
}

void fft_exec(const struct fft_plan *p, double complex *x, double complex *w)
{
	size_t n = p->n;
	if (n == 1)
		return;
	if (p->tw) {
		memcpy(w, x, n * sizeof *x);
		work(p, x, w, 1, 1, p->fac);
		return;
	}
	size_t m = fft_length(p->fwd);
	double complex *a = w, *sub = w + m;
	for (size_t j = 0; j < n; j++)
		a[j] = cmul(x[j], p->chirp[j]);
	for (size_t j = n; j < m; j++)
		a[j] = 0;
	fft_exec(p->fwd, a, sub);
	for (size_t j = 0; j < m; j++)
		a[j] = cmul(a[j], p->bhat[j]);
	fft_exec(p->bwd, a, sub);
	for (size_t k = 0; k < n; k++)
		x[k] = cmul(p->chirp[k], a[k]) / (double)m;
}

size_t fft_work2_size(const struct fft_plan *px, const struct fft_plan *py)
{
	size_t wx = fft_work_size(px), wy = fft_work_size(py);
	return fft_length(py) + (wx > wy ? wx : wy);
}

void fft_exec2(const struct fft_plan *px, const struct fft_plan *py, double complex *a,
	       double complex *w)
{
	size_t nx = px->n, ny = py->n;
	double complex *col = w, *sub = w + ny;
	for (size_t j = 0; j < ny; j++)
		fft_exec(px, a + j * nx, sub);
	for (size_t i = 0; i < nx; i++) {
		for (size_t j = 0; j < ny; j++)
			col[j] = a[j * nx + i];
		fft_exec(py, col, sub);
		for (size_t j = 0; j < ny; j++)
			a[j * nx + i] = col[j];
	}
}
