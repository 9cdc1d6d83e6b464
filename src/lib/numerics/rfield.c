/*
 * rfield.c - trilinear interpolation of the rate array and its gradient,
 * and one step of the ray equation over it (shared by etch and etch2d).
 *
 * The gradient is that of the trilinear interpolant inside the cell
 * holding the point, so R and grad R are consistent (the ray equation
 * [6.6] integrates exactly what R describes).  It is discontinuous across
 * cell faces, as the interpolant's derivative is; a point on a face takes
 * the cell above it (clamped at the last cell).
 */
#include "rfield.h"

#include "par.h"
#include "util.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

/* What one worker of rfield_init finds in its planes. */
struct scan {
	size_t bad;                     /* first negative or NaN rate, or SIZE_MAX */
	double rmax, gmax2;
};

struct scan_job {
	const struct rfield *f;
	struct scan *w;
};

/* Rates of planes [lo, hi) of points, and the largest |grad R|^2 at
 * their points. */
static void scan_planes(void *ctx, size_t lo, size_t hi, int worker)
{
	const struct scan_job *j = ctx;
	const struct rfield *f = j->f;
	struct scan *w = &j->w[worker];
	const int *n = f->n;
	size_t sx = 1, sy = (size_t)n[0], sz = (size_t)n[0] * n[1];
	for (size_t i = lo * sz; i < hi * sz; i++) {
		if (!(f->v[i] >= 0)) {
			if (i < w->bad)
				w->bad = i;
		} else if (f->v[i] > w->rmax) {
			w->rmax = f->v[i];
		}
	}
	if (w->bad != SIZE_MAX)
		return;
	/* |grad R| of a trilinear cell is largest at one of its corners
	 * (|grad R|^2 is convex along each axis), where each component is
	 * the difference along one cell edge: so max |grad R| is the largest
	 * over grid points P and the cells around P of gx^2 + gy^2 + gz^2,
	 * taken along that cell's edges from P, exactly as thesis 7.4.1 wants
	 * it.  The cells around P use every combination of the edges on
	 * either side of P along each axis, and rounded addition is monotone,
	 * so that is (largest gx^2) + (largest gy^2) + (largest gz^2) at P:
	 * the same number with six slopes a point instead of 24 a cell. */
	for (size_t k = lo; k < hi; k++)
		for (int jj = 0; jj < n[1]; jj++) {
			const double *row = f->v + k * sz + (size_t)jj * sy;
			double left = 0;        /* gx^2 of the edge ending at i */
			for (int i = 0; i < n[0]; i++) {
				const double *v = row + i;
				double mx = left, my = 0, mz = 0;
				if (i + 1 < n[0]) {
					double g = (v[sx] - v[0]) / f->h[0];
					left = g * g;
					if (left > mx)
						mx = left;
				}
				if (jj > 0) {
					double g = (v[0] - v[-(ptrdiff_t)sy]) / f->h[1];
					my = g * g;
				}
				if (jj + 1 < n[1]) {
					double g = (v[sy] - v[0]) / f->h[1];
					if (g * g > my)
						my = g * g;
				}
				if (k > 0) {
					double g = (v[0] - v[-(ptrdiff_t)sz]) / f->h[2];
					mz = g * g;
				}
				if (k + 1 < (size_t)n[2]) {
					double g = (v[sz] - v[0]) / f->h[2];
					if (g * g > mz)
						mz = g * g;
				}
				double g2 = mx + my + mz;
				if (g2 > w->gmax2)
					w->gmax2 = g2;
			}
		}
}

