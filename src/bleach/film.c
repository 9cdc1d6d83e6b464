/*
 * film.c - an image stack that already holds the film (splat -bf with
 * imaging vector, the header word film, stack.5): its planes are the
 * intensity inside the resist with every reflection and the absorption of
 * the unexposed resist, where a plain stack holds the image alone and
 * bleach multiplies it by its thin-film factor.
 *
 * Such a stack is divided, plane by plane, by the normal-incidence 1D
 * factor I_1D(z; M = 1) of the unexposed film at the plane's depth
 * (filmstack_normal, the same stack as thinfilm.c's), and is then
 * exposed as a plain stack (stack.c):
 *   - for a resist that does not bleach (A = 0) stack.c multiplies back
 *     by the same factor at the node's depth, so the node receives the
 *     film stack's intensity itself (exactly at the planes, the ratio
 *     interpolated between them, which keeps the standing waves of the
 *     node's depth even with few planes);
 *   - for a bleaching resist the node receives the stack's intensity
 *     scaled by the ratio of the bleached to the unbleached 1D factors,
 *     I(x, y, z) I_1D(z; M) / I_1D(z; 1), with M the state of a column of
 *     the node's own local dose (stack.c's table): the oblique waves and
 *     the lateral image keep the shape the unbleached film gives them,
 *     and the bleaching changes their strength as it changes the
 *     normal-incidence standing wave.  At normal incidence with a clear
 *     mask the ratio is 1 and the exposure is the 1D bleach exactly
 *     (tests/bleach/013-film-stack.sh).
 */
#include "bleach.h"
#include "filmstack.h"
#include "fmt_stack.h"
#include "util.h"

#include <stdlib.h>

/* Below this the unexposed film's factor is taken as this: only a
 * lossless perfect mirror has a true zero, and no dose is finite there. */
static const double FILM_FLOOR = 1e-12;

void stack_film_divide(struct image_stack *st, const struct bleach_input *in,
		       const char *stack_name, const char *input_name)
{
	if (!in->standing)
		die("%s:1: the image stack holds the film's reflections (splat -bf, the header "
		    "word film), but %s turns standingwaves off", stack_name, input_name);
	struct film_layer layers[BLEACH_MAX_LAYERS];
	struct filmstack fs;
	fmt_bleach_film(in, &fs, layers);
	double *irel = xreallocarray(NULL, (size_t)st->n, sizeof *irel);
	filmstack_normal(&fs, st->n, st->depth, irel);
	for (int k = 0; k < st->n; k++) {
		struct contour *c = st->plane[k];
		double f = 1 / (irel[k] > FILM_FLOOR ? irel[k] : FILM_FLOOR);
		size_t n = (size_t)c->nx * (size_t)c->ny;
		for (size_t i = 0; i < n; i++)
			c->z[i] *= f;
	}
	free(irel);
}
