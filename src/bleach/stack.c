/*
 * stack.c - the exposure from an image stack: the aerial image at several
 * depths inside the resist (splat's resist statement, stack.5),
 * in place of the thesis' one image applied unchanged at every depth.
 *
 * The intensity a node of column (x, y) at depth d receives is the stack's
 * image at that depth, linear in depth between the two planes around it,
 * times the thin-film standing-wave factor of the column.  Each node is
 * exposed to its local dose D = dose I(x, y, d) by the same dose table as
 * a single image (expose.c): its M is that of a column of uniform
 * intensity I(x, y, d) at its depth.  This is exact for a resist that does
 * not bleach (A = 0), where the standing-wave factor I_sw(d) does not
 * change during the exposure and M = exp(-C D I_sw(d)), which is then
 * evaluated in closed form rather than from the table.  For a bleaching
 * resist it neglects how the change of the image through the film changes
 * the bleaching of the resist above a node (for Olin Hunt 6512 and an
 * image falling by 40% through the film, M within 0.01 of the column's own
 * equations, tests/bleach/stack_local.c); the cost stays that of one 1D
 * run, not one per column.
 *
 * The bake in z no longer commutes with the exposure (the table is
 * evaluated at a different dose at every depth), so it smooths the M
 * array itself, column by column.
 */
#include "bleach.h"
#include "fmt_stack.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The stack's thickness and index must equal the resist file's to this
 * fraction: both come from input files written with a few decimals. */
static const double STACK_MATCH = 1e-9;

void stack_check(const struct image_stack *st, const struct bleach_input *in,
		 const char *stack_name, const char *input_name)
{
	if (fabs(st->thick - in->thick) > STACK_MATCH * in->thick)
		die("%s: the image stack is for a resist %g um thick, but %s gives "
		    "thickness %g um", stack_name, st->thick, input_name, in->thick);
	if (fabs(st->index - in->index) > STACK_MATCH * in->index)
		die("%s: the image stack is for a resist of index %g, but %s gives "
		    "index %g", stack_name, st->index, input_name, in->index);
	/* the standing waves and the dose table are for bleach's wavelength:
	 * an image of another is another exposure.  Stacks written before
	 * the wavelength was recorded are taken as they are, with a warning. */
	if (!(st->wavelength > 0)) {
		warn("%s:1: the image stack does not record its wavelength (written by an "
		     "older splat): taking it as %s's %g um", stack_name, input_name,
		     in->wavelength);
		return;
	}
	if (fabs(st->wavelength - in->wavelength) > STACK_MATCH * in->wavelength) {
		double r = st->wavelength / in->wavelength;
		die("%s:1: the image stack was computed at wavelength %g um, but %s gives "
		    "wavelength %g um%s", stack_name, st->wavelength, input_name, in->wavelength,
		    r > 500 && r < 2000 ? " (the stack's wavelength in nanometres?)" :
		    r > 1 / 2000. && r < 1 / 500. ? " (the input's wavelength in nanometres?)" : "");
	}
}

void stack_expose(const struct image_stack *st, const struct bleach_input *in,
		  struct exposure *e, const struct dose_table *t, const double *I,
		  size_t ncol, int nz, double *M)
{
	int np = st->n;
	double dz = in->thick / (nz - 1);
	/* for each node: the plane above it and its weight toward the next */
	int *kk = xreallocarray(NULL, (size_t)nz, sizeof *kk);
	double *ww = xreallocarray(NULL, (size_t)nz, sizeof *ww);
	for (int j = 0, k = 0; j < nz; j++) {
		double d = j == nz - 1 ? st->depth[np - 1] : j * dz;
		while (k < np - 2 && d >= st->depth[k + 1])
			k++;
		double w = (d - st->depth[k]) / (st->depth[k + 1] - st->depth[k]);
		kk[j] = k;
		ww[j] = w < 0 ? 0 : w > 1 ? 1 : w;
	}
	/* A = 0: the factor I_sw of the unbleached column is the factor for
	 * good, and exp(-C D I_sw) is the exact M */
	double *isw = NULL;
	if (in->A == 0) {
		double *one = xreallocarray(NULL, (size_t)nz, sizeof *one);
		isw = xreallocarray(NULL, (size_t)nz, sizeof *isw);
		for (int j = 0; j < nz; j++)
			one[j] = 1;
		exposure_intensity(e, one, isw);
		free(one);
	}
	for (size_t q = 0; q < ncol; q++) {
		const double *iq = I + q * (size_t)np;
		for (int j = 0; j < nz; j++) {
			/* a + w (b - a): exact where the planes agree */
			double a = iq[kk[j]], b = iq[kk[j] + 1];
			double ia = a + ww[j] * (b - a);
			double D = ia > 0 ? in->dose * ia : 0;
			M[(size_t)(nz - 1 - j) * ncol + q] =
				isw ? exp(-in->C * D * isw[j]) : dose_table_node(t, D, j);
		}
	}
	free(isw);
	free(kk);
	free(ww);
	if (in->bake != BAKE_NONE && in->diffusion > 0)
		bake_z_columns(M, ncol, nz, dz, in->diffusion);
}
