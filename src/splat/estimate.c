/*
 * estimate.c - the work and memory of a splat run, estimated from the
 * input alone before anything is allocated (budget.h), so that a window
 * of 2000 um at NA 0.99 or a source of sigma 45 is refused at once with
 * its estimate instead of running for days.
 *
 * Counts (mask.c, tcc.c, image.c): orders inside the circle |f| <= fmax,
 * fmax = NA/lambda + largest source frequency, n ~ pi fmax^2 Lx Ly (plus
 * the rows and columns on the axes); every pair (n^2/2) is tried, and the
 * pairs whose pupils overlap (|f' - f''| < 2 NA/lambda, about
 * n pi (2 NA/lambda)^2 Lx Ly / 2 of them) are integrated over the source
 * discs with nouter x ninner quadrature points; the image costs
 * (4M+1)(4N+1) ny + (4M+1) nx ny products and the output about 0.06
 * microseconds a number.  The per-operation times are seconds of one
 * core, measured on the development machine (a 2020 x86-64 core) and
 * checked by tests/bench/estimate.sh (make bench), which prints each
 * estimate beside the time the run takes: within a factor of 2.
 *
 * The Abbe method (abbe.c) costs, per source cell and image plane, the
 * coefficients placed in the pupil (one test an order) and an FFT of the
 * Kx x Ky grid, Kx ~ 4M + 1, of which only the 2M + 1 columns holding
 * orders need the column pass: about area x log(area) a cell, with the
 * cell count fixed by the source shape alone.  splat -method auto runs
 * the method with the smaller estimate.
 *
 * A mask of polygons or gds shapes (mask.c) costs, on top, every slanted
 * boundary piece times every order of the rectangle, every vertical piece
 * times every row of orders and every distinct x of the vertical pieces
 * times every order, about one piece per edge: an array of a million
 * squares from a 258-byte GDSII file is hundreds of MB and seconds of
 * work, which the counts of orders alone do not see.
 */
#include "splat.h"
#include "util.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* seconds per pair tried and rejected; per quadrature point of an
 * integrated pair; per complex product of the image sums; per number
 * written (measured, see above; the contact's image on 1024^2 to 4096^2
 * points costs 0.09 us a point with its output) */
static const double T_PAIR = 4e-8, T_QUAD = 4e-8, T_IMAGE = 3e-9, T_OUT = 6e-8;
/* per row of a flat pupil's source integral (the row's sine and cosine
 * precomputed) */
static const double T_ROW = 1.3e-8;

/* Abbe (abbe.c): per source cell and plane, one pass over the orders, a
 * column and a row pass of FFTs (seconds per point and log2 of the
 * length) and the accumulation; per order of a cell; measured as above. */
static const double T_FFT = 6e-10, T_ORDER = 3e-9, T_ACC = 1e-9;

/* the polygon mask (mask.c polygon_orders): seconds per slanted edge and
 * order of the rectangle, per vertical edge and row of orders, per
 * distinct x of the vertical edges and order, per vertex in the sweep;
 * bytes per vertex (the layers, their painted copy, the sweep's pieces);
 * measured as above with arrays of squares and of 999-gons */
static const double T_POLY = 1.2e-8, T_COL = 1e-8, T_GROUP = 3e-9, T_SWEEP = 1e-8;
static const double B_POLY = 90;

/* The distinct values among finite doubles, counted in a hash set (open
 * addressing, NaN marking an empty slot, the table doubled at half full):
 * linear time, where sorting a million squares' edges took longer than
 * the rest of the estimate and of the mask's reading together. */
struct xset {
	double *v;
	size_t cap, n;
};

static size_t xset_slot(const struct xset *h, double x)
{
	uint64_t b;
	memcpy(&b, &x, sizeof b);
	/* splitmix64's finaliser */
	b ^= b >> 30, b *= 0xbf58476d1ce4e5b9u;
	b ^= b >> 27, b *= 0x94d049bb133111ebu;
	b ^= b >> 31;
	size_t i = (size_t)b & (h->cap - 1);
	while (!isnan(h->v[i]) && h->v[i] != x)
		i = (i + 1) & (h->cap - 1);
	return i;
}

