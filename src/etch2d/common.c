/*
 * common.c - the set-up every etch2d method shares (e2.h): the box and
 * rate of the 2D array, the print times (the library's rule, ptimes.h),
 * the default cell counts and the limits on steps and sets.
 */
#include "e2.h"

#include "ptimes.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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
	double n = ptimes_count(o->et, o->pt);
	if (n > MAX_PRINTS)
		die("-pt %g against -et %g asks for %.0f print times (at most %d)",
		    o->pt, o->et, n, MAX_PRINTS);
	e->tp = ptimes_make(o->et, o->pt, &e->ntp);
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

void e2_check_steps(const struct e2 *e, double dt)
{
	double n = e->o.et / dt;
	if (!(n <= MAX_STEPS))
		die("%.3g time steps of %g s to -et %g is more than the %.0f allowed (a larger -dt)",
		    n, dt, e->o.et, MAX_STEPS);
}

