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
 * (4M+1)(4N+1) ny + (4M+1) nx ny products and the output about a
 * microsecond a number.  The per-operation times were measured on the
 * development machine (a 2020 x86-64 core): the estimate is meant to be
 * right within a factor of a few, which is all a limit of an hour needs.
 */
#include "splat.h"

#include <math.h>

/* seconds per pair tried and rejected; per quadrature point of an
 * integrated pair; per complex product of the image sums; per number
 * written (measured, see above) */
static const double T_PAIR = 4e-8, T_QUAD = 4e-8, T_IMAGE = 3e-9, T_OUT = 1e-6;

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
	double fm = (p.cutoff + s.smax) * (1 + 1e-9);
	double M = floor(fm * lx), N = floor(fm * ly);
	double nrect = (2 * M + 1) * (2 * N + 1);
	double n = fmin(nrect, M_PI * fm * fm * lx * ly + 2 * (M + N) + 1);
	double tried = n * (n + 1) / 2;
	double r2 = 2 * p.cutoff;
	double near = fmin(n, M_PI * r2 * r2 * lx * ly + 2 * (r2 * lx + r2 * ly) + 1);
	double integrated = n * near / 2;
	double per = s.coherent ? 1 : (double)s.ndisc * nouter * ninner;
	double w = 4 * M + 1, h = 4 * N + 1;
	double cells = (2.0 * m->nrects + 1) * (2.0 * m->nrects + 1);
	double pts = (double)in->nx * in->ny;
	for (int k = 0; k < in->ncutlines; k++)
		pts += in->cutlines[k].npts;
	*orders = n;
	*pairs = tried;
	*seconds = tried * T_PAIR + integrated * per * T_QUAD
		 + (w * h * in->ny + w * pts) * T_IMAGE
		 + cells * (2 * N + 1) * T_IMAGE + (2 * m->nrects + 1) * nrect * T_IMAGE
		 + pts * T_OUT;
	/* coefficients of the rectangle of orders and the kept lists (56 bytes
	 * an order), the spectrum, the cells, the image and its phasors */
	*bytes = nrect * (16 + 56) + w * h * 16 + cells * 16
		 + (2.0 * m->nrects + 1) * (2 * N + 1) * 16
		 + pts * 8 + w * in->nx * 16;
}
