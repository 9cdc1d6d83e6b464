/*
 * spectrum.c - the image spectrum A(dm, dn) that both imaging methods
 * fill (Hopkins' pair sum, tcc.c; Abbe's sum over source points,
 * abbe.c) and image.c reads: its allocation, the view of one plane of an
 * image stack, and the whole computation for an input by either method
 * (pupil, source, the orders that reach the pupil, then the method).
 * It sits above both methods, so neither calls the other.
 */
#include "splat.h"
#include "util.h"

#include <stdlib.h>

struct spectrum spectrum_plane(const struct spectrum *sp, int k)
{
	struct spectrum v = *sp;
	v.a = sp->a + (size_t)k * (4 * (size_t)sp->mmax + 1) * (4 * (size_t)sp->nmax + 1);
	v.nplanes = 1;
	return v;
}

struct spectrum *spectrum_new(const struct orders *o, int np)
{
	struct spectrum *sp = xcalloc(1, sizeof *sp);
	sp->lx = o->lx;
	sp->ly = o->ly;
	sp->mmax = o->mmax;
	sp->nmax = o->nmax;
	sp->nplanes = np;
	size_t w = 4 * (size_t)o->mmax + 1, h = 4 * (size_t)o->nmax + 1;
	sp->a = xcalloc(w * h * (size_t)np, sizeof *sp->a);
	return sp;
}

void spectrum_free(struct spectrum *sp)
{
	if (!sp)
		return;
	free(sp->a);
	free(sp);
}

struct spectrum *splat_spectrum(const struct splat_input *in, int nouter, int ninner,
				int *norders)
{
	return splat_spectrum_method(in, SPLAT_HOPKINS, nouter, ninner, norders);
}

struct spectrum *splat_spectrum_method(const struct splat_input *in, enum splat_method method,
				       int nouter, int ninner, int *norders)
{
	struct pupil p;
	struct source s;
	pupil_init(&p, in);
	source_init(&s, in, p.cutoff);
	/* an order reaches the pupil from some source point if |f + s| < NA/lambda */
	struct orders *o = mask_orders(&in->mask, p.cutoff + s.smax);
	if (norders)
		*norders = o->n;
	struct spectrum *sp;
	if (method == SPLAT_ABBE) {
		double h = abbe_cell_default(&p, &s);
		if (nouter > 0 && !s.coherent)
			h *= abbe_cell_default(&p, &s) > 0 ? (double)ABBE_CELLS / nouter : 1;
		sp = abbe_spectrum(o, &p, &s, h);
	} else {
		struct quad q;
		if (nouter <= 0 || ninner <= 0)
			quad_default(&p, &nouter, &ninner);
		quad_init(&q, nouter, ninner);
		sp = tcc_spectrum(o, &p, &s, &q);
		quad_free(&q);
	}
	mask_orders_free(o);
	return sp;
}
