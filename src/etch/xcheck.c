/*
 * xcheck.c - etch -xcheck: the ray-string surface measured against the
 * independent fast-marching engine (fmm.h).  After a ray-string run, the
 * nodes of each set of curves.plot are compared with the surface T = t of
 * a fast-marching solve of the same rate file: the distance of a node
 * from it is the engines' disagreement there, and its median and 95th
 * percentile per print time are reported on stderr.
 */
#include "etch.h"
#include "fmm.h"
#include "fmt_plot.h"
#include "ptimes.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int cmp_point(const void *a, const void *b)
{
	const double *p = a, *q = b;
	for (int d = 0; d < 3; d++)
		if (p[d] != q[d])
			return p[d] < q[d] ? -1 : 1;
	return 0;
}

/* Sorts n points (x y z triples) and drops repeats; returns the count. */
static size_t unique_points(double *p, size_t n)
{
	if (n == 0)
		return 0;
	qsort(p, n, 3 * sizeof *p, cmp_point);
	size_t m = 1;
	for (size_t i = 1; i < n; i++)
		if (cmp_point(p + 3 * i, p + 3 * (m - 1)) != 0)
			memmove(p + 3 * m++, p + 3 * i, 3 * sizeof *p);
	return m;
}

/* -xcheck: the cross-check of the two engines (etch(1)): the vertices of every set of the ray-string
 * curves.plot against the fast-marching surface T = t at its print time,
 * median and 95th percentile of their distances, in um and in rate-grid
 * z cells.  The solve is refined in z as -refine says, by default auto,
 * with the rate linear between nodes as the ray-string engine takes it
 * (fmm_solve_linear), so that the engines differ by their discretisations
 * alone. */
void etch_xcheck(const struct ratefile *r, struct etch_opts *o)
{
	if (!o->refine_auto && o->refine[0] * o->refine[1] * o->refine[2] == 1)
		o->refine_auto = 1;
	int refine[3];
	etch_fmm_refinement(r, o, refine);
	struct fmm *fm = fmm_solve_linear(r, refine);
	struct plot_file *pf = fmt_plot_read(o->out3d, 3);
	int n;
	double *times = ptimes_make(o->et, o->pt, &n);
	/* the rate grid is anisotropic (a resist has ~0.002 um in z against
	 * ~0.1 um in x and y): report both cell sizes */
	double hz = (r->zmax - r->zmin) / (r->nz - 1);
	double hxy = fmax((r->xmax - r->xmin) / (r->nx - 1), (r->ymax - r->ymin) / (r->ny - 1));
	for (int k = 0; k < pf->nsets && k < n; k++) {
		const struct plot_set *set = &pf->sets[k];
		/* the mesh nodes: each triangle's three corners (its fourth
		 * point closes it), every node once */
		double *p = xreallocarray(NULL, (size_t)set->ncurves * 3 + 1, 3 * sizeof *p);
		size_t np = 0;
		for (int c = 0; c < set->ncurves; c++)
			for (int q = 0; q < 3 && q < set->curves[c].npts; q++)
				memcpy(p + 3 * np++, set->curves[c].p + 3 * q, 3 * sizeof *p);
		np = unique_points(p, np);
		double med, p95;
		fmm_distance_stats(fm, p, np, times[k], &med, &p95);
		fprintf(stderr, "%s: xcheck t = %g s: %zu nodes from the fast-marching "
			"surface (z x%d): median %.3g um, 95%% %.3g um (%.2f and %.2f x-y cells, "
			"%.2f and %.2f z cells)\n", util_prog(), times[k], np, refine[2], med, p95,
			med / hxy, p95 / hxy, med / hz, p95 / hz);
		free(p);
	}
	free(times);
	fmt_plot_free(pf);
	fmm_free(fm);
}
