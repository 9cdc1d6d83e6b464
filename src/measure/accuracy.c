/*
 * accuracy.c - the discretisation error of a CD from two solves at
 * different resolutions (measure -accuracy, used by the drivers'
 * -accuracy).
 *
 * The same feature measured on a solve at grid spacing h (this surface)
 * and at r h (the table of -coarse) differ by about C h^p (r^p - 1) when
 * the error is C h^p; Richardson's estimate of the error of the fine CD is
 * therefore |cd(h) - cd(r h)| / (r^p - 1).  The order p is assumed, not
 * observed (two solves cannot give it): p = 1, the lowest order in the
 * chain (first-order upwind differences of fast marching; the image and
 * the rates are interpolated linearly, second order), which makes the
 * estimate the larger one of the two orders.
 */
#include "measure.h"
#include "fmt_measure.h"
#include "util.h"

#include <math.h>

/* The order assumed in the Richardson estimate (see above). */
static const double ORDER = 1;
/* Two tables' heights agree to their printing resolution, 1e-6 um (a
 * height is printed rounded to it): a larger difference means another
 * resist thickness or other -at/-rel heights. */
static const double Z_TOL = 2e-6;

int accuracy_estimate(const struct options *o, struct result *r)
{
	struct measure_table c;
	fmt_measure_read(o->coarse, &c);
	if (c.nrows != r->nrows || c.hole != (o->kind == HOLE)) {
		int n = c.nrows;
		fmt_measure_free(&c);
		die("%s: a %s at %d heights, this one a %s at %d: not the same measurement",
		    o->coarse, c.hole ? "hole" : "space or line", n,
		    o->kind == HOLE ? "hole" : "space or line", r->nrows);
	}
	double f = pow(o->ratio, ORDER) - 1;
	int over = 0;
	for (int i = 0; i < r->nrows; i++) {
		struct row *w = &r->rows[i];
		if (fabs(c.rows[i].z - w->z) > Z_TOL) {
			double zc = c.rows[i].z;
			fmt_measure_free(&c);
			die("%s: row %d is at z = %g, this one at %g: not the same measurement",
			    o->coarse, i + 1, zc, w->z);
		}
		w->err = fabs(w->cd - c.rows[i].cd) / f;
		if (o->accuracy > 0 && w->err > o->accuracy / 100 * w->cd)
			over++;
	}
	r->have_err = 1;
	fmt_measure_free(&c);
	return over;
}
