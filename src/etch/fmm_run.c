/*
 * fmm_run.c - etch -method fmm: the fast-marching engine (fmm.h) run as
 * the ray-string engine is: the refinement -refine asks for, a solve from
 * the resist top or the -seed points, one set of curves.plot (and .2D)
 * per print time, and the same curves.cut.
 */
#include "etch.h"
#include "fmm.h"
#include "fmt_plot.h"
#include "ptimes.h"
#include "util.h"

#include <stdio.h>
#include <stdlib.h>

/* The refinement asked for with -refine, or its auto choice. */
void etch_fmm_refinement(const struct ratefile *r, const struct etch_opts *o, int refine[3])
{
	for (int d = 0; d < 3; d++)
		refine[d] = o->refine[d];
	if (o->refine_auto)
		refine[2] = fmm_auto_refine(r);
}

void etch_run_fmm(struct ratefile *r, const struct rfield *f, const struct etch_opts *o)
{
	int refine[3];
	etch_fmm_refinement(r, o, refine);
	struct fmm *fm = o->seed ? fmm_solve_points(r, refine, &o->seedp[0][0], o->seed)
				 : fmm_solve(r, refine);
	/* the solution holds the rates it used (fm->rate): the file's go
	 * before the surfaces are made (8 bytes a rate point, a third of
	 * the memory left; f's box is all that is read of it below) */
	for (int a = 0; a < r->narrays; a++) {
		free(r->arrays[a].v);
		r->arrays[a].v = NULL;
	}
	int n;
	double *times = ptimes_make(o->et, o->pt, &n);
	/* -last: only the final set is written */
	int first = o->last ? n - 1 : 0;
	fmm_write_curves(fm, times + first, n - first, o->out3d, o->out2d, o->dense, o->tol);
	if (o->cut_axis >= 0 && o->outcut) {
		/* bounds as the ray-string cut: the other axis' range, then z */
		int other = 1 - o->cut_axis;
		double bc[4] = {f->lo[other], f->hi[other], f->lo[2], f->hi[2]};
		struct plot_file *pf = fmt_plot_new(2);
		pf->labels = *fmt_labels_std(o->cut_axis == 0 ? LABELS_CUT_X : LABELS_CUT_Y);
		for (int k = first; k < n; k++)
			fmm_cut(fm, times[k], o->cut_axis, o->cut_value, pf, bc);
		fmt_plot_write(o->outcut, pf);
		fmt_plot_free(pf);
	}
	if (!o->quiet)
		fprintf(stderr, "%s: fast marching: refinement %d x %d x %d%s, %ld grid nodes "
			"reached, %d sets written\n", util_prog(), refine[0], refine[1],
			refine[2], o->refine_auto ? " (auto)" : "", fm->accepted, n);
	free(times);
	fmm_free(fm);
}