void rfield_init(struct rfield *f, const int n[3], const double lo[3], const double hi[3],
		 const double *v, const char *name)
{
	for (int d = 0; d < 3; d++) {
		if (d == 1 && n[d] == 1) {
			/* a 2D array: one row, the same at every y; the box
			 * keeps the file's y bounds, the spacing is nominal */
			f->n[d] = 1;
			f->lo[d] = lo[d];
			f->hi[d] = hi[d] > lo[d] ? hi[d] : lo[d];
			f->h[d] = 1;
			continue;
		}
		if (n[d] < 2)
			die("%s:1: needs at least 2 grid points along %c, got %d",
			    name, "xyz"[d], n[d]);
		if (!(hi[d] > lo[d]))
			die("%s:1: empty %c range", name, "xyz"[d]);
		f->n[d] = n[d];
		f->lo[d] = lo[d];
		f->hi[d] = hi[d];
		f->h[d] = (hi[d] - lo[d]) / (n[d] - 1);
	}
	f->v = v;
	f->flat_outside = 0;
	/* planes of cells split among threads; max is independent of the
	 * split, and the first bad point is the smallest index any finds */
	int nw = par_threads();
	struct scan *w = xcalloc((size_t)nw, sizeof *w);
	for (int i = 0; i < nw; i++)
		w[i].bad = SIZE_MAX;
	struct scan_job j = {f, w};
	par_for((size_t)n[2], 1, scan_planes, &j);
	size_t bad = SIZE_MAX;
	double gmax2 = 0;
	f->rmax = 0;
	for (int i = 0; i < nw; i++) {
		if (w[i].bad < bad)
			bad = w[i].bad;
		if (w[i].rmax > f->rmax)
			f->rmax = w[i].rmax;
		if (w[i].gmax2 > gmax2)
			gmax2 = w[i].gmax2;
	}
	free(w);
	if (bad != SIZE_MAX)
		die("%s:1: negative or invalid rate at point %zu", name, bad);
	f->gmax = sqrt(gmax2);
}

/* R and grad R in cell c at local coordinates t (each in [0, 1]). */
static double cell_eval(const struct rfield *f, const int c[3], const double t[3], double g[3])
{
	/* ny = 1: the y neighbour is the point itself, so dR/dy = 0 */
	size_t sx = 1, sy = f->n[1] > 1 ? (size_t)f->n[0] : 0, sz = (size_t)f->n[0] * f->n[1];
	const double *v = f->v + c[2] * sz + c[1] * sy + c[0];
	double v000 = v[0], v100 = v[sx], v010 = v[sy], v110 = v[sx + sy];
	double v001 = v[sz], v101 = v[sx + sz], v011 = v[sy + sz], v111 = v[sx + sy + sz];
	double tx = t[0], ty = t[1], tz = t[2];
	/* interpolate along x, then y, then z, keeping the partial sums
	 * needed for the derivatives */
	double a00 = v000 + tx * (v100 - v000), a10 = v010 + tx * (v110 - v010);
	double a01 = v001 + tx * (v101 - v001), a11 = v011 + tx * (v111 - v011);
	double b0 = a00 + ty * (a10 - a00), b1 = a01 + ty * (a11 - a01);
	double r = b0 + tz * (b1 - b0);
	if (g) {
		double dx00 = v100 - v000, dx10 = v110 - v010, dx01 = v101 - v001, dx11 = v111 - v011;
		double dx0 = dx00 + ty * (dx10 - dx00), dx1 = dx01 + ty * (dx11 - dx01);
		g[0] = (dx0 + tz * (dx1 - dx0)) / f->h[0];
		double dy0 = a10 - a00, dy1 = a11 - a01;
		g[1] = (dy0 + tz * (dy1 - dy0)) / f->h[1];
		g[2] = (b1 - b0) / f->h[2];
	}
	return r;
}

double rfield_eval(const struct rfield *f, const double p[3], double g[3])
{
	int c[3];
	double t[3];
	int face = -1;
	for (int d = 0; d < 3; d++) {
		if (f->n[d] == 1) {
			c[d] = 0;
			t[d] = 0;
			continue;
		}
		double u = (p[d] - f->lo[d]) / f->h[d];
		if (!(u > 0))           /* also catches NaN */
			u = 0;
		double top = f->n[d] - 1;
		if (u > top)
			u = top;
		int i = (int)u;
		if (i > f->n[d] - 2)
			i = f->n[d] - 2;
		c[d] = i;
		t[d] = u - i;
		if (t[d] == 0 && i > 0)
			face = d;
	}
	double r = cell_eval(f, c, t, g);
	if (g && f->flat_outside)
		for (int d = 0; d < 3; d++)
			if (p[d] < f->lo[d] || p[d] > f->hi[d])
				g[d] = 0;
	if (g && face >= 0) {
		/* On a face between cells the interpolant has a kink: take the
		 * mean of the two one-sided slopes, so that mirror-symmetric
		 * rates turn mirror-symmetric rays (nodes of the flat start sit
		 * on grid planes).  Exactly on the face only: t == 0 exactly. */
		for (int d = 0; d < 3; d++) {
			if (!(t[d] == 0 && c[d] > 0))
				continue;
			int c2[3] = {c[0], c[1], c[2]};
			double t2[3] = {t[0], t[1], t[2]}, g2[3];
			c2[d]--;
			t2[d] = 1;
			cell_eval(f, c2, t2, g2);
			g[d] = 0.5 * (g[d] + g2[d]);
		}
	}
	return r;
}

