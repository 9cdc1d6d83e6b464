/*
 * accuracy.c - the discretisation error of a CD from solves at two or
 * three resolutions (measure -accuracy, used by the drivers' -accuracy).
 *
 * When the error of a CD is C h^p at grid spacing h, the same feature
 * measured at h (this surface) and at r h (the table of -coarse) differ by
 * C h^p (r^p - 1); Richardson's estimate of the error of the fine CD is
 * therefore |cd(h) - cd(r h)| / (r^p - 1).
 *
 * With a third table (-coarser, at q r h) the order is observed rather
 * than assumed: the two changes e1 = cd(rh) - cd(qrh) and e2 = cd(h) -
 * cd(rh) stand in the ratio e1 / e2 = r^p (q^p - 1) / (r^p - 1) (r^p when
 * q = r), which is solved for p.  The estimate is then trusted only in
 * the asymptotic range, where the changes shrink steadily:
 *   - same sign, ORDER_MIN <= p <= ORDER_MAX: the estimate with p, times
 *     SAFETY;
 *   - same sign, p > ORDER_MAX (above the chain's highest order, the
 *     linear interpolation of the image and the rates): the coarser
 *     change is not yet asymptotic (a coarse level far off, whose large
 *     change makes the ratio look fast), and the estimate falls back to
 *     order 1, times SAFETY;
 *   - opposite signs, the second change smaller: a damped oscillation
 *     about the limit, which then lies within |e2| of cd(h): err = |e2|;
 *   - otherwise (growing, or shrinking slower than ORDER_MIN) the levels
 *     are not in the asymptotic range: the row is refused (counted as
 *     over), with err the estimate at ORDER_MIN (not a bound: the real
 *     error may be larger) and a note on standard error, unless that
 *     estimate is under a tenth of P % of the cd (SMALL_FRAC).
 * Changes both under NOISE_REL of the cd are below anything -accuracy
 * can ask and count as converged (err the two-solve estimate).
 * An earlier change between two solves that both lack the feature (cd
 * 0: a hole not yet open at that height) says nothing of the order: such
 * a row gets the two-table estimate.
 * With two tables the order cannot be observed: p is -order's, by default
 * 1, the lowest in the chain (first-order upwind differences of fast
 * marching; the image and the rates are interpolated linearly, second
 * order), which of the orders 1 and 2 gives the larger estimate; fem
 * passes the order its nominal point showed over three solves.
 *
 * Refinement by axis (the drivers' -accuracy P): when the error is a sum
 * of terms, one per group of axes (the image grid x-y; the points through
 * the resist, z), C h_xy^p + D h_z^q, the change made by refining one
 * group does not depend on the level of the other.  The two changes of
 * one group may then come from solves at different levels of the other
 * (-coarser-fine names the finer solve of the earlier change), and the
 * estimate of the other group's error (its own table's err, -plus) is
 * added to this one's.
 */
#include "measure.h"
#include "fmt_measure.h"
#include "util.h"

#include <math.h>
#include <stdio.h>

/* The observed orders trusted (measure.h). */
static const double ORDER_MIN = ACCURACY_ORDER_MIN, ORDER_MAX = ACCURACY_ORDER_MAX;
/* The safety factor on an estimate whose order is observed from three
 * solves: 1.25, Roache's for a grid convergence index from three grids
 * (P.J. Roache, Verification and Validation in Computational Science and
 * Engineering, 1998): the order itself is known only to the extent the
 * three solves are asymptotic. */
static const double SAFETY = 1.25;
/* Changes under 1e-4 of the cd (0.01 %, a twentieth of the 0.2 % of the
 * references, docs/accuracy.md) are noise for every -accuracy asked. */
static const double NOISE_REL = 1e-4;
/* With P, a row whose solves are not in the asymptotic range but whose
 * estimate at ORDER_MIN (2.4 times the last change) is under a tenth of
 * P % of the cd is trusted: changes that small (a few 1e-4 of the cd) are
 * at the level of the surface's own extraction and measurement, whose
 * steadiness cannot be judged, and they matter to no P asked. */
static const double SMALL_FRAC = 0.1;
/* Two tables' heights agree to their printing resolution, 1e-6 um (a
 * height is printed rounded to it): a larger difference means another
 * resist thickness or other -at/-rel heights. */
static const double Z_TOL = 2e-6;

/* g(p) = r^p (q^p - 1) / (r^p - 1): the ratio of the coarser change to
 * the finer one at order p; increasing in p. */
static double change_ratio(double p, double r, double q)
{
	return pow(r, p) * (pow(q, p) - 1) / (pow(r, p) - 1);
}

/* The order p at which change_ratio is rho, by bisection within
 * [ORDER_MIN / 8, ORDER_MAX * 4] (clamped to its ends): outside, only
 * "below ORDER_MIN" or "above ORDER_MAX" matters. */
static double observed_order(double rho, double r, double q)
{
	double lo = ORDER_MIN / 8, hi = ORDER_MAX * 4;
	if (rho <= change_ratio(lo, r, q))
		return lo;
	if (rho >= change_ratio(hi, r, q))
		return hi;
	for (int i = 0; i < 60; i++) {
		double mid = (lo + hi) / 2;
		if (change_ratio(mid, r, q) < rho)
			lo = mid;
		else
			hi = mid;
	}
	return (lo + hi) / 2;
}

