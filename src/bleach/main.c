/*
 * bleach - 3D exposure of a photoresist (thesis 2.1, 8.6, Appendix B):
 * reads splat's aerial image (a contour-file) and a resist/process
 * description (bleach.5), computes the PAC concentration M(x, y, z) with
 * Dill bleaching under standing waves, the post-exposure bake, and the
 * development rate, and writes the rate array for etch (rval.3D.binary,
 * or rval.3D with -ascii), carrying M as a second array.  -solid also
 * writes mxyz.solid.3D, the surface M = level (Figure 8.15).
 *
 * Order of work: one 1D exposure run tabulated over dose (expose.c), the
 * z bake applied to that table (bake.c: it commutes with the
 * interpolation), every column interpolated from it, the x-y bake on the
 * full array, then the rates.
 */
#include "args.h"
#include "budget.h"
#include "bleach.h"
#include "cutline.h"
#include "fmt_bleach.h"
#include "fmt_contour.h"
#include "fmt_rate.h"
#include "fmt_stack.h"
#include "num.h"
#include "par.h"
#include "util.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
	"usage: bleach [-ascii] [-solid] [-m level] [-o rate-file] [-q] [-dose D] [-big]\n"
	"              [-threads n] contour-file bleach-inputfile\n"
	"       bleach -cutline [-ascii] [-o rate-file] [-q] cutline-plot bleach-inputfile\n"
	"  -cutline       the first file is a cutline of splat (a 2D plot file): write the\n"
	"                 2D rate array (ny = 1) over (distance along the cut, z) for etch2d\n"
	"  -ascii         write the rate array as ASCII rval.3D (default binary rval.3D.binary)\n"
	"  -solid         also write mxyz.solid.3D, the surface M = level, for pdraw\n"
	"  -m level       M of that surface (default 0.8)\n"
	"  -o rate-file   name of the rate array file\n"
	"  -q             no progress lines on stderr\n"
	"  -dose D        exposure dose in mJ/cm2, replacing the input's dose statement\n"
	"  -big           run work estimated beyond the limits (an hour, the\n"
	"                 machine's memory; also SAMPLE3D_BIG=1)\n"
	"  -threads n     threads to use (default $SAMPLE3D_THREADS, else every core)\n";

/* Largest -dose, mJ/cm2: bleach(5)'s bound on the dose statement. */
static const double DOSE_MAX = 1e6;

/* Seconds per rate point (exposure lookup, bake, development rate) and
 * per number written, measured on the development machine.  Memory: M
 * is held (8 bytes a point), the rate is made plane by plane as it is
 * written; per column the dose, a stack's intensities, and one plane of
 * bake scratch per thread.  There is no fixed cap on the grid: the
 * estimate against the machine's memory (budget.h) is the limit. */
static const double T_POINT = 3e-7, T_OUT = 1e-6;

struct options {
	int ascii, solid, quiet, cutline;
	long threads;
	double level;
	const char *output;
	const char *dose;       /* -dose value, checked after parsing */
	const char *contour;
	const char *input;
};

static void parse_options(int argc, char **argv, struct options *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage, NULL, NULL);
	memset(o, 0, sizeof *o);
	o->level = 0.8;
	while (a.i < argc) {
		args_help_exit(&a, 1);
		if (args_flag(&a, "-ascii"))
			o->ascii = 1;
		else if (args_flag(&a, "-solid"))
			o->solid = 1;
		else if (args_flag(&a, "-cutline"))
			o->cutline = 1;
		else if (args_flag(&a, "-q"))
			o->quiet = 1;
		else if (args_flag(&a, "-big"))
			budget_allow_big();
		else if (args_int(&a, "-threads", 1, PAR_MAX_THREADS, &o->threads))
			;
		else if (args_num(&a, "-m", 0, 1, &o->level))
			;
		else if (args_str(&a, "-o", &o->output))
			;
		else if (args_str(&a, "-dose", &o->dose))
			;
		else
			args_operand(&a, (const char **[]){&o->contour, &o->input}, 2, "file");
	}
	if (o->cutline && o->solid)
		args_error(&a, "-solid draws a 3D array: not with -cutline");
	if (!o->contour)
		args_error(&a, "no contour-file");
	else if (!o->input)
		args_error(&a, "no bleach-inputfile");
	args_done(&a, NULL);
}

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
	double target = in->wavelength / (2 * in->index) / PEB_Z_PER_PERIOD;
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
	budget_check(input, what, (double)np * n * (T_PEB + peb_react_seconds(&pp, 1, in->peb_time / n)),
		     (double)np * 3 * sizeof(double));
	double change_xy;
	int nouter = peb_choose_outer(&pp, M, nx, ny, nz, dx, dy, dz, n, &change_xy);
	peb_run(&pp, M, nx, ny, nz, dx, dy, dz, nouter, n / nouter, NULL);
	progress("peb: %g s, acid diffusion length %g um, %d steps (%d in x-y), m of sample "
		 "columns and slices within %.2g of the doubled counts", in->peb_time,
		 sqrt(2 * in->dacid * in->peb_time), n, nouter,
		 change > change_xy ? change : change_xy);
}

