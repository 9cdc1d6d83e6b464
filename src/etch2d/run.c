/*
 * run.c - the set-up every method shares: the box and rate of the 2D
 * array, the print times, the default cell counts, and the dispatch.
 */
#include "etch2d.h"

#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Print times closer than this (s) to the next are merged with it: a
 * -pt that divides -et must not add a set a rounding error before it. */
#define PT_TINY 1e-9
/* Most print times a run may ask for (-pt tiny against -et). */
#define MAX_PRINTS 100000
/* Most time steps of a run: beyond, a run takes hours (-dt tiny). */
#define MAX_STEPS 1e7

double e2_rate(const struct e2 *e, double x, double z, double g[2])
{
	double p[3] = {x, e->y, z}, g3[3];
	double r = rfield_eval(e->f, p, g ? g3 : NULL);
	if (g) {
		g[0] = g3[0];
		g[1] = g3[2];
	}
	return r;
}

void e2_init(struct e2 *e, struct rfield *f, const struct e2opts *o)
{
	memset(e, 0, sizeof *e);
	f->flat_outside = 1;
	e->f = f;
	e->o = *o;
	e->x0 = f->lo[0], e->x1 = f->hi[0];
	e->z0 = f->lo[2], e->z1 = f->hi[2];
	e->y = f->lo[1];
	double pt = o->pt > 0 ? o->pt : o->et;
	double n = floor(o->et / pt + PT_TINY);
	if (n > MAX_PRINTS)
		die("-pt %g against -et %g asks for %.0f print times (at most %d)",
		    o->pt, o->et, n, MAX_PRINTS);
	e->tp = xreallocarray(NULL, (size_t)n + 2, sizeof *e->tp);
	for (long k = 1; k <= (long)n; k++) {
		double t = k * pt;
		if (t < o->et - PT_TINY)
			e->tp[e->ntp++] = t;
	}
	e->tp[e->ntp++] = o->et;
	e->pf = fmt_plot_new(2);
	e->pf->labels = *fmt_labels_std(LABELS_PROFILE2D);
	/* a start profile given (by -start, or by a caller's points): one of
	 * no points (start NULL) is an error there, not a flat top */
	if (o->start || o->startfile)
		e2_start_init(e);
}

void e2_free(struct e2 *e)
{
	free(e->tp);
	free(e->sp);
	e->sp = NULL;
	fmt_plot_free(e->pf);
	e->tp = NULL;
	e->pf = NULL;
}

void e2_cells(const struct e2 *e, int *nx, int *nz)
{
	/* default: 200 cells along the longer side (Table 10.1's 200 x 100
	 * on the thesis' 2 x 1 um box), square cells */
	double w = e->x1 - e->x0, d = e->z1 - e->z0;
	if (e->o.cells[0] > 0) {
		*nx = (int)e->o.cells[0];
		*nz = (int)e->o.cells[1];
		return;
	}
	double a = fmax(w, d) / 200;
	*nx = (int)fmax(1, ceil(w / a - 1e-9));
	*nz = (int)fmax(1, ceil(d / a - 1e-9));
}

void e2_run(struct e2 *e)
{
	clock_t c0 = clock();
	switch (e->o.method) {
	case M_CELL: run_cell(e); break;
	case M_HUYGENS: run_huygens(e); break;
	case M_STRING: run_string(e); break;
	case M_RAY: run_ray(e); break;
	case M_FMM: run_fmm(e); break;
	default: run_raystring(e); break;
	}
	e->st.cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
}

void e2_check_steps(const struct e2 *e, double dt)
{
	double n = e->o.et / dt;
	if (!(n <= MAX_STEPS))
		die("%.3g time steps of %g s to -et %g is more than the %.0f allowed (a larger -dt)",
		    n, dt, e->o.et, MAX_STEPS);
}
