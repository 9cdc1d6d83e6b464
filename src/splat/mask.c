/*
 * mask.c - Fourier coefficients of the periodic mask (thesis 2.2.1: SPLAT
 * images a mask that repeats with the period of the simulation window).
 *
 * Rects are painted over the background in file order, so overlapping
 * rects are not additive.  The window is therefore cut into the cells of
 * the grid made by every rect edge; each cell takes the transmission of
 * the last rect covering it.  A cell is a rectangle of constant complex
 * transmission tau, whose coefficient is separable and exact:
 *   c(m, n) = tau_bg delta(m) delta(n)
 *           + sum_cells (tau - tau_bg) X(m) Y(n),
 *   X(m) = (w/Lx) sinc(pi m w/Lx) exp(-i pi m (xa + xb)/Lx),  w = xb - xa,
 * so no sampling of the mask (and no aliasing) enters the image.
 *
 * With polygons or gds layers the painted mask is cut instead by the slab
 * sweep of the library (poly_boundary) into boundary pieces, segments
 * where the top layer changes from tau_L to tau_R, and the transform is
 * summed over them exactly (Green's theorem with a field along x only, so
 * horizontal edges contribute nothing):
 *   fx != 0:  (tau_L - tau_R) e^{-2 pi i f.r_mid} h sinc(pi k h) / (-2 pi i fx),
 *             k = fx dx/dy + fy, h the piece's height, r_mid its midpoint;
 *   fx == 0:  (tau_L - tau_R) integral over the piece of x(y) e^{-2 pi i fy y} dy,
 * both exact on the axes and at f = 0 (sinc and its moment are evaluated
 * by series near 0).  Rect-only masks keep the cell path above unchanged.
 */
#include "splat.h"
#include "checked.h"
#include "par.h"
#include "util.h"

#include <limits.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

