/*
 * lateral - a rate that varies across as well as down: an isolated space
 * (a Gaussian of 0.35 um across) under standing waves, 0.003 to 0.11 um/s,
 * on a 41 x 51 rate grid over 2 x 1 um (cells of 0.05 x 0.02 um),
 * developed from the top for 60 s.  The reference is the fast-marching
 * solution on a grid refined 16 times in x and 8 in z (0.003125 x 0.0025
 * um), an independent method: it knows nothing of rays or strings.
 *
 * Checks, for the profiles at 20, 40 and 60 s, the distance of every
 * profile point to the reference profile: median under half a cell and
 * 95th percentile under two cells (the accuracy asked of a surface method; a
 * cell is the rate grid's smaller spacing, 0.02 um).  Held to them: the
 * surface methods of semicircle.c (raystring, string, fmm; the ray below) and
 * Dill's cells, each at its defaults except where said:
 *   - raystring (S_ideal 0.04 um, the width / 50) and fmm (200 x 100);
 *   - the string at S_ideal = one cell (0.02 um).  At the default 0.04 its
 *     median is about 0.6 cells, whatever the step (0.02 s: the same),
 *     falling to 0.05 at 0.01 um: the error is the resolution of the
 *     directions it takes from its own segments (6.2), not its time
 *     stepping; that run is printed for the record;
 *   - cell (200 x 100 cells of 0.01 um).
 * Not held: the ray method (6.3) keeps every ray, also those that lost the
 * race to a faster neighbour's front (no delooping, no filling of the
 * ray-scarce regions: 6.3.3): its 95th percentile is about 7 cells from
 * 20 s, its median grows to 3 cells by 60 s.  Its rays themselves are
 * held: at 20 s their median end lies within RAY_MED cells of the
 * reference (a wrong ray equation moves it).  Huygens at its default 10
 * cells a step is printed only (the thesis' verdict on it, chapter 4).
 */
#include "e2test.h"

#define CELL 0.02       /* um, the rate grid's smaller spacing */
#define MED_TOL 0.5     /* cells: the median asked of a method */
#define P95_TOL 2.0     /* cells: the 95th percentile asked */
#define RAY_MED 0.1     /* cells: the ray ends at 20 s (0.01 measured) */
#define ALL 3           /* check every print time */

static double space(double x, double z)
{
	return 0.003 + 0.107 * exp(-(x * x) / (0.35 * 0.35)) *
	       (0.55 - 0.45 * cos(2 * M_PI * (z + 0.02) / 0.13));
}

static int fails;
static struct e2 ref;

/* Checks the first nsets print times against med and p95 (cells); 0:
 * printed only. */
static void check(const char *name, int method, const struct ratefile *r, double seg,
		  int nsets, double med_tol, double p95_tol)
{
	struct e2opts o;
	t_opts(&o, method, 60, 20);
	o.seg = seg;
	struct rfield f;
	struct e2 e;
	t_run(&e, r, &f, &o);
	double med = 0, p95 = 0;
	int strict = nsets > 0;
	if (!strict || nsets > e.pf->nsets)
		nsets = e.pf->nsets;
	for (int s = 0; s < nsets; s++) {
		const struct plot_set *set = &e.pf->sets[s];
		size_t n = 0, cap = 0;
		double *d = NULL;
		for (int c = 0; c < set->ncurves; c++)
			for (int k = 0; k < set->curves[c].npts; k++) {
				xgrow(&d, &cap, n + 1, sizeof *d);
				d[n++] = t_dist(&ref.pf->sets[s], set->curves[c].p + 2 * k) / CELL;
			}
		if (n == 0) {
			printf("FAIL %s: no profile at t = %g\n", name, e.tp[s]);
			fails++;
			continue;
		}
		double m = t_quantile(d, n, 0.5), q = t_quantile(d, n, 0.95);
		if (m > med) med = m;
		if (q > p95) p95 = q;
		free(d);
	}
	printf("%-26s distance to the reference, cells: median %.3f, 95th percentile %.3f%s\n",
	       name, med, p95, strict ? "" : " (not checked)");
	if (strict && !(med < med_tol && p95 < p95_tol)) {
		printf("FAIL %s: want median < %g, 95th percentile < %g cells\n", name, med_tol, p95_tol);
		fails++;
	}
	e2_free(&e);
}

int main(void)
{
	util_setprog("lateral");
	double b[4] = {-1, 1, -1, 0};
	struct ratefile *r = t_rate(41, 51, b, space);
	struct e2opts o;
	t_opts(&o, M_FMM, 60, 20);
	o.cells[0] = 640, o.cells[1] = 400;
	struct rfield f;
	t_run(&ref, r, &f, &o);
	check("raystring", M_RAYSTRING, r, 0, ALL, MED_TOL, P95_TOL);
	check("string S_ideal 0.02", M_STRING, r, CELL, ALL, MED_TOL, P95_TOL);
	/* the string's directions come from the surface it has (6.2): at
	 * two cells a segment about half a cell off, printed for the record */
	check("string S_ideal 0.04", M_STRING, r, 0, 0, 0, 0);
	check("fmm", M_FMM, r, 0, ALL, MED_TOL, P95_TOL);
	check("cell", M_CELL, r, 0, ALL, MED_TOL, P95_TOL);
	check("ray, 20 s (median only)", M_RAY, r, 0, 1, RAY_MED, INFINITY);
	check("ray", M_RAY, r, 0, 0, 0, 0);
	check("huygens", M_HUYGENS, r, 0, 0, 0, 0);
	e2_free(&ref);
	fmt_rate_free(r);
	return fails ? 1 : 0;
}