/* Reads TABLE and checks that it is the same measurement as r. */
static void read_same(const char *path, const struct options *o, const struct result *r,
		      struct measure_table *t)
{
	fmt_measure_read(path, t);
	if (t->nrows != r->nrows || t->hole != (o->kind == HOLE)) {
		int n = t->nrows, hole = t->hole;
		fmt_measure_free(t);
		die("%s: a %s at %d heights, this one a %s at %d: not the same measurement",
		    path, hole ? "hole" : "space or line", n,
		    o->kind == HOLE ? "hole" : "space or line", r->nrows);
	}
	for (int i = 0; i < r->nrows; i++)
		if (fabs(t->rows[i].z - r->rows[i].z) > Z_TOL) {
			double zc = t->rows[i].z;
			fmt_measure_free(t);
			die("%s: row %d is at z = %g, this one at %g: not the same measurement",
			    path, i + 1, zc, r->rows[i].z);
		}
}

/* The estimate of one row from its three CDs, finest first (cd0 at h,
 * cd1 at r h, cd2 at q r h); returns 1 when the levels are in the
 * asymptotic range, 0 when the row is refused (*err then the estimate at
 * ORDER_MIN). */
static int three_levels(double cd0, double cd1, double cd2, double r, double q,
			double *err, double *p)
{
	double e2 = cd0 - cd1, e1 = cd1 - cd2;
	double a2 = fabs(e2), a1 = fabs(e1);
	*p = 1;
	*err = a2 / (r - 1);
	if (fmax(a1, a2) <= NOISE_REL * fabs(cd0))
		return 1;
	if (a2 == 0) {
		*p = ORDER_MAX;
		*err = 0;
		return 1;
	}
	if ((e1 > 0) != (e2 > 0) && e1 != 0) {
		/* an oscillation: damped, the limit lies within |e2| */
		*err = a2;
		*p = 0;
		if (a2 < a1)
			return 1;
		*err = a2 / (pow(r, ORDER_MIN) - 1);
		return 0;
	}
	*p = observed_order(a1 / a2, r, q);
	if (*p < ORDER_MIN) {
		*err = a2 / (pow(r, ORDER_MIN) - 1);
		return 0;
	}
	*err = SAFETY * a2 / (pow(r, *p > ORDER_MAX ? 1 : *p) - 1);
	return 1;
}

/* The note on a row whose solves are not in the asymptotic range: the
 * changes (coarser to coarse, coarse to this) and why. */
static void untrusted(const struct options *o, const struct row *w, double e1, double e2,
		      double p)
{
	char why[80];
	if ((e1 > 0) != (e2 > 0) && e1 != 0)
		snprintf(why, sizeof why, "an oscillation that does not shrink");
	else if (fabs(e2) >= fabs(e1))
		snprintf(why, sizeof why, "the changes do not shrink");
	else
		snprintf(why, sizeof why, "the changes shrink at order %.2g, under %g", p,
			 ORDER_MIN);
	warn("%s: at z = %g the cd moved %g then %g um over the last two refinements: "
	     "not in the asymptotic range (%s); err %g um assumes order %g", o->input, w->z,
	     e1, e2, why, w->err, ORDER_MIN);
}

/* The CD of row i of the coarser change's finer solve: -coarser-fine's
 * table when given, else -coarse's. */
static double coarser_fine_cd(const struct measure_table *c, const struct measure_table *cf,
			      int i)
{
	return (cf ? cf : c)->rows[i].cd;
}

int accuracy_estimate(const struct options *o, struct result *r)
{
	struct measure_table c, cc, cf, pl;
	read_same(o->coarse, o, r, &c);
	if (o->coarser)
		read_same(o->coarser, o, r, &cc);
	if (o->coarser_fine)
		read_same(o->coarser_fine, o, r, &cf);
	if (o->plus) {
		read_same(o->plus, o, r, &pl);
		if (!pl.have_err) {
			fmt_measure_free(&pl);
			die("%s: no err column: -plus takes a table of measure -accuracy", o->plus);
		}
	}
	const struct measure_table *cfp = o->coarser_fine ? &cf : NULL;
	int over = 0;
	for (int i = 0; i < r->nrows; i++) {
		struct row *w = &r->rows[i];
		int trusted = 1;
		double c1 = o->coarser ? coarser_fine_cd(&c, cfp, i) : 0;
		if (o->coarser && c1 == 0 && cc.rows[i].cd == 0 && c.rows[i].cd != 0) {
			/* the earlier change is between two solves without the
			 * feature: it says nothing of the order, and the
			 * estimate is the two-solve one */
			w->err = fabs(w->cd - c.rows[i].cd) / (pow(o->ratio, o->order) - 1);
		} else if (o->coarser) {
			double p;
			/* the changes alone enter: cd1 - cd2 is c1 - cd(-coarser) */
			trusted = three_levels(w->cd, c.rows[i].cd,
					       c.rows[i].cd - (c1 - cc.rows[i].cd), o->ratio,
					       o->ratio2, &w->err, &p);
			/* changes too small to judge their steadiness: their
			 * estimate at ORDER_MIN under SMALL_FRAC of P */
			if (!trusted && o->accuracy > 0 &&
			    w->err <= SMALL_FRAC * o->accuracy / 100 * fabs(w->cd))
				trusted = 1;
			else if (!trusted)
				untrusted(o, w, c1 - cc.rows[i].cd, w->cd - c.rows[i].cd, p);
		} else {
			w->err = fabs(w->cd - c.rows[i].cd) / (pow(o->ratio, o->order) - 1);
		}
		if (o->plus)
			w->err += pl.rows[i].err;
		if (o->accuracy > 0 && (!trusted || w->err > o->accuracy / 100 * w->cd))
			over++;
	}
	r->have_err = 1;
	fmt_measure_free(&c);
	if (o->coarser)
		fmt_measure_free(&cc);
	if (o->coarser_fine)
		fmt_measure_free(&cf);
	if (o->plus)
		fmt_measure_free(&pl);
	return over;
}
