/*
 * run.c - bleach's 3D pipeline (thesis 2.1, 8.6, Appendix B), from the
 * aerial image or image stack and the resist description to the rate
 * array (main.c only reads the command line).
 *
 * Order of work: one 1D exposure run tabulated over dose (expose.c), the
 * z bake applied to that table (bake.c: it commutes with the
 * interpolation), every column interpolated from it, the x-y bake on the
 * full array, then the rates.
 */
#include "bleach.h"

#include "budget.h"
#include "fmt_bleach.h"
#include "fmt_contour.h"
#include "fmt_rate.h"
#include "fmt_stack.h"
#include "par.h"
#include "util.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Seconds per rate point (exposure lookup, bake, development rate) and
 * per number written in the binary and the ASCII form, measured with one
 * core on the contact example's image at 201^2 and 401^2 columns of 300
 * points (tests/bench/estimate.sh: 0.065 us a point in all with the
 * binary output, 0.16 us with -ascii).  Memory: M
 * is held (8 bytes a point), the rate is made plane by plane as it is
 * written; per column the dose, a stack's intensities, and one plane of
 * bake scratch per thread.  There is no fixed cap on the grid: the
 * estimate against the machine's memory (budget.h) is the limit. */
static const double T_POINT = 4.5e-8, T_OUT_BIN = 1e-8, T_OUT_ASCII = 5.5e-8;

static int quiet;

/* What main holds while it may still die: kept reachable from here so
 * that a fatal error (die exits at once) is not reported as a leak by
 * the sanitizers; main frees it all on success. */
static struct {
	struct image_stack *st;
	double *I;
	struct ratefile *r;
	double *dose;
	struct exposure e;
	double *Mfine;
} held;

