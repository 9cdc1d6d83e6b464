/*
 * spectrum.c - the image spectrum A(dm, dn) that both imaging methods
 * fill (Hopkins' pair sum, tcc.c; Abbe's sum over source points,
 * abbe.c) and image.c reads: its allocation and the view of one plane of
 * an image stack.  It sits below both methods, and compute.c, which
 * chooses between them, above: no file of the two calls the other.
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
