/*
 * zonly - a rate depending only on z (thesis 7.4: standing waves).  The
 * flat front must reach the depth z(t) at which the integral of dz / R(z)
 * from the top equals t, where R(z) is the rate as etch interpolates it
 * from the array (piecewise linear in z between grid points: the integral
 * is done exactly, cell by cell, here, independently of etch's advance).
 *
 * Checks, for a smooth rate and for 10:1 standing waves (R between 0.1
 * and 1 um/s, period 0.125 um, 300 points over 1 um):
 *   - at the default time step every node is within 1e-3 (relative to
 *     the depth) of the exact depth (REL_TOL);
 *   - the error falls as the step shrinks (halving dt twice must divide
 *     it by at least 4, i.e. at least first order), for the default
 *     Runge-Kutta advance and for the thesis' first-order step (-euler);
 *   - the mesh checker is clean after every step.
 * Prints the errors and the observed orders (log2 of the error ratio per
 * halving) for the report.
 */
#include "etch.h"

#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define REL_TOL 1e-3    /* the accuracy asked at the default time step */

static double smooth(double z) { return 0.6 + 0.3 * sin(3 * z); }
static double waves(double z) { return 0.55 + 0.45 * cos(2 * M_PI * z / 0.125); }

/* Exact depth at time t for the piecewise-linear interpolant of v[k] at
 * z_k = zmin + k h (k = 0..nz-1), starting from the top. */
static double exact_z(const double *v, int nz, double zmin, double h, double t)
{
	for (int k = nz - 1; k > 0; k--) {
		double rh = v[k], rl = v[k - 1];
		double b = (rl - rh) / h;       /* R = rh + b u, u down from z_k */
		double cell = b != 0 ? log1p((rl - rh) / rh) / b : h / rh;
		if (cell >= t) {
			double u = b != 0 ? rh * expm1(b * t) / b : rh * t;
			return zmin + k * h - u;
		}
		t -= cell;
	}
	return zmin;
}

static double run(double (*rate)(double), double dt, int euler, double et, double *zex)
{
	int nz = 300;
	double b[6] = {-0.5, 0.5, -0.5, 0.5, -1, 0};
	struct ratefile *r = fmt_rate_new(3, 3, nz, b);
	double *v = fmt_rate_values(r), *col = xmalloc(nz * sizeof *col);
	for (int k = 0; k < nz; k++) {
		col[k] = rate(fmt_rate_z(r, k));
		for (int i = 0; i < 9; i++)
			v[(size_t)k * 9 + i] = col[k];
	}
	struct rfield f;
	fmt_rate_field(&f, r, "zonly");
	struct etch_opts o = {0};
	o.et = et;
	o.dt = dt;
	o.seg = 0.25;
	o.smax = ETCH_SMAX;
	o.smin = ETCH_SMIN;
	o.rl = ETCH_RL;
	o.clip_every = ETCH_CLIP;
	o.cut_axis = -1;
	o.euler = euler;
	o.check = 1;
	o.quiet = 1;
	struct etch_stats st = {0};
	struct mesh *m = etch_run(&f, &o, &st);
	double h = 1.0 / (nz - 1);
	*zex = exact_z(col, nz, -1, h, et);
	double err = 0;
	for (size_t i = 0; i < m->nnode; i++) {
		double e = fabs(m->node[i].p[2] - *zex);
		if (e > err)
			err = e;
	}
	if (dt <= 0)
		printf("  default dt %g s (max|grad R| %g /s)\n", st.dt, f.gmax);
	mesh_free(m);
	fmt_rate_free(r);
	free(col);
	return err / fabs(*zex);
}

int main(void)
{
	int bad = 0;
	struct { const char *name; double (*rate)(double); double et; } cases[] = {
		{"smooth 0.6 + 0.3 sin(3z)", smooth, 1.0},
		{"10:1 standing waves 0.55 + 0.45 cos(2 pi z / 0.125)", waves, 2.0},
	};
	for (int c = 0; c < 2; c++) {
		double zex;
		printf("%s, %g s:\n", cases[c].name, cases[c].et);
		double e0 = run(cases[c].rate, 0, 0, cases[c].et, &zex);
		printf("  exact depth %.9f um; default step: relative error %.3g\n", zex, e0);
		if (!(e0 <= REL_TOL)) {
			printf("FAIL: error %g above %g at the default step\n", e0, REL_TOL);
			bad = 1;
		}
		for (int euler = 0; euler < 2; euler++) {
			double dt = euler ? 0.02 : 0.04, e[3];
			for (int k = 0; k < 3; k++)
				e[k] = run(cases[c].rate, dt / (1 << k), euler, cases[c].et, &zex);
			printf("  %s: dt %g %g %g: errors %.3g %.3g %.3g, orders %.2f %.2f\n",
			       euler ? "thesis step" : "Runge-Kutta", dt, dt / 2, dt / 4,
			       e[0], e[1], e[2], log2(e[0] / e[1]), log2(e[1] / e[2]));
			if (!(e[2] <= e[0] / 4)) {
				printf("FAIL: no convergence\n");
				bad = 1;
			}
		}
	}
	return bad;
}
