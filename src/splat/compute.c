/*
 * compute.c - the whole computation of an image spectrum for an input:
 * the pupil (pupil.c), the source (source.c), the mask's diffraction
 * orders that can reach the pupil from some source point (mask.c), then
 * Hopkins' pair sum (tcc.c) or Abbe's sum over source points (abbe.c).
 * Used by main and the tests.
 */
#include "splat.h"

#include <stddef.h>

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