/* ---- the ray equation, thesis [6.3] ----
 *
 * d/ds (s / R) = grad(1 / R), written in time (ds = R dt), is the system
 *
 *     dP/dt = R s,     ds/dt = -(grad R - (s . grad R) s),
 *
 * of which the thesis' step [6.7] + [6.6]/[A.33] (move P by R(P1) dt
 * along s1; s2 = s1 + s1 (R2/R1 - 1) - 0.5 (R1 + R2)/R1 grad R dt) is
 * the first-order (Euler) discretisation. */

/* R1 below this (um/s) counts as zero in the thesis form [A.33], which
 * divides by R1; the limit form s2 = s1 - grad R dt is used instead. */
#define RATE_TINY 1e-300

static void normalize(double s[3])
{
	double r = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
	if (r > 0) {
		s[0] /= r;
		s[1] /= r;
		s[2] /= r;
	}
}

/* The right-hand side of the ray system at (p, s). */
static void deriv(const struct rfield *f, const double p[3], const double s[3],
		  double dp[3], double ds[3])
{
	double g[3];
	double r = rfield_eval(f, p, g);
	double sg = s[0] * g[0] + s[1] * g[1] + s[2] * g[2];
	for (int d = 0; d < 3; d++) {
		dp[d] = r * s[d];
		ds[d] = -(g[d] - sg * s[d]);
	}
}

void raystep_rk4(const struct rfield *f, const double p[3], const double s[3],
		 double dt, double p2[3], double s2[3])
{
	double k1p[3], k1s[3], k2p[3], k2s[3], k3p[3], k3s[3], k4p[3], k4s[3];
	double q[3], u[3];
	deriv(f, p, s, k1p, k1s);
	for (int d = 0; d < 3; d++) {
		q[d] = p[d] + 0.5 * dt * k1p[d];
		u[d] = s[d] + 0.5 * dt * k1s[d];
	}
	deriv(f, q, u, k2p, k2s);
	for (int d = 0; d < 3; d++) {
		q[d] = p[d] + 0.5 * dt * k2p[d];
		u[d] = s[d] + 0.5 * dt * k2s[d];
	}
	deriv(f, q, u, k3p, k3s);
	for (int d = 0; d < 3; d++) {
		q[d] = p[d] + dt * k3p[d];
		u[d] = s[d] + dt * k3s[d];
	}
	deriv(f, q, u, k4p, k4s);
	for (int d = 0; d < 3; d++) {
		p2[d] = p[d] + dt / 6 * (k1p[d] + 2 * k2p[d] + 2 * k3p[d] + k4p[d]);
		s2[d] = s[d] + dt / 6 * (k1s[d] + 2 * k2s[d] + 2 * k3s[d] + k4s[d]);
	}
	normalize(s2);
}

/* The thesis' step: [6.7], then [6.6]/[A.33] with grad R taken at P2
 * (6.3.1: "evaluate the etch-rate gradient at P2"). */
void raystep_euler(const struct rfield *f, const double p[3], const double s[3],
		   double dt, double p2[3], double s2[3])
{
	double g[3];
	double r1 = rfield_eval(f, p, NULL);
	for (int d = 0; d < 3; d++)
		p2[d] = p[d] + s[d] * r1 * dt;
	double r2 = rfield_eval(f, p2, g);
	for (int d = 0; d < 3; d++) {
		if (r1 > RATE_TINY)
			s2[d] = s[d] * (r2 / r1) - 0.5 * (r1 + r2) / r1 * g[d] * dt;
		else
			s2[d] = s[d] - g[d] * dt;
	}
	normalize(s2);
}
