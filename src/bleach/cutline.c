/*
 * cutline.c - bleach along a cutline (thesis 2.2.1: "use SPLAT to generate
 * intensity profiles along a cutline through a 2D mask, and then feed that
 * profile to SAMPLE").  The cutline is the 2D plot file splat's "cutline"
 * statement writes: one curve of (distance along the cut, intensity).
 * Each of nx columns across it (the cutline's points, or "grid nx" of the
 * bleach input) gets the dose intensity * dose and is exposed through the
 * same dose table as the 3D columns (expose.c), baked in z by the same
 * rows (bake.c); a "bake 3d" diffusion also smooths along the cut, with
 * no flux through its ends (a cutline is not periodic, unlike splat's
 * window); then the rate model (devrate.c).  The result is a rate array
 * with ny = 1 over x = distance along the cut, y = 0, z = -thickness..0,
 * carrying M as the 3D one does.
 */
#include "cutline.h"

#include "bleach.h"
#include "fmt_bleach.h"
#include "fmt_plot.h"
#include "fmt_rate.h"
#include "util.h"

#include <stdio.h>
#include <stdlib.h>

/* Most columns across a cutline: the along-cut bake is an nx x nx matrix. */
#define CUT_MAX_NX 20000

/* What cutline_bleach holds while it may still die, reachable from a
 * global (not static: a write-only static may be optimised away) so that
 * the sanitizers do not report a fatal error's memory as a leak. */
struct cutline_held {
	struct plot_file *pf;
	struct ratefile *r;
	double *dose, *col;
	struct dose_table *t;
	struct exposure e;
} cutline_held;
#define held cutline_held

/* Intensity at distance s, linear between the cutline's points (which
 * are in increasing s, as splat writes them). */
static double at(const double *p, int n, double s)
{
	if (s <= p[0])
		return p[1];
	for (int k = 1; k < n; k++)
		if (s <= p[2 * k]) {
			double a = p[2 * (k - 1)], b = p[2 * k];
			double u = b > a ? (s - a) / (b - a) : 1;
			return p[2 * k - 1] + u * (p[2 * k + 1] - p[2 * k - 1]);
		}
	return p[2 * n - 1];
}

void cutline_bleach(const char *cut, const char *input, const char *out, int ascii, int quiet)
{
	struct plot_file *pf = held.pf = fmt_plot_read(cut, 2);
	if (pf->nsets < 1 || pf->sets[0].ncurves < 1)
		die("%s:1: no curve: expected the intensity along a cutline (splat's cutline)", cut);
	const struct plot_curve *cv = &pf->sets[0].curves[0];
	int n = cv->npts;
	if (n < 2)
		die("%s:1: the cutline has %d point; at least 2 are needed", cut, n);
	for (int k = 1; k < n; k++)
		if (!(cv->p[2 * k] > cv->p[2 * k - 2]))
			die("%s:1: distances along the cutline must increase (point %d)", cut, k + 1);
	struct bleach_input in;
	fmt_bleach_read(input, &in);
	if (in.have_car)
		die("%s:%ld: car and peb are not for -cutline: use a "
		    "3D window one period wide", input, in.line_car);
	int nx = in.nx ? in.nx : n, nz = in.nz;
	if (nx > CUT_MAX_NX)
		die("%s:1: %d columns across the cutline is too many (at most %d; set grid nx)",
		    cut, nx, CUT_MAX_NX);
	double s0 = cv->p[0], s1 = cv->p[2 * n - 2];
	double bounds[6] = {s0, s1, 0, 0, -in.thick, 0};
	struct ratefile *r = held.r = fmt_rate_new(nx, 1, nz, bounds);
	double *M = fmt_rate_add_array(r, "M"), *R = fmt_rate_values(r);
	double *dose = held.dose = xreallocarray(NULL, (size_t)nx, sizeof *dose);
	double dmax = 0;
	for (int i = 0; i < nx; i++) {
		double ia = at(cv->p, n, fmt_rate_x(r, i));
		dose[i] = ia > 0 ? in.dose * ia : 0;
		if (dose[i] > dmax)
			dmax = dose[i];
	}
	if (!quiet)
		fprintf(stderr, "%s: cutline of %d points over %g um from %s, largest dose %g mJ/cm2\n",
			util_prog(), n, s1 - s0, cut, dmax);
	struct exposure *e = &held.e;
	if (exposure_init(e, &in, nz, dmax, 1.0) != 0)
		die("%s:%ld: dose %g mJ/cm2 with C = %g cm2/mJ needs more than %g exposure steps",
		    input, in.line_dose, in.dose, in.C, EXPOSE_MAX_STEPS);
	struct dose_table *t = held.t = dose_table_build(e, dmax);
	double dz = in.thick / (nz - 1);
	if (in.bake != BAKE_NONE && in.diffusion > 0)
		bake_rows2(t->M, t->dM, t->nd + 1, nz, dz, in.diffusion);
	double *col = held.col = xreallocarray(NULL, (size_t)nz, sizeof *col);
	for (int i = 0; i < nx; i++) {
		dose_table_eval(t, dose[i], col);
		for (int k = 0; k < nz; k++)
			M[(size_t)k * nx + i] = col[nz - 1 - k];
	}
	if (in.bake == BAKE_3D && in.diffusion > 0 && nx > 2)
		bake_rows(M, nz, nx, (s1 - s0) / (nx - 1), in.diffusion);
	struct devrate dv;
	devrate_init(&dv, &in);
	for (int k = 0; k < nz; k++) {
		double depth = in.thick - k * dz;
		if (depth < 0)
			depth = 0;
		for (int i = 0; i < nx; i++)
			R[(size_t)k * nx + i] = devrate(&dv, M[(size_t)k * nx + i], depth);
	}
	fmt_rate_write(out, r, ascii);
	if (!quiet)
		fprintf(stderr, "%s: wrote %s (2D: %dx1x%d, arrays rate and M)\n", util_prog(), out, nx, nz);
	free(col);
	free(dose);
	dose_table_free(t);
	exposure_free(e);
	fmt_rate_free(r);
	fmt_plot_free(pf);
}