static void xset_add(struct xset *h, double x)
{
	x += 0.0;       /* -0 is 0 */
	if (2 * (h->n + 1) > h->cap) {
		struct xset g = {xreallocarray(NULL, h->cap ? 2 * h->cap : 1024, sizeof *g.v),
				 h->cap ? 2 * h->cap : 1024, h->n};
		for (size_t i = 0; i < g.cap; i++)
			g.v[i] = NAN;
		for (size_t i = 0; i < h->cap; i++)
			if (!isnan(h->v[i]))
				g.v[xset_slot(&g, h->v[i])] = h->v[i];
		free(h->v);
		*h = g;
	}
	size_t i = xset_slot(h, x);
	if (isnan(h->v[i]))
		h->v[i] = x, h->n++;
}

/* The seconds of the polygon mask for nrect orders in nrows rows, and its
 * vertex count (0 for rects alone, which take the cell path). */
static double mask_poly_cost(const struct splat_mask *m, double nrect, double nrows,
			     double *verts)
{
	double v = 0, slant = 0, vert = 0;
	for (int k = 0; k < m->nlayers; k++) {
		const struct poly_set *ps = &m->layers[k].shapes;
		v += ps->n ? ps->start[ps->n] : 0;
	}
	*verts = v > 0 ? v + 4.0 * m->nrects : 0;
	if (v == 0)
		return 0;
	struct xset xs = {0};
	for (int k = 0; k < m->nlayers; k++) {
		const struct poly_set *ps = &m->layers[k].shapes;
		for (int i = 0; i < ps->n; i++) {
			const double *xy = poly_set_xy(ps, i);
			int nv = poly_set_nv(ps, i);
			for (int j = 0; j < nv; j++) {
				int j1 = (j + 1) % nv;
				if (xy[2 * j + 1] == xy[2 * j1 + 1])
					continue;               /* horizontal: no piece */
				if (xy[2 * j] == xy[2 * j1]) {
					vert++;
					xset_add(&xs, xy[2 * j]);
				} else {
					slant++;
				}
			}
		}
	}
	double groups = (double)xs.n;
	free(xs.v);
	/* the rects' vertical edges, 2 each, at their own x */
	vert += 2.0 * m->nrects;
	groups += 2.0 * m->nrects;
	return slant * nrect * T_POLY + vert * nrows * T_COL + groups * nrect * T_GROUP
	       + *verts * log2(*verts + 1) * T_SWEEP;
}

static double nice(double n)
{
	/* the FFT length (abbe.c's nice_length) is within 10 % of n above 100 */
	return n * 1.1 + 8;
}

/* The orders (mask.c) inside the circle |f| <= fmax = NA/lambda + the
 * largest source frequency, about pi fmax^2 Lx Ly plus the axes: M and N
 * across, nrect in their rectangle; returns the count kept. */
static double order_counts(const struct splat_input *in, const struct pupil *p,
			  const struct source *s, double *M, double *N, double *nrect)
{
	const struct splat_mask *m = &in->mask;
	double lx = m->xmax - m->xmin, ly = m->ymax - m->ymin;
	double fm = (p->cutoff + s->smax) * (1 + 1e-9);
	*M = floor(fm * lx);
	*N = floor(fm * ly);
	*nrect = (2 * *M + 1) * (2 * *N + 1);
	return fmin(*nrect, M_PI * fm * fm * lx * ly + 2 * (*M + *N) + 1);
}