static void progress(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void progress(const char *fmt, ...)
{
	if (quiet)
		return;
	va_list ap;
	va_start(ap, fmt);
	fprintf(stderr, "%s: ", util_prog());
	vfprintf(stderr, fmt, ap);
	fputc('\n', stderr);
	va_end(ap);
}

/* Aerial intensity at (x, y), bilinear between the contour-file's points
 * (resampling for "grid nx ny"). */
static double aerial_at(const struct contour *c, double x, double y)
{
	double u = (x - c->xmin) / (c->xmax - c->xmin) * (c->nx - 1);
	double v = (y - c->ymin) / (c->ymax - c->ymin) * (c->ny - 1);
	if (!(u > 0)) u = 0;
	if (!(v > 0)) v = 0;
	if (u > c->nx - 1) u = c->nx - 1;
	if (v > c->ny - 1) v = c->ny - 1;
	int i = (int)u, j = (int)v;
	if (i > c->nx - 2) i = c->nx - 2;
	if (j > c->ny - 2) j = c->ny - 2;
	double s = u - i, t = v - j;
	const double *z = c->z + (size_t)j * c->nx + i;
	return (1 - s) * (1 - t) * z[0] + s * (1 - t) * z[1] +
	       (1 - s) * t * z[c->nx] + s * t * z[c->nx + 1];
}

/* Columns per thread at least: below this the pool costs more than it
 * saves (a column is nz Hermite evaluations). */
#define PAR_MIN_COLUMNS 64

/* M of every column from the dose table, columns split among threads
 * (each column depends only on its own dose). */
struct columns {
	const struct dose_table *t;
	const double *dose;
	double *M;
	size_t ncol;
	int nz;
	double *col;                    /* nz scratch values per worker */
};

static void fill_columns(void *ctx, size_t lo, size_t hi, int worker)
{
	struct columns *c = ctx;
	int nz = c->nz;
	double *col = c->col + (size_t)worker * (size_t)nz;
	for (size_t q = lo; q < hi; q++) {
		dose_table_eval(c->t, c->dose[q], col);
		/* node j is at depth j dz; the rate file's k = 0 is the bottom */
		for (int k = 0; k < nz; k++)
			c->M[(size_t)k * c->ncol + q] = col[nz - 1 - k];
	}
}

/* The development rate of one plane, made as the rate file is written
 * (fmt_rate_write_planes: the rate array is never held whole), its
 * columns split among threads; each point depends only on its own M. */
struct rates {
	const struct devrate *dv;
	const double *M;
	size_t ncol;
	double thick, dz;
	int k;                          /* the plane being made */
	double *plane;
};

#define PAR_MIN_RATES 4096

static void fill_rates(void *ctx, size_t lo, size_t hi, int worker)
{
	(void)worker;
	struct rates *r = ctx;
	double depth = r->thick - (double)r->k * r->dz;
	if (depth < 0)
		depth = 0;
	const double *mk = r->M + (size_t)r->k * r->ncol;
	for (size_t q = lo; q < hi; q++)
		r->plane[q] = devrate(r->dv, mk[q], depth);
}

static void rate_plane(void *ctx, int array, int k, double *plane)
{
	(void)array;            /* only the rate (array 0) is made */
	struct rates *r = ctx;
	r->k = k;
	r->plane = plane;
	par_for(r->ncol, PAR_MIN_RATES, fill_rates, r);
}

/* Seconds per point and column step of the reaction-diffusion bake
 * (measured), to refuse a bake beyond the budget. */
static const double T_PEB = 8e-8;

/* z nodes of the CA bake a node of the output grid spans: the bake runs
 * on a z grid of at least PEB_Z_PER_PERIOD points a standing-wave period
 * and four per acid diffusion length (second-order differences err by
 * (kappa dz)^2 / 12 of a mode's decay rate: 0.8% for the standing waves
 * at 20 points a period, measured 3e-3 in m for examples/car-krf-lines
 * at 21 and 6e-4 at 42: 40 is the rule), the exposure computed on it, and the output
 * keeps every r-th node. */
#define PEB_Z_PER_PERIOD 40
#define PEB_Z_MAX_REFINE 16

static int car_refine(const struct bleach_input *in, int nz)
{
	double dz = in->thick / (nz - 1);
	/* without standing waves only the acid diffusion sets the grid */
	double target = in->standing ? in->wavelength / (2 * in->index) / PEB_Z_PER_PERIOD
				     : HUGE_VAL;
	double L = sqrt(2 * in->dacid * in->peb_time);
	if (L > 0 && L / 4 < target)
		target = L / 4;
	double r = ceil(dz / target - 1e-9);
	if (!(r >= 1))
		r = 1;
	if (r > PEB_Z_MAX_REFINE)
		r = PEB_Z_MAX_REFINE;
	return (int)r;
}

/* The shot noise of the stochastic statement (shotnoise.c), with its
 * progress line. */
static double *shotnoise_report(const struct bleach_input *in, double *h, int nx, int ny,
				int nz, double dx, double dy, double dz)
{
	struct shotnoise_info si = {0};
	double *q = shotnoise_apply(in, h, nx, ny, nz, dx, dy, dz, &si);
	progress("stochastic: seed %ld, photon noise %s, acid noise %s; voxels %.3g nm^3 of "
		 "%.3g PAG, photons of %.4g eV, %.3g PAG converted per photon the resist absorbs",
		 in->seed, in->noise_photons ? "on" : "off", in->noise_acid ? "on" : "off",
		 si.voxel_nm3, si.npag, si.photon_ev, si.yield);
	return q;
}

/* The bake's progress line: counts of the bake (the coarse one's before
 * the fine one's when extrapolated: nc 0 when not) and the estimate. */
static void bake_report(const struct peb_params *pp, int nc, int kc, int n, int nouter,
			double change)
{
	char counts[80];
	if (nc)
		snprintf(counts, sizeof counts, "%d and %d steps (%d and %d in x-y) extrapolated", nc,
			 n, kc, nouter);
	else
		snprintf(counts, sizeof counts, "%d steps (%d in x-y)", n, nouter);
	progress("peb: %g s, acid diffusion length %g um, %s, m of sample columns and slices "
		 "within %.2g of converged (estimated)", pp->t, sqrt(2 * pp->dh * pp->t), counts,
		 change);
}

/* The deterministic bake of h0 = M in n steps, nouter in x-y, m out; or,
 * where peb_choose_extrapolated finds a pair of fewer steps whose m
 * extrapolated is within PEB_TOL, those two bakes and their Richardson
 * extrapolation (the two cost 3/4 of n steps or less).  Reports the
 * counts; *change the estimate of m's error. */
static void car_bake_plain(const struct peb_params *pp, double *M, int nx, int ny, int nz,
			   double dx, double dy, double dz, int n, int nouter, double *change)
{
	size_t np = (size_t)nx * (size_t)ny * (size_t)nz;
	double rich;
	int c[4];
	int ok = peb_choose_extrapolated(pp, M, nx, ny, nz, dx, dy, dz, n, nouter, c, &rich);
	/* the x-y diffusion at every step instead of every fourth: its
	 * splitting error is smaller, and where the reaction costs more than
	 * an x-y step (orders other than 1: a logarithm or quadrature a point)
	 * the two bakes cost about the plain one (the order-2 line image of
	 * tests/bench/car.sh: 1.40 s for 16 steps, 4 in x-y; 1.37 s for 4 and
	 * 8 with x-y at every step).  At order 1 they cost more: the 100 x
	 * 100 x 200 contact window of tests/bench/car.sh, 2.90 s for 32 steps
	 * with 8 in x-y, 4.69 s for 8 and 16 with x-y at every step. */
	if (!ok && pp->p != 1 && nouter < n && 4 * nouter >= n)
		ok = peb_choose_extrapolated(pp, M, nx, ny, nz, dx, dy, dz, n, n, c, &rich);
	if (!ok) {
		peb_run(pp, M, nx, ny, nz, dx, dy, dz, nouter, n / nouter, NULL);
		bake_report(pp, 0, 0, n, nouter, *change);
		return;
	}
	double *mc = xreallocarray(NULL, np, sizeof *mc);
	memcpy(mc, M, np * sizeof *mc);
	peb_run(pp, mc, nx, ny, nz, dx, dy, dz, c[3], c[2] / c[3], NULL);
	peb_run(pp, M, nx, ny, nz, dx, dy, dz, c[1], c[0] / c[1], NULL);
	for (size_t k = 0; k < np; k++)
		M[k] = peb_extrapolate(mc[k], M[k]);
	free(mc);
	*change = rich;
	bake_report(pp, c[2], c[3], c[0], c[1], rich);
}

/* The post-exposure bake of a chemically amplified positive resist
 * (peb.c): M = 1 - h0 in, m out. */
static void car_bake(const struct bleach_input *in, double *M, int nx, int ny, int nz,
		     double dx, double dy, double dz, const char *input)
{
	size_t ncol = (size_t)nx * (size_t)ny, np = ncol * (size_t)nz;
	for (size_t k = 0; k < np; k++)
		M[k] = 1 - M[k];
	struct peb_params pp;
	peb_params_from(&pp, in);
	peb_set_budget((double)np, T_PEB, input);
	double change;
	int n = peb_choose_steps(&pp, M, ncol, nz, dz, &change);
	if (!(change < PEB_TOL))
		die("%s:%ld: the bake did not converge in %d steps (m still changes by %g)",
		    input, in->line_peb, n, change);
	char what[64];
	snprintf(what, sizeof what, "%.3g bake points x %d steps", (double)np, n);
	/* h, q, the m integral, and for a stochastic run their noise, which
	 * about doubles the work (the full bake: the noisy quencher alone);
	 * at order 1 with a quencher the products of the m integral's
	 * logarithms (peb.c); a deterministic run m of its coarse bake when
	 * it extrapolates */
	int lin = in->stochastic && !in->bake_full;
	budget_check(input, what, (double)np * n * (1 + lin) *
		     (T_PEB + peb_react_seconds(&pp, 1, in->peb_time / n)),
		     (double)np * (3 + 3 * lin + in->bake_full + (in->porder == 1 && in->kq > 0) +
				   !in->stochastic) *
			     sizeof(double));
	double change_xy;
	int nouter = peb_choose_outer(&pp, M, nx, ny, nz, dx, dy, dz, n, 0, &change_xy);
	/* x-y diffusion at every column step and still not converged: the
	 * columns' count is too small for the x-y structure (a window of
	 * lines on a 1 nm grid); doubled until the slices converge */
	while (!(change_xy < PEB_TOL) && nouter == n && n < PEB_MAX_STEPS) {
		n *= 2;
		nouter = peb_choose_outer(&pp, M, nx, ny, nz, dx, dy, dz, n, n / 4, &change_xy);
	}
	if (!(change_xy < PEB_TOL))
		die("%s:%ld: the bake did not converge in %d steps (m of the x-y slices still "
		    "changes by %g)", input, in->line_peb, n, change_xy);
	/* shot noise after the step choice: the counts are chosen for the
	 * deterministic acid, which the linear-noise bake follows, the same
	 * for every seed */
	double *dh = NULL, *dq = NULL;
	if (change_xy > change)
		change = change_xy;
	if (!in->stochastic) {
		car_bake_plain(&pp, M, nx, ny, nz, dx, dy, dz, n, nouter, &change);
		return;
	}
	if (in->bake_full) {
		/* bake full: the ordinary bake of the noisy acid and quencher */
		dq = shotnoise_report(in, M, nx, ny, nz, dx, dy, dz);
		if (!dq) {
			dq = xreallocarray(NULL, np, sizeof *dq);
			for (size_t k = 0; k < np; k++)
				dq[k] = in->q0;
		}
		peb_run_field(&pp, M, dq, nx, ny, nz, dx, dy, dz, nouter, n / nouter, NULL);
	} else {
		/* the noise as the drawn values less the deterministic ones */
		dh = xreallocarray(NULL, np, sizeof *dh);
		memcpy(dh, M, np * sizeof *dh);
		dq = shotnoise_report(in, dh, nx, ny, nz, dx, dy, dz);
		for (size_t k = 0; k < np; k++) {
			dh[k] -= M[k];
			if (dq)
				dq[k] -= in->q0;
		}
		if (!dq)
			dq = xcalloc(np, sizeof *dq);
		peb_run_noise(&pp, M, dh, dq, nx, ny, nz, dx, dy, dz, nouter, n / nouter, NULL);
	}
	free(dh);
	free(dq);
	bake_report(&pp, 0, 0, n, nouter, change);
}

/* The state of one run, passed between the steps below. */
struct run {
	const struct bleach_opts *o;
	struct bleach_input in;
	const struct contour *c;        /* the image, or the stack's first plane */
	int nx, ny, nz;
	size_t ncol;
	double bounds[6];
	double *M;                      /* the rate file's M array */
	double dmax;                    /* the largest column dose, mJ/cm2 */
};

/* Reads the image (or stack) and the resist file, checks the budget and
 * makes the rate file with its M array; the rate array itself is made
 * plane by plane as it is written (rate_plane). */
static void read_inputs(struct run *u)
{
	const struct bleach_opts *o = u->o;
	/* an image, or an image stack (the image at depths in the resist) */
	struct image_stack *st = held.st = fmt_stack_read(o->contour);
	const struct contour *c = u->c = st->plane[0];
	struct bleach_input *in = &u->in;
	fmt_bleach_read(o->input, in);
	if (o->have_dose)
		in->dose = o->dose;
	if (o->seed >= 0 && !in->stochastic)
		die("-seed %ld: %s has no stochastic statement (bleach(5))", o->seed, o->input);
	if (o->seed >= 0)
		in->seed = o->seed;
	if (o->nz) {
		/* -nz: the grid statement's nz, with the file's check that the
		 * standing waves are sampled (two points a period) */
		in->nz = o->nz;
		double period = in->wavelength / (2 * in->index);
		if (in->standing && in->thick / (in->nz - 1) > period / 2)
			die_status(EXIT_USAGE, "option -nz %d: %g um a point through %g um of "
				   "resist, more than half the standing-wave period %g um",
				   in->nz, in->thick / (in->nz - 1), in->thick, period);
	}
	if (st->is_stack)
		stack_check(st, in, o->contour, o->input);
	if (st->film)
		stack_film_divide(st, in, o->contour, o->input);

	int nx = u->nx = in->nx ? in->nx : c->nx, ny = u->ny = in->nx ? in->ny : c->ny;
	int nz = u->nz = in->nz;
	double npts = (double)nx * ny * nz, ncold = (double)nx * ny;
	char what[64], where[FILENAME_MAX + 24];
	snprintf(what, sizeof what, "%.3g rate points", npts);
	snprintf(where, sizeof where, "%s:%ld", o->input, in->line_nz ? in->line_nz : 1L);
	budget_check(where, what, npts * (T_POINT + 2 * (o->ascii ? T_OUT_ASCII : T_OUT_BIN)),
		     8 * npts + 8 * ncold * (1 + (st->is_stack ? st->n : 0) + par_threads()) +
		     8 * (double)nz * nz);
	/* the rate file and mxyz.solid.3D are committed together (util.h) */
	aout_defer();
	double bounds[6] = {c->xmin, c->xmax, c->ymin, c->ymax, -in->thick, 0};
	memcpy(u->bounds, bounds, sizeof bounds);
	struct ratefile *r = held.r = fmt_rate_new(nx, ny, nz, u->bounds);
	u->M = fmt_rate_add_array(r, "M");
	/* the rate is made plane by plane as it is written (rate_plane) */
	free(r->arrays[0].v);
	r->arrays[0].v = NULL;
	u->ncol = (size_t)nx * (size_t)ny;
}

/* Column doses, mJ/cm2, into held.dose, and for a stack every plane's
 * intensity at every column into held.I (I[q * n + k]); negative
 * intensities (interpolation ripple in an aerial image) expose nothing. */
static void column_doses(struct run *u)
{
	const struct image_stack *st = held.st;
	const struct contour *c = u->c;
	const struct bleach_input *in = &u->in;
	const struct ratefile *r = held.r;
	int nx = u->nx, ny = u->ny;
	double *dose = held.dose = xreallocarray(NULL, u->ncol, sizeof *dose);
	double *I = st->is_stack ? held.I = xreallocarray(NULL, u->ncol, st->n * sizeof *I)
				 : NULL;
	double dmax = 0;
	for (int j = 0; j < ny; j++)
		for (int i = 0; i < nx; i++) {
			double ia = in->nx ? aerial_at(c, fmt_rate_x(r, i), fmt_rate_y(r, j))
					   : c->z[(size_t)j * nx + i];
			for (int k = 0; I && k < st->n; k++) {
				/* the table must reach the brightest plane's dose */
				const struct contour *ck = st->plane[k];
				double v = in->nx ? aerial_at(ck, fmt_rate_x(r, i), fmt_rate_y(r, j))
						  : ck->z[(size_t)j * nx + i];
				I[((size_t)j * nx + i) * st->n + k] = v;
				if (v > ia)
					ia = v;
			}
			double d = ia > 0 ? in->dose * ia : 0;
			dose[(size_t)j * nx + i] = d;
			if (d > dmax)
				dmax = d;
		}
	u->dmax = dmax;
	if (st->is_stack)
		progress("image stack of %d planes through %g um, %dx%d, from %s, largest "
			 "dose %g mJ/cm2", st->n, st->thick, c->nx, c->ny, u->o->contour, dmax);
	else
		progress("aerial image %dx%d from %s, largest column dose %g mJ/cm2",
			 c->nx, c->ny, u->o->contour, dmax);
}

/* The exposure of every node into u->M, with the Gaussian bake and the
 * CA bake; returns the dose table (the caller frees it). */
static struct dose_table *expose(struct run *u)
{
	const struct bleach_opts *o = u->o;
	const struct image_stack *st = held.st;
	const struct contour *c = u->c;
	const struct bleach_input *in = &u->in;
	int nx = u->nx, ny = u->ny, nz = u->nz;
	size_t ncol = u->ncol;
	double *M = u->M;
	/* a CA bake may need a finer z grid than the output's: the exposure
	 * and the bake run on nze nodes, every zr-th of which is output */
	int zr = in->have_car ? car_refine(in, nz) : 1, nze = zr * (nz - 1) + 1;
	double *Me = M;
	if (zr > 1) {
		double ne = (double)ncol * nze;
		char what[64];
		snprintf(what, sizeof what, "%.3g bake points", ne);
		budget_check(o->input, what, ne * T_POINT, ne * 4 * sizeof(double));
		Me = held.Mfine = xreallocarray(NULL, ncol, (size_t)nze * sizeof *Me);
	}
	struct exposure *e = &held.e;
	if (exposure_init(e, in, nze, u->dmax, 1.0) != 0) {
		if (o->have_dose)
			die("-dose %g mJ/cm2 with C = %g cm2/mJ (%s) needs more than %g exposure "
			    "steps", in->dose, in->C, o->input, EXPOSE_MAX_STEPS);
		die("%s:%ld: dose %g mJ/cm2 with C = %g cm2/mJ needs more than %g exposure steps",
		    o->input, in->line_dose, in->dose, in->C, EXPOSE_MAX_STEPS);
	}
	struct dose_table *t = dose_table_build(e, u->dmax);
	progress("exposure: %d dose steps of %g mJ/cm2, %d points through %g um, %s",
		 t->nd, t->h, nze, in->thick,
		 in->standing ? "thin-film standing waves" : "Beer-Lambert, no reflections");

	double dz = in->thick / (nz - 1);
	/* with a stack the bake smooths the M array instead (stack.c) */
	if (in->bake != BAKE_NONE && in->diffusion > 0 && !st->is_stack) {
		bake_rows2(t->M, t->dM, t->nd + 1, nz, dz, in->diffusion);
	}

	if (st->is_stack) {
		stack_expose(st, in, e, t, held.I, ncol, nze, Me);
	} else {
		struct columns cj = {t, held.dose, Me, ncol, nze,
				     xreallocarray(NULL, (size_t)par_threads() * (size_t)nze,
						   sizeof(double))};
		par_for(ncol, PAR_MIN_COLUMNS, fill_columns, &cj);
		free(cj.col);
	}
	if (in->bake == BAKE_3D && in->diffusion > 0)
		bake_xy(M, nx, ny, nz, (c->xmax - c->xmin) / (nx - 1),
			(c->ymax - c->ymin) / (ny - 1), in->diffusion);
	if (in->bake != BAKE_NONE)
		progress("bake: diffusion length %g um in %s", in->diffusion,
			 in->bake == BAKE_3D ? "x, y and z" : "z");

	if (in->have_car) {
		car_bake(in, Me, nx, ny, nze, (c->xmax - c->xmin) / (nx - 1),
			 (c->ymax - c->ymin) / (ny - 1), in->thick / (nze - 1), o->input);
		if (zr > 1) {
			for (int k = 0; k < nz; k++)
				memcpy(M + (size_t)k * ncol, Me + (size_t)k * zr * ncol,
				       ncol * sizeof *M);
			free(Me);
			held.Mfine = NULL;
			progress("peb: on %d points through the resist, one in %d written",
				 nze, zr);
		}
	}
	return t;
}

void bleach_run(const struct bleach_opts *o)
{
	quiet = o->quiet;
	struct run u = {.o = o};
	read_inputs(&u);
	column_doses(&u);
	struct dose_table *t = expose(&u);

	const struct bleach_input *in = &u.in;
	struct devrate dv;
	devrate_init(&dv, in);
	static const char *mname[] = {"kim", "mack", "dill", "canegative", "enhanced", "notch"};
	struct rates rj = {&dv, u.M, u.ncol, in->thick, in->thick / (u.nz - 1), 0, NULL};
	const char *out = o->output ? o->output : o->ascii ? "rval.3D" : "rval.3D.binary";
	fmt_rate_write_planes(out, held.r, o->ascii, rate_plane, &rj);
	progress("development rate: %s model", mname[in->model]);
	progress("wrote %s (%dx%dx%d, arrays rate and M)", out, u.nx, u.ny, u.nz);
	if (o->solid) {
		long ntri = solid_write("mxyz.solid.3D", u.M, u.nx, u.ny, u.nz, u.bounds,
					o->level);
		progress("wrote mxyz.solid.3D (%ld triangles, M = %g)", ntri, o->level);
	}

	aout_finish();
	free(held.dose);
	dose_table_free(t);
	exposure_free(&held.e);
	fmt_rate_free(held.r);
	free(held.I);
	fmt_stack_free(held.st);
}
