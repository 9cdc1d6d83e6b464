/*
 * semicircle - uniform etching from a seed on the resist top (thesis
 * Figures 3.3, 4.2, 6.4, 7.7): with R = 1 um/s everywhere the front at
 * time t is the half circle of radius t about the seed, the top being a
 * wall the front slides along.
 *
 * Checks every point of every print time's profile (t = 0.2 .. 1 s):
 *   - ray, string, raystring and fmm lie within 1 % of the radius
 *     (the figure);
 *   - huygens at 40 cells a step (400 cells/um, dt 0.1 s) within 3 %;
 *   - each surface method's profile reaches the top at both ends (it
 *     covers the whole half circle, rays along the top included);
 *   - Dill's cells overshoot the circle most near 22.5 degrees: the
 *     octagon of Figure 3.3, more than 4 % at 200 cells/um where string
 *     and ray are exact (an overshoot below that means the removal times
 *     a/R, a/(sqrt 2 R), a/(2R) are not what runs).
 */
#include "e2test.h"

#define TOL_SURF 0.01   /* issue 17: ray, string, raystring, fmm */
#define TOL_HUY 0.03    /* issue 17: huygens at 40 cells a step */
#define OCT_MIN 0.04    /* a perfect octagon overshoots 8.2 %; the cells'
			 * is rounder at the seed, about 6-7 % at 1 um */

static double one(double x, double z) { (void)x; (void)z; return 1; }

static int fails;

static void check(const char *name, int method, long cx, long cz, double dt, double seg,
		  double tol, int ends)
{
	double b[4] = {-1.2, 1.2, -1.2, 0};
	struct ratefile *r = t_rate(3, 3, b, one);
	struct e2opts o;
	t_opts(&o, method, 1, 0.2);
	o.seeded = 1;
	o.cells[0] = cx, o.cells[1] = cz;
	o.dt = dt;
	o.seg = seg;
	struct rfield f;
	struct e2 e;
	t_run(&e, r, &f, &o);
	double worst = 0;
	for (int s = 0; s < e.pf->nsets; s++) {
		double t = e.tp[s];
		const struct plot_set *set = &e.pf->sets[s];
		double zend_min = 0;
		int npts = 0;
		for (int c = 0; c < set->ncurves; c++) {
			const struct plot_curve *cv = &set->curves[c];
			for (int k = 0; k < cv->npts; k++) {
				double x = cv->p[2 * k], z = cv->p[2 * k + 1];
				double err = fabs(hypot(x, z) / t - 1);
				if (err > worst)
					worst = err;
				npts++;
			}
			double ze = fmin(cv->p[1], cv->p[2 * cv->npts - 1]);
			if (ze < zend_min)
				zend_min = ze;
		}
		if (npts == 0) {
			printf("FAIL %s: no profile at t = %g\n", name, t);
			fails++;
		}
		if (ends && (set->ncurves != 1 || zend_min < -1e-9)) {
			printf("FAIL %s: t = %g: %d curves, lowest end z = %g (want one, ends on the top)\n",
			       name, t, set->ncurves, zend_min);
			fails++;
		}
	}
	printf("%-10s largest radial error %.5f (tolerance %.3f)\n", name, worst, tol);
	if (!(worst <= tol)) {
		printf("FAIL %s\n", name);
		fails++;
	}
	e2_free(&e);
	fmt_rate_free(r);
}

/* Dill's cells: the overshoot along 22.5 degrees at t = 1. */
static void octagon(void)
{
	double b[4] = {-1.2, 1.2, -1.2, 0};
	struct ratefile *r = t_rate(3, 3, b, one);
	struct e2opts o;
	t_opts(&o, M_CELL, 1, 0);
	o.seeded = 1;
	o.cells[0] = 480, o.cells[1] = 240;     /* 200 cells/um */
	struct rfield f;
	struct e2 e;
	t_run(&e, r, &f, &o);
	double over = 0;
	const struct plot_set *set = &e.pf->sets[0];
	for (int c = 0; c < set->ncurves; c++)
		for (int k = 0; k < set->curves[c].npts; k++) {
			double x = set->curves[c].p[2 * k], z = set->curves[c].p[2 * k + 1];
			double d = hypot(x, z) - 1;
			if (d > over)
				over = d;
		}
	printf("cell       octagon overshoot %.4f (want above %.2f)\n", over, OCT_MIN);
	if (!(over > OCT_MIN)) {
		printf("FAIL cell octagon\n");
		fails++;
	}
	e2_free(&e);
	fmt_rate_free(r);
}

int main(void)
{
	util_setprog("semicircle");
	check("raystring", M_RAYSTRING, 0, 0, 0.1, 0.02, TOL_SURF, 1);
	check("string", M_STRING, 0, 0, 0.1, 0.02, TOL_SURF, 1);
	check("ray", M_RAY, 0, 0, 0.1, 0.02, TOL_SURF, 1);
	check("fmm", M_FMM, 480, 240, 0, 0, TOL_SURF, 0);
	check("huygens", M_HUYGENS, 960, 480, 0.1, 0, TOL_HUY, 0);
	octagon();
	return fails ? 1 : 0;
}