void splat_estimate_abbe(const struct splat_input *in, double *nodes, double *seconds,
			 double *bytes)
{
	struct pupil p;
	struct source s;
	pupil_init(&p, in);
	source_init(&s, in, p.cutoff);
	const struct splat_mask *m = &in->mask;
	double M, N, nrect, n = order_counts(in, &p, &s, &M, &N, &nrect);
	double h = abbe_cell_default(&p, &s), ns = 0;
	if (s.coherent)
		ns = 1;
	else
		for (int k = 0; k < s.ndisc; k++)
			if (s.sign[k] > 0)
				ns += M_PI * s.r[k] * s.r[k] / (h * h) + 2 * M_PI * s.r[k] / h + 1;
	double kx = nice(4 * M + 1), ky = nice(4 * N + 1);
	double np = p.nplanes;
	double per = (2 * M + 1) * ky * log2(ky) * T_FFT + kx * ky * log2(kx) * T_FFT
		   + kx * ky * T_ACC + n * T_ORDER;
	double w = 4 * M + 1, hh = 4 * N + 1;
	double cx = mask_edge_count(m, 0) - 1, cy = mask_edge_count(m, 1) - 1;
	double cells = cx * cy;
	double pts = (double)in->nx * in->ny, cut = 0;
	for (int k = 0; k < in->ncutlines; k++)
		cut += in->cutlines[k].npts;
	/* the grid by one FFT per plane (image_grid_fft), cutlines summed */
	double grid = (double)in->nx * in->ny;
	*nodes = ns;
	double mv, mt = mask_poly_cost(m, nrect, 2 * N + 1, &mv);
	*seconds = mt + ns * np * per + np * kx * ky * log2(kx * ky) * T_FFT
		 + np * grid * log2(grid + 1) * T_FFT + w * hh * np * cut * T_IMAGE
		 + cells * (2 * N + 1) * T_IMAGE + cx * nrect * T_IMAGE
		 + (pts + cut) * np * T_OUT;
	pts += cut;
	/* the field's grid, the planes' sums, a work row per thread, the
	 * spectra, the coefficients, the image and its phasors */
	*bytes = mv * B_POLY + kx * ky * (16 + 8 * np) + 64 * (kx + ky) * 16 + w * hh * 16 * np
		 + nrect * (16 + 56) + cells * 16 + cy * (2 * N + 1) * 16
		 + pts * 8 * np + grid * 16;
}

void splat_estimate(const struct splat_input *in, double *orders, double *pairs,
		    double *seconds, double *bytes)
{
	struct pupil p;
	struct source s;
	pupil_init(&p, in);
	source_init(&s, in, p.cutoff);
	int nouter, ninner;
	quad_default(&p, &nouter, &ninner);
	const struct splat_mask *m = &in->mask;
	double lx = m->xmax - m->xmin, ly = m->ymax - m->ymin;
	double M, N, nrect, n = order_counts(in, &p, &s, &M, &N, &nrect);
	double tried = n * (n + 1) / 2;
	double r2 = 2 * p.cutoff;
	double near = fmin(n, M_PI * r2 * r2 * lx * ly + 2 * (r2 * lx + r2 * ly) + 1);
	double integrated = n * near / 2;
	/* quadrature points of a pair, in units of T_QUAD: with a flat pupil
	 * a row's integral is its length (source.c), about three pieces of
	 * nouter rows a disc, each row about T_ROW */
	double per = s.coherent ? 1 : (double)s.ndisc * nouter * ninner;
	if (!s.coherent && p.flat && p.nplanes == 1)
		per = (double)s.ndisc * nouter * 3 * (T_ROW / T_QUAD);
	double w = 4 * M + 1, h = 4 * N + 1;
	/* the cells of the rects' distinct edges (mask.c) */
	double cx = mask_edge_count(m, 0) - 1, cy = mask_edge_count(m, 1) - 1;
	double cells = cx * cy;
	double pts = (double)in->nx * in->ny;
	for (int k = 0; k < in->ncutlines; k++)
		pts += in->cutlines[k].npts;
	*orders = n;
	*pairs = tried;
	double mv, mt = mask_poly_cost(m, nrect, 2 * N + 1, &mv);
	*seconds = mt + tried * T_PAIR + integrated * per * T_QUAD
		 + (w * h * in->ny + w * pts) * T_IMAGE
		 + cells * (2 * N + 1) * T_IMAGE + cx * nrect * T_IMAGE
		 + pts * T_OUT;
	/* coefficients of the rectangle of orders and the kept lists (56 bytes
	 * an order), the spectrum, the cells, the image and its phasors */
	*bytes = mv * B_POLY + nrect * (16 + 56) + w * h * 16 + cells * 16
		 + cy * (2 * N + 1) * 16
		 + pts * 8 + w * in->nx * 16;
}