static struct orders *mask_orders_poly(const struct splat_mask *m, struct orders *o,
					double fm);

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static double clampd(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

/* Sorted distinct edges of the rects along one axis, window ends included. */
static int edges(const struct splat_mask *m, int axis, double lo, double hi, double **out)
{
	double *e = xreallocarray(NULL, 2 * (size_t)m->nrects + 2, sizeof *e);
	int n = 0;
	e[n++] = lo;
	e[n++] = hi;
	for (int i = 0; i < m->nrects; i++) {
		const struct splat_rect *r = &m->rects[i];
		e[n++] = clampd(axis ? r->y1 : r->x1, lo, hi);
		e[n++] = clampd(axis ? r->y2 : r->x2, lo, hi);
	}
	qsort(e, (size_t)n, sizeof *e, cmp_double);
	int k = 0;
	for (int i = 0; i < n; i++)
		if (k == 0 || e[i] > e[k - 1])
			e[k++] = e[i];
	*out = e;
	return k;
}

int mask_edge_count(const struct splat_mask *m, int axis)
{
	double *e;
	int n = edges(m, axis, axis ? m->ymin : m->xmin, axis ? m->ymax : m->xmax, &e);
	free(e);
	return n;
}

/* Index of v in the sorted array e (v is one of its values). */
static int find(const double *e, int n, double v)
{
	int lo = 0, hi = n - 1;
	while (lo < hi) {
		int mid = (lo + hi) / 2;
		if (e[mid] < v)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

static double complex phasor(double t, double deg)
{
	double a = deg * (M_PI / 180);
	return t * cos(a) + I * (t * sin(a));
}

/* (1/L) integral over [a, b] of exp(-2 pi i q x / L) dx, for q = -qmax..qmax. */
static void interval_ft(double a, double b, double len, int qmax, double complex *out)
{
	double w = (b - a) / len, c = (a + b) / len;
	for (int q = -qmax; q <= qmax; q++) {
		double arg = M_PI * q * w;
		double sinc = q == 0 ? 1 : sin(arg) / arg;
		double ph = -M_PI * q * c;
		out[q + qmax] = w * sinc * (cos(ph) + I * sin(ph));
	}
}

/* integral_0^H u sin(w u) du, by its series where the closed form
 * cancels (|w H| small). */
static double moment_sin(double w, double H)
{
	double a = w * H;
	if (fabs(a) > 0.5)
		return sin(a) / (w * w) - H * cos(a) / w;
	/* sum_n (-1)^n w^(2n+1) H^(2n+3) / ((2n+1)! (2n+3)) */
	double term = w * H * H * H, s = 0, fact = 1;
	for (int n = 0; n < 12; n++) {
		if (n > 0) {
			fact *= (2.0 * n) * (2.0 * n + 1);
			term *= -a * a;
		}
		s += term / (fact * (2 * n + 3));
	}
	return s;
}

/* The layer that the next shapes of transmission tau go to: painting
 * twice with the same tau is a union, so consecutive statements with the
 * same tau share one layer (and the result does not depend on how the
 * shapes were split into statements). */
static int layer_for(int *k, double complex *t, double complex tau)
{
	if (*k > 0 && t[*k - 1] == tau)
		return *k - 1;
	t[*k] = tau;
	return (*k)++;
}

/* The painted mask as layers in paint order: rects (clamped to the window
 * as above) and the splat layers, interleaved by file order. */
static int paint_layers(const struct splat_mask *m, struct poly_set **out,
			double complex **tau)
{
	int nl = m->nrects + m->nlayers;
	struct poly_set *ls = xcalloc((size_t)nl, sizeof *ls);
	double complex *t = xreallocarray(NULL, (size_t)nl, sizeof *t);
	int k = 0, j = 0;
	for (int i = 0; i <= m->nrects; i++) {
		for (; j < m->nlayers && m->layers[j].after == i; j++) {
			const struct splat_layer *l = &m->layers[j];
			int to = layer_for(&k, t, phasor(l->t, l->phase));
			for (int p = 0; p < l->shapes.n; p++)
				poly_set_add(&ls[to], poly_set_xy(&l->shapes, p),
					     poly_set_nv(&l->shapes, p));
		}
		if (i == m->nrects)
			break;
		const struct splat_rect *r = &m->rects[i];
		double x1 = clampd(r->x1, m->xmin, m->xmax), x2 = clampd(r->x2, m->xmin, m->xmax);
		double y1 = clampd(r->y1, m->ymin, m->ymax), y2 = clampd(r->y2, m->ymin, m->ymax);
		double q[8] = {x1, y1, x2, y1, x2, y2, x1, y2};
		poly_set_add(&ls[layer_for(&k, t, phasor(r->t, r->phase))], q, 4);
	}
	for (int i = k; i < nl; i++)
		poly_set_free(&ls[i]);
	*out = ls;
	*tau = t;
	return k;
}

/* Keeps, of the coefficients cc of all orders |p| <= mmax, |q| <= nmax
 * (row q + nmax, column p + mmax), those inside the circle |f| <= fm, in
 * o's order lists (both mask paths end here). */
static void keep_in_circle(struct orders *o, const double complex *cc, double fm)
{
	int nm = 2 * o->mmax + 1, nn = 2 * o->nmax + 1;
	size_t cap = (size_t)nm * nn;
	o->m = xreallocarray(NULL, cap, sizeof *o->m);
	o->k = xreallocarray(NULL, cap, sizeof *o->k);
	o->fx = xreallocarray(NULL, cap, sizeof *o->fx);
	o->fy = xreallocarray(NULL, cap, sizeof *o->fy);
	o->c = xreallocarray(NULL, cap, sizeof *o->c);
	for (int q = -o->nmax; q <= o->nmax; q++)
		for (int p = -o->mmax; p <= o->mmax; p++) {
			double fx = p / o->lx, fy = q / o->ly;
			if (hypot(fx, fy) > fm)
				continue;
			o->m[o->n] = p;
			o->k[o->n] = q;
			o->fx[o->n] = fx;
			o->fy[o->n] = fy;
			o->c[o->n] = cc[(size_t)(q + o->nmax) * nm + p + o->mmax];
			o->n++;
		}
}

/* The sums of polygon_orders for the rows [lo, hi) of orders (row q +
 * nmax): a row adds every piece in piece order, so a coefficient is the
 * same sum whichever thread holds its row.  Along a row the phase
 * e^{-2 pi i (fx xm + fy ym)} and e^{i arg} of the sinc advance by one
 * complex product an order, and are taken afresh every SEED orders (the
 * products drift by an ulp or two each: 1e-14 at most); where the sinc's
 * argument is small its sine is taken directly (there the product's
 * absolute error would be a large relative one).  Two sines a piece and
 * order had made an array of a million squares a minute and a half. */
enum { SEED = 32 };

/* sin(x)/x for |x| < 0.5 by its series to x^16 (the next term is below
 * 1e-22): vertical edges (b = 0) of short pieces have small arguments all
 * along a row, where a sine call each would cost more than the rest. */
static double sinc_small(double x)
{
	double z = x * x, s = 0;
	/* 1/(2k+1)! for k = 8 .. 1: 1 - z (1/3! - z (1/5! - z (...))) */
	static const double c[] = {1.0 / 355687428096000.0, 1.0 / 1307674368000.0,
				   1.0 / 6227020800.0, 1.0 / 39916800.0, 1.0 / 362880.0,
				   1.0 / 5040.0, 1.0 / 120.0, 1.0 / 6.0};
	for (int k = 0; k < 8; k++)
		s = c[k] - z * s;
	return 1 - z * s;
}
struct poly_rows {
	const struct orders *o;
	const struct poly_piece *pc;
	const double complex *dt;       /* (tau_L - tau_R) / (Lx Ly) a piece */
	size_t np;
	double complex *cc;
	const size_t *vert;             /* the vertical pieces, by x then index */
	size_t nvert;
	double complex *scratch;        /* 2 nm + 2 rows a worker */
};

/* The vertical pieces (b = 0, the edges of Manhattan layouts) of the rows
 * [lo, hi).  Their term is separable: e^{-2 pi i fx xm} / fx depends on
 * the column alone and e^{-2 pi i fy ym} h sinc(pi h fy) on the row alone,
 * so the pieces at one x add their row factors first (U) and the row
 * times the column factors is added once for them all: an array of a
 * million squares has a few thousand distinct x.  The row factors advance
 * by a complex product a row, taken afresh every SEED rows. */
static void poly_columns(const struct poly_rows *r, size_t lo, size_t hi, int worker)
{
	const struct orders *o = r->o;
	int nm = 2 * o->mmax + 1, mmax = o->mmax;
	size_t nr = hi - lo;
	double complex *u = r->scratch + (size_t)worker * (size_t)(2 * nm + 2 + 2 * o->nmax + 1);
	double complex *v = u + 2 * o->nmax + 1;
	for (size_t g = 0; g < r->nvert;) {
		double xm = r->pc[r->vert[g]].x0;
		for (size_t k = 0; k < nr; k++)
			u[k] = 0;
		for (; g < r->nvert && r->pc[r->vert[g]].x0 == xm; g++) {
			const struct poly_piece *p = &r->pc[r->vert[g]];
			double complex dt = r->dt[r->vert[g]];
			double h = p->y1 - p->y0, ym = 0.5 * (p->y0 + p->y1);
			double wy = -2 * M_PI * ym / o->ly, ay = M_PI * h / o->ly;
			double sxr = cos(wy), sxi = sin(wy), sar = cos(ay), sai = sin(ay);
			double er = 0, ei = 0, sr = 0, si = 0;
			for (size_t k = 0; k < nr; k++) {
				int q = (int)(lo + k) - o->nmax;
				if (k % SEED == 0) {
					er = cos(wy * q); ei = sin(wy * q);
					sr = cos(ay * q); si = sin(ay * q);
				}
				double arg = ay * q;
				double sinc = fabs(arg) < 0.5 ? sinc_small(arg) : si / arg;
				u[k] += dt * (er + I * ei) * (h * sinc);
				double t = er * sxr - ei * sxi;
				ei = er * sxi + ei * sxr;
				er = t;
				t = sr * sar - si * sai;
				si = sr * sai + si * sar;
				sr = t;
			}
		}
		/* the column factors: i e^{-2 pi i fx xm} / (2 pi fx), and xm at fx = 0
		 * (the integral of x(y) = xm along the piece) */
		for (int mm = -mmax; mm <= mmax; mm++) {
			double ph = -2 * M_PI * (mm / o->lx) * xm;
			v[mm + mmax] = mm == 0 ? xm :
				(cos(ph) + I * sin(ph)) * (I / (2 * M_PI * (mm / o->lx)));
		}
		for (size_t k = 0; k < nr; k++) {
			double complex *c = r->cc + (lo + k) * (size_t)nm;
			double complex uk = u[k];
			if (uk == 0)
				continue;
			for (int j = 0; j < nm; j++)
				c[j] += uk * v[j];
		}
	}
}

static void poly_rows(void *ctx, size_t lo, size_t hi, int worker)
{
	const struct poly_rows *r = ctx;
	const struct orders *o = r->o;
	int nm = 2 * o->mmax + 1, mmax = o->mmax;
	poly_columns(r, lo, hi, worker);
	for (size_t i = 0; i < r->np; i++) {
		double dr = creal(r->dt[i]), di = cimag(r->dt[i]);
		const struct poly_piece *p = &r->pc[i];
		if ((dr == 0 && di == 0) || p->x0 == p->x1)
			continue;       /* vertical pieces: poly_columns */
		double h = p->y1 - p->y0, b = (p->x1 - p->x0) / h;
		double xm = 0.5 * (p->x0 + p->x1), ym = 0.5 * (p->y0 + p->y1);
		/* the phase and the sinc's argument per order along x */
		double wx = -2 * M_PI * xm / o->lx, ax = M_PI * h * b / o->lx;
		double sxr = cos(wx), sxi = sin(wx), sar = cos(ax), sai = sin(ax);
		for (size_t row = lo; row < hi; row++) {
			double fy = ((int)row - o->nmax) / o->ly;
			double py = -2 * M_PI * fy * ym, ay = M_PI * h * fy;
			double complex *c = r->cc + row * (size_t)nm + mmax;
			double er = 0, ei = 0, sr = 0, si = 0;
			for (int mm = -mmax; mm <= mmax; mm++) {
				if ((mm + mmax) % SEED == 0) {
					er = cos(wx * mm + py); ei = sin(wx * mm + py);
					sr = cos(ax * mm + ay); si = sin(ax * mm + ay);
				}
				if (mm != 0) {
					double arg = ax * mm + ay;
					double sinc = fabs(arg) < 0.5 ? sinc_small(arg) : si / arg;
					/* dt e h sinc / (-2 pi i fx) = dt (i e) k */
					double k = h * sinc / (2 * M_PI * (mm / o->lx));
					double tr = -ei * k, ti = er * k;
					c[mm] += (dr * tr - di * ti) + I * (dr * ti + di * tr);
				} else {
					double w = 2 * M_PI * fy, a0 = 0.5 * w * h;
					double sinc = a0 == 0 ? 1 : sin(a0) / a0;
					double complex e = cos(py) + I * sin(py);
					/* integral of (xm + b u) e^{-i w u}, u in [-h/2, h/2] */
					double complex v = xm * h * sinc - I * (2 * b * moment_sin(w, 0.5 * h));
					c[mm] += (dr + I * di) * e * v;
				}
				double t = er * sxr - ei * sxi;
				ei = er * sxi + ei * sxr;
				er = t;
				t = sr * sar - si * sai;
				si = sr * sai + si * sar;
				sr = t;
			}
		}
	}
}

/* qsort's order of the vertical pieces: by x, then by index (the sweep's
 * order), so the groups and their sums do not depend on qsort. */
static const struct poly_piece *vert_pc;
static int cmp_vert(const void *a, const void *b)
{
	size_t i = *(const size_t *)a, j = *(const size_t *)b;
	double x = vert_pc[i].x0, y = vert_pc[j].x0;
	if (x != y)
		return x < y ? -1 : 1;
	return (i > j) - (i < j);
}

/* cc[(n + nmax) * nm + m + mmax] += the transform of the painted layers,
 * minus the background under them, divided by Lx Ly. */
static void polygon_orders(const struct splat_mask *m, const struct orders *o,
			   double complex bg, double complex *cc)
{
	struct poly_set *ls;
	double complex *tau;
	int nl = paint_layers(m, &ls, &tau);
	struct poly_piece *pc;
	size_t np = poly_boundary(ls, nl, &pc);
	double area = o->lx * o->ly;
	double complex *dt = xreallocarray(NULL, np ? np : 1, sizeof *dt);
	for (size_t i = 0; i < np; i++) {
		double complex tl = pc[i].left < 0 ? 0 : tau[pc[i].left] - bg;
		double complex tr = pc[i].right < 0 ? 0 : tau[pc[i].right] - bg;
		dt[i] = (tl - tr) / area;
	}
	/* the vertical pieces by x, then by their order in the sweep */
	size_t nv = 0;
	size_t *vert = xreallocarray(NULL, np ? np : 1, sizeof *vert);
	for (size_t i = 0; i < np; i++)
		if (pc[i].x0 == pc[i].x1 && dt[i] != 0)
			vert[nv++] = i;
	vert_pc = pc;
	qsort(vert, nv, sizeof *vert, cmp_vert);
	size_t per = 2 * (size_t)o->mmax + 1 + 2 + 2 * (size_t)o->nmax + 1 + 2 * (size_t)o->mmax + 1;
	double complex *scratch = xreallocarray(NULL, (size_t)par_threads(), per * sizeof *scratch);
	struct poly_rows r = {o, pc, dt, np, cc, vert, nv, scratch};
	par_for(2 * (size_t)o->nmax + 1, 1, poly_rows, &r);
	free(scratch);
	free(vert);
	free(dt);
	free(pc);
	for (int k = 0; k < nl; k++)
		poly_set_free(&ls[k]);
	free(ls);
	free(tau);
}

struct orders *mask_orders(const struct splat_mask *m, double fmax)
{

	struct orders *o = xcalloc(1, sizeof *o);
	o->lx = m->xmax - m->xmin;
	o->ly = m->ymax - m->ymin;
	/* the 1e-9 keeps an order lying exactly on fmax (a coherent grating
	 * order on the pupil edge) from depending on rounding */
	double fm = fmax * (1 + 1e-9);
	/* checked: a huge window or source must not wrap the order counts
	 * (the image indexes 4 mmax + 1 columns in an int) */
	o->mmax = ck_int(floor(fm * o->lx), 0, (INT_MAX - 1) / 4, "diffraction orders along x");
	o->nmax = ck_int(floor(fm * o->ly), 0, (INT_MAX - 1) / 4, "diffraction orders along y");
	int nm = 2 * o->mmax + 1, nn = 2 * o->nmax + 1;

	if (m->nlayers)
		return mask_orders_poly(m, o, fm);
	/* the cells and their transmissions */
	double *ex, *ey;
	int nex = edges(m, 0, m->xmin, m->xmax, &ex);
	int ney = edges(m, 1, m->ymin, m->ymax, &ey);
	int cx = nex - 1, cy = ney - 1;
	double complex bg = phasor(m->bg_t, m->bg_phase);
	double complex *tau = xreallocarray(NULL, (size_t)cx * (size_t)cy, sizeof *tau);
	for (size_t i = 0; i < (size_t)cx * (size_t)cy; i++)
		tau[i] = bg;
	for (int r = 0; r < m->nrects; r++) {
		const struct splat_rect *re = &m->rects[r];
		int i0 = find(ex, nex, clampd(re->x1, m->xmin, m->xmax));
		int i1 = find(ex, nex, clampd(re->x2, m->xmin, m->xmax));
		int j0 = find(ey, ney, clampd(re->y1, m->ymin, m->ymax));
		int j1 = find(ey, ney, clampd(re->y2, m->ymin, m->ymax));
		double complex t = phasor(re->t, re->phase);
		for (int j = j0; j < j1; j++)
			for (int i = i0; i < i1; i++)
				tau[(size_t)j * cx + i] = t;
	}

	/* C(m, n) = sum_i X_i(m) S_i(n),  S_i(n) = sum_j dtau_ij Y_j(n) */
	double complex *cc = xcalloc((size_t)nm * nn, sizeof *cc);
	double complex *xf = xreallocarray(NULL, (size_t)nm, sizeof *xf);
	double complex *yf = xreallocarray(NULL, (size_t)cy * nn, sizeof *yf);
	double complex *s = xreallocarray(NULL, (size_t)nn, sizeof *s);
	for (int j = 0; j < cy; j++)
		interval_ft(ey[j], ey[j + 1], o->ly, o->nmax, yf + (size_t)j * nn);
	for (int i = 0; i < cx; i++) {
		int any = 0;
		for (int q = 0; q < nn; q++)
			s[q] = 0;
		for (int j = 0; j < cy; j++) {
			double complex d = tau[(size_t)j * cx + i] - bg;
			if (d == 0)
				continue;
			any = 1;
			for (int q = 0; q < nn; q++)
				s[q] += d * yf[(size_t)j * nn + q];
		}
		if (!any)
			continue;
		interval_ft(ex[i], ex[i + 1], o->lx, o->mmax, xf);
		for (int q = 0; q < nn; q++)
			for (int p = 0; p < nm; p++)
				cc[(size_t)q * nm + p] += xf[p] * s[q];
	}
	cc[(size_t)o->nmax * nm + o->mmax] += bg;

	keep_in_circle(o, cc, fm);
	free(ex);
	free(ey);
	free(tau);
	free(cc);
	free(xf);
	free(yf);
	free(s);
	return o;
}

/* The orders of o (period and counts set by mask_orders) for a mask with
 * polygon or gds layers, |f| <= fm. */
static struct orders *mask_orders_poly(const struct splat_mask *m, struct orders *o,
				       double fm)
{
	int nm = 2 * o->mmax + 1, nn = 2 * o->nmax + 1;
	double complex bg = phasor(m->bg_t, m->bg_phase);
	double complex *cc = xcalloc((size_t)nm * nn, sizeof *cc);
	polygon_orders(m, o, bg, cc);
	cc[(size_t)o->nmax * nm + o->mmax] += bg;
	keep_in_circle(o, cc, fm);
	free(cc);
	return o;
}

void mask_orders_free(struct orders *o)
{
	if (!o)
		return;
	free(o->m);
	free(o->k);
	free(o->fx);
	free(o->fy);
	free(o->c);
	free(o);
}