int main(int argc, char **argv)
{
	util_setprog(argv[0]);
	struct options o;
	parse_options(argc, argv, &o);
	quiet = o.quiet;
	par_set_threads((int)o.threads);
	if (o.cutline) {
		cutline_bleach(o.contour, o.input, o.output ? o.output : o.ascii ? "rval.2D" :
			       "rval.2D.binary", o.ascii, o.quiet);
		return 0;
	}

	/* -dose D: the range of bleach(5)'s dose statement; a bad value is a
	 * one-line usage error (sweep scripts read it in a log) */
	double dose_override = 0;
	if (o.dose && (!num_parse(o.dose, &dose_override) ||
		       !(dose_override >= 0 && dose_override <= DOSE_MAX)))
		die_status(EXIT_USAGE, "option -dose: expected a number from 0 to %g, found \"%.40s\"",
			   DOSE_MAX, o.dose);

	/* an image, or an image stack (the image at depths in the resist) */
	struct image_stack *st = held.st = fmt_stack_read(o.contour);
	const struct contour *c = st->plane[0];
	struct bleach_input in;
	fmt_bleach_read(o.input, &in);
	if (o.dose)
		in.dose = dose_override;
	if (st->is_stack)
		stack_check(st, &in, o.contour, o.input);

	int nx = in.nx ? in.nx : c->nx, ny = in.nx ? in.ny : c->ny, nz = in.nz;
	double npts = (double)nx * ny * nz, ncold = (double)nx * ny;
	char what[64], where[FILENAME_MAX + 24];
	snprintf(what, sizeof what, "%.3g rate points", npts);
	snprintf(where, sizeof where, "%s:%ld", o.input, in.line_nz ? in.line_nz : 1L);
	budget_check(where, what, npts * (T_POINT + 2 * T_OUT),
		     8 * npts + 8 * ncold * (1 + (st->is_stack ? st->n : 0) + par_threads()) +
		     8 * (double)nz * nz);
	/* the rate file and mxyz.solid.3D are committed together (util.h) */
	aout_defer();
	double bounds[6] = {c->xmin, c->xmax, c->ymin, c->ymax, -in.thick, 0};
	struct ratefile *r = held.r = fmt_rate_new(nx, ny, nz, bounds);
	double *M = fmt_rate_add_array(r, "M");
	/* the rate is made plane by plane as it is written (rate_plane) */
	free(r->arrays[0].v);
	r->arrays[0].v = NULL;
	size_t ncol = (size_t)nx * (size_t)ny;

	/* column doses, mJ/cm2; negative intensities (interpolation ripple
	 * in an aerial image) expose nothing */
	double *dose = held.dose = xreallocarray(NULL, ncol, sizeof *dose);
	/* a stack: every plane's intensity at every column, I[q * n + k] */
	double *I = st->is_stack ? held.I = xreallocarray(NULL, ncol, st->n * sizeof *I) : NULL;
	double dmax = 0;
	for (int j = 0; j < ny; j++)
		for (int i = 0; i < nx; i++) {
			double ia = in.nx ? aerial_at(c, fmt_rate_x(r, i), fmt_rate_y(r, j))
					  : c->z[(size_t)j * nx + i];
			for (int k = 0; I && k < st->n; k++) {
				/* the table must reach the brightest plane's dose */
				const struct contour *ck = st->plane[k];
				double v = in.nx ? aerial_at(ck, fmt_rate_x(r, i), fmt_rate_y(r, j))
						 : ck->z[(size_t)j * nx + i];
				I[((size_t)j * nx + i) * st->n + k] = v;
				if (v > ia)
					ia = v;
			}
			double d = ia > 0 ? in.dose * ia : 0;
			dose[(size_t)j * nx + i] = d;
			if (d > dmax)
				dmax = d;
		}
	if (st->is_stack)
		progress("image stack of %d planes through %g um, %dx%d, from %s, largest "
			 "dose %g mJ/cm2", st->n, st->thick, c->nx, c->ny, o.contour, dmax);
	else
		progress("aerial image %dx%d from %s, largest column dose %g mJ/cm2",
			 c->nx, c->ny, o.contour, dmax);

	/* a CA bake may need a finer z grid than the output's: the exposure
	 * and the bake run on nze nodes, every zr-th of which is output */
	int zr = in.have_car ? car_refine(&in, nz) : 1, nze = zr * (nz - 1) + 1;
	double *Me = M;
	if (zr > 1) {
		double ne = (double)ncol * nze;
		snprintf(what, sizeof what, "%.3g bake points", ne);
		budget_check(o.input, what, ne * T_POINT, ne * 4 * sizeof(double));
		Me = held.Mfine = xreallocarray(NULL, ncol, (size_t)nze * sizeof *Me);
	}
	struct exposure *e = &held.e;
	if (exposure_init(e, &in, nze, dmax, 1.0) != 0) {
		if (o.dose)
			die("-dose %g mJ/cm2 with C = %g cm2/mJ (%s) needs more than %g exposure "
			    "steps", in.dose, in.C, o.input, EXPOSE_MAX_STEPS);
		die("%s:%ld: dose %g mJ/cm2 with C = %g cm2/mJ needs more than %g exposure steps",
		    o.input, in.line_dose, in.dose, in.C, EXPOSE_MAX_STEPS);
	}
	struct dose_table *t = dose_table_build(e, dmax);
	progress("exposure: %d dose steps of %g mJ/cm2, %d points through %g um, %s",
		 t->nd, t->h, nze, in.thick,
		 in.standing ? "thin-film standing waves" : "Beer-Lambert, no reflections");

	double dz = in.thick / (nz - 1);
	/* with a stack the bake smooths the M array instead (stack.c) */
	if (in.bake != BAKE_NONE && in.diffusion > 0 && !st->is_stack) {
		bake_rows2(t->M, t->dM, t->nd + 1, nz, dz, in.diffusion);
	}

	if (st->is_stack) {
		stack_expose(st, &in, e, t, I, ncol, nze, Me);
	} else {
		struct columns cj = {t, dose, Me, ncol, nze,
				     xreallocarray(NULL, (size_t)par_threads() * (size_t)nze,
						   sizeof(double))};
		par_for(ncol, PAR_MIN_COLUMNS, fill_columns, &cj);
		free(cj.col);
	}
	if (in.bake == BAKE_3D && in.diffusion > 0)
		bake_xy(M, nx, ny, nz, (c->xmax - c->xmin) / (nx - 1),
			(c->ymax - c->ymin) / (ny - 1), in.diffusion);
	if (in.bake != BAKE_NONE)
		progress("bake: diffusion length %g um in %s", in.diffusion,
			 in.bake == BAKE_3D ? "x, y and z" : "z");

	if (in.have_car) {
		car_bake(&in, Me, nx, ny, nze, (c->xmax - c->xmin) / (nx - 1),
			 (c->ymax - c->ymin) / (ny - 1), in.thick / (nze - 1), o.input);
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

	struct devrate dv;
	devrate_init(&dv, &in);
	static const char *mname[] = {"kim", "mack", "dill", "canegative", "enhanced", "notch"};
	struct rates rj = {&dv, M, ncol, in.thick, dz, 0, NULL};
	const char *out = o.output ? o.output : o.ascii ? "rval.3D" : "rval.3D.binary";
	fmt_rate_write_planes(out, r, o.ascii, rate_plane, &rj);
	progress("development rate: %s model", mname[in.model]);
	progress("wrote %s (%dx%dx%d, arrays rate and M)", out, nx, ny, nz);
	if (o.solid) {
		long ntri = solid_write("mxyz.solid.3D", M, nx, ny, nz, bounds, o.level);
		progress("wrote mxyz.solid.3D (%ld triangles, M = %g)", ntri, o.level);
	}

	aout_finish();
	free(dose);
	dose_table_free(t);
	exposure_free(e);
	fmt_rate_free(r);
	free(I);
	fmt_stack_free(st);
	return 0;
}
