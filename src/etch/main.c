/*
 * etch - 3D development of a resist by the ray-string algorithm (thesis
 * chapters 7 and 8): a triangulated surface is moved through the etch-rate
 * array of bleach, each node along a ray obeying the ray equation.  See
 * man/man1/etch.1 and etch.h.
 */
#include "args.h"
#include "budget.h"
#include "etch.h"
#include "fmm.h"
#include "fmt_plot.h"
#include "fmt_rate.h"
#include "fmt_vtk.h"
#include "num.h"
#include "par.h"
#include "util.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
	"usage: etch -et etchtime [-pt printtime] [-dt timestep] [-seg length]\n"
	"            [-smax r] [-smin r] [-rl length] [-linear] [-euler] [-clip n]\n"
	"            [-deloop [n]] [-cut x|y value] [-seed x y z]... [-method ray|fmm|cell|huygens]\n"
	"            [-refine n|nx ny nz|auto] [-dense] [-tol um]\n"
	"            [-o curves.plot] [-no2d] [-last] [-vtk file.vtp] [-check] [-n] [-q] [-big]\n"
	"            [-threads n] rate-file\n"
	"  -et etchtime     total development time, s (required)\n"
	"  -pt printtime    print interval, s (default: only the end)\n"
	"  -dt timestep     time step, s (default: 0.25 / max|grad R|,\n"
	"                   at most S_ideal / max R)\n"
	"  -seg length      ideal segment length S_ideal, um (default: box side / 30,\n"
	"                   at most the rate grid's x-y spacing, divided to\n"
	"                   under 0.4 of the standing waves' period)\n"
	"  -smax r          cut segments longer than r S_ideal (default 1.2)\n"
	"  -smin r          merge segments shorter than r S_ideal (default 0.2)\n"
	"  -rl length       recursive length of vector checking (default 0.1)\n"
	"  -linear          place new nodes by linear, not arc, interpolation\n"
	"  -euler           the thesis' first-order ray step instead of Runge-Kutta\n"
	"  -clip n          clip the mesh every n steps (default 10)\n"
	"  -deloop [n]      remove loops at every print time (and every n steps)\n"
	"  -cut x|y value   also write the profile in the plane x (y) = value\n"
	"                   (mid: the middle of the rate box)\n"
	"                   to curves.cut\n"
	"  -seed x y z      start from a seed point instead of the resist top\n"
	"                   (repeat for several, at most 16)\n"
	"  -method ray|fmm  ray-string (default) or fast-marching engine; cell or\n"
	"                   huygens: the thesis' cell methods (cells of side -seg)\n"
	"  -xcheck          after a ray-string run, report how far its nodes lie\n"
	"                   from the fast-marching surface at each print time\n"
	"  -refine n|nx ny nz|auto  with -method fmm: subdivide every rate cell\n"
	"                   n times in z (or nx, ny, nz in x, y, z); auto picks z\n"
	"                   from the standing waves (the default)\n"
	"  -dense           with -method fmm: write flat regions cell by cell, as\n"
	"                   marching tetrahedra give them (default: large triangles)\n"
	"  -tol um          with -method fmm: decimate each surface, no kept vertex\n"
	"                   farther than um from the planes of the triangles it\n"
	"                   replaced (default: 0.02 of the x-y grid spacing; 0:\n"
	"                   only exactly flat regions merged)\n"
	"  -o curves.plot   3D output; the 2D projection goes to curves.plot.2D,\n"
	"                   the cut to curves.cut\n"
	"  -no2d            do not write the 2D projection (curves.plot.2D)\n"
	"  -last            write only the final set (-pt still paces -deloop)\n"
	"  -vtk file.vtp    also write the surfaces as VTK XML PolyData (ParaView)\n"
	"  -check           check the mesh's consistency after every step, and\n"
	"                   deloop's near searches against a full search\n"
	"  -n               check the command line only: read and write nothing\n"
	"  -q               no progress or summary on stderr\n"
	"  -big             run work estimated beyond the limits (an hour, the\n"
	"                   machine's memory; also SAMPLE3D_BIG=1)\n"
	"  -threads n       threads to use (default $SAMPLE3D_THREADS, else every core)\n";

static int parse3(struct args *a, const char *opt, double v[3])
{
	if (a->i >= a->argc || strcmp(a->argv[a->i], opt) != 0)
		return 0;
	a->i++;
	for (int k = 0; k < 3; k++) {
		if (a->i >= a->argc || !num_parse(a->argv[a->i], &v[k])) {
			args_error(a, "option %s needs three numbers", opt);
			return 1;
		}
		a->i++;
	}
	return 1;
}

/* -refine n | nx ny nz | auto (FMM_REFINE_MAX per axis) */
enum { FMM_REFINE_MAX = 64 };
static void parse_refine(struct args *a, struct etch_opts *o)
{
	char **v = a->argv + a->i + 1;
	int left = a->argc - a->i - 1;
	long n[3];
	if (left >= 1 && strcmp(v[0], "auto") == 0) {
		o->refine_auto = 1;
		a->i += 2;
		return;
	}
	if (left >= 3 && num_parse_count(v[0], 1, FMM_REFINE_MAX, &n[0]) &&
	    num_parse_count(v[1], 1, FMM_REFINE_MAX, &n[1]) &&
	    num_parse_count(v[2], 1, FMM_REFINE_MAX, &n[2])) {
		for (int d = 0; d < 3; d++)
			o->refine[d] = (int)n[d];
		a->i += 4;
		return;
	}
	if (left >= 1 && num_parse_count(v[0], 1, FMM_REFINE_MAX, &n[0])) {
		o->refine[0] = o->refine[1] = 1;
		o->refine[2] = (int)n[0];
		a->i += 2;
		return;
	}
	args_error(a, "option -refine needs auto, n or nx ny nz (whole numbers from 1 to %d)",
		   FMM_REFINE_MAX);
	a->i = a->argc;
}

static void parse_options(int argc, char **argv, struct etch_opts *o)
{
	struct args a;
	args_init(&a, argc, argv);
	memset(o, 0, sizeof *o);
	o->et = -1;
	o->smax = ETCH_SMAX;
	o->smin = ETCH_SMIN;
	o->rl = ETCH_RL;
	o->clip_every = ETCH_CLIP;
	o->cut_axis = -1;
	o->refine[0] = o->refine[1] = o->refine[2] = 1;
	o->out3d = "curves.plot";
	o->tol = -1;
	const char *method = "ray", *cutaxis = NULL;
	long threads = 0;
	int refine_given = 0;
	args_usage(&a, usage, NULL, NULL);
	while (a.i < argc) {
		const char *s = argv[a.i];
		args_help_exit(&a, 1);
		if (args_num(&a, "-et", 0, 1e12, &o->et) ||
		    args_num(&a, "-pt", 0, 1e12, &o->pt) ||
		    args_num(&a, "-dt", 0, 1e12, &o->dt) ||
		    args_num(&a, "-seg", 0, 1e12, &o->seg) ||
		    args_num(&a, "-smax", 0, 1e6, &o->smax) ||
		    args_num(&a, "-smin", 0, 1e6, &o->smin) ||
		    args_num(&a, "-rl", 0, 2, &o->rl) ||
		    args_num(&a, "-tol", 0, 1e6, &o->tol) ||
		    args_int(&a, "-clip", 1, 1000000000, &o->clip_every) ||
		    args_int(&a, "-threads", 1, PAR_MAX_THREADS, &threads) ||
		    args_str(&a, "-o", &o->out3d) ||
		    args_str(&a, "-vtk", &o->outvtk) ||
		    args_str(&a, "-method", &method))
			;
		else if (args_flag(&a, "-linear"))
			o->linear = 1;
		else if (args_flag(&a, "-euler"))
			o->euler = 1;
		else if (args_flag(&a, "-deloop")) {
			/* an optional step count: -deloop n (thesis 8.4.3) */
			char *end;
			long n = a.i < argc ? strtol(argv[a.i], &end, 10) : 0;
			if (a.i < argc && end != argv[a.i] && *end == '\0') {
				if (n < 1)
					args_error(&a, "-deloop n needs a positive step count");
				o->deloop_every = n;
				a.i++;
			}
			o->deloop = 1;
		}
		else if (args_flag(&a, "-xcheck"))
			o->xcheck = 1;
		else if (args_flag(&a, "-check"))
			o->check = 1;
		else if (args_flag(&a, "-no2d"))
			o->no2d = 1;
		else if (args_flag(&a, "-last"))
			o->last = 1;
		else if (args_flag(&a, "-dense"))
			o->dense = 1;
		else if (args_flag(&a, "-n"))
			o->dryrun = 1;
		else if (args_flag(&a, "-q"))
			o->quiet = 1;
		else if (args_flag(&a, "-big"))
			budget_allow_big();
		else if (parse3(&a, "-seed", o->seedp[o->seed < ETCH_MAX_SEEDS ? o->seed
							       : ETCH_MAX_SEEDS - 1])) {
			if (o->seed < ETCH_MAX_SEEDS)
				o->seed++;
			else
				args_error(&a, "more than %d -seed points", ETCH_MAX_SEEDS);
		}
		else if (strcmp(s, "-refine") == 0) {
			parse_refine(&a, o);
			refine_given = 1;
		}
		else if (strcmp(s, "-cut") == 0) {
			if (a.i + 2 < argc && strcmp(argv[a.i + 2], "mid") == 0) {
				o->cut_mid = 1;
				cutaxis = argv[a.i + 1];
				a.i += 3;
			} else if (a.i + 2 >= argc || !num_parse(argv[a.i + 2], &o->cut_value)) {
				args_error(&a, "option -cut needs x or y and a number (or mid)");
				a.i = argc;
			} else {
				cutaxis = argv[a.i + 1];
				a.i += 3;
			}
		} else
			args_operand(&a, (const char **[]){&o->input}, 1, "rate file");
	}
	if (!o->input)
		args_error(&a, "no rate file");
	if (o->et < 0)
		args_error(&a, "-et etchtime is required");
	else if (!(o->et > 0))
		args_error(&a, "-et must be positive");
	if (o->dt < 0 || o->seg < 0 || o->pt < 0)
		args_error(&a, "-dt, -seg and -pt must be positive");
	if (o->smax > 0 && o->smin * 2 >= o->smax)
		args_error(&a, "-smin must be less than half of -smax "
			   "(a cut segment would be merged again)");
	if (!(o->smax > 1) && o->smax != 0)
		args_error(&a, "-smax must be greater than 1");
	if (!(o->rl > 0))
		args_error(&a, "-rl must be positive");
	if (strcmp(method, "ray") == 0)
		o->method = METHOD_RAY;
	else if (strcmp(method, "fmm") == 0)
		o->method = METHOD_FMM;
	else if (strcmp(method, "cell") == 0 || strcmp(method, "huygens") == 0)
		o->method = method[0] == 'c' ? METHOD_CELL : METHOD_HUYGENS;
	else
		args_error(&a, "-method must be ray, fmm, cell or huygens, not %.40s", method);
	if (o->last && (o->method == METHOD_CELL || o->method == METHOD_HUYGENS))
		args_error(&a, "-last goes with -method ray or fmm");
	if ((o->refine_auto || o->refine[0] * o->refine[1] * o->refine[2] > 1) &&
	    o->method != METHOD_FMM && !o->xcheck)
		args_error(&a, "-refine goes with -method fmm or -xcheck");
	if (o->method >= METHOD_CELL && (o->xcheck || o->deloop || cutaxis))
		args_error(&a, "-method cell and huygens take no -xcheck, -deloop or -cut");
	if (o->dense && o->method != METHOD_FMM)
		args_error(&a, "-dense goes with -method fmm");
	if (o->tol >= 0 && o->method != METHOD_FMM)
		args_error(&a, "-tol goes with -method fmm");
	if (o->tol >= 0 && o->dense)
		args_error(&a, "-tol and -dense exclude each other (-dense writes every triangle)");
	if (o->xcheck && o->method == METHOD_FMM)
		args_error(&a, "-xcheck compares the ray-string run with fast marching: not with -method fmm");
	/* fast marching by default resolves the standing waves in z */
	if (o->method == METHOD_FMM && !refine_given)
		o->refine_auto = 1;
	if (cutaxis) {
		if (strcmp(cutaxis, "x") == 0)
			o->cut_axis = 0;
		else if (strcmp(cutaxis, "y") == 0)
			o->cut_axis = 1;
		else
			args_error(&a, "-cut takes x or y, not %.40s", cutaxis);
	}
	args_done(&a, NULL);
	par_set_threads((int)threads);
}

/* out3d.2D, and out3d with .plot replaced by .cut */
static void output_names(struct etch_opts *o, char **n2, char **nc)
{
	size_t len = strlen(o->out3d);
	*n2 = xmalloc(len + 4);
	sprintf(*n2, "%s.2D", o->out3d);
	*nc = xmalloc(len + 5);
	if (len > 5 && strcmp(o->out3d + len - 5, ".plot") == 0)
		sprintf(*nc, "%.*s.cut", (int)(len - 5), o->out3d);
	else
		sprintf(*nc, "%s.cut", o->out3d);
	o->out2d = o->no2d ? NULL : *n2;
	o->outcut = o->cut_axis >= 0 ? *nc : NULL;
}

/* A usage error found after reading the rate file (it gives the box). */
static _Noreturn void usage_die(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static _Noreturn void usage_die(const char *fmt, ...)
{
	va_list ap;
	fprintf(stderr, "%s: ", util_prog());
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
	fputs(usage, stderr);
	exit(EXIT_USAGE);
}

static void check_inside(const struct rfield *f, struct etch_opts *o)
{
	if (o->cut_axis >= 0 && o->cut_mid)     /* -cut x|y mid */
		o->cut_value = (f->lo[o->cut_axis] + f->hi[o->cut_axis]) / 2;
	for (int k = 0; k < o->seed; k++)
		for (int d = 0; d < 3; d++)
			if (o->seedp[k][d] < f->lo[d] || o->seedp[k][d] > f->hi[d])
				usage_die("-seed point outside the rate box (%c from %g to %g)",
					  "xyz"[d], f->lo[d], f->hi[d]);
	if (o->cut_axis >= 0) {
		int d = o->cut_axis;
		if (o->cut_value < f->lo[d] || o->cut_value > f->hi[d])
			usage_die("-cut %c %g is outside the rate box (%g to %g)",
				  "xy"[d], o->cut_value, f->lo[d], f->hi[d]);
	}
}

/* The print times: every pt seconds, and the end (run.c hits the same). */
static double *print_times(const struct etch_opts *o, int *n)
{
	double *times = NULL;
	size_t cap = 0;
	*n = 0;
	for (long k = 1;; k++) {
		double tp = o->pt > 0 ? k * o->pt : o->et;
		if (tp > o->et * (1 - 1e-12))
			tp = o->et;
		xgrow(&times, &cap, (size_t)*n + 1, sizeof *times);
		times[(*n)++] = tp;
		if (tp >= o->et)
			break;
	}
	return times;
}

/* The refinement asked for with -refine, or its auto choice. */
static void refinement(const struct ratefile *r, const struct etch_opts *o, int refine[3])
{
	for (int d = 0; d < 3; d++)
		refine[d] = o->refine[d];
	if (o->refine_auto)
		refine[2] = fmm_auto_refine(r);
}

static int cmp_point(const void *a, const void *b)
{
	const double *p = a, *q = b;
	for (int d = 0; d < 3; d++)
		if (p[d] != q[d])
			return p[d] < q[d] ? -1 : 1;
	return 0;
}

/* Sorts n points (x y z triples) and drops repeats; returns the count. */
static size_t unique_points(double *p, size_t n)
{
	if (n == 0)
		return 0;
	qsort(p, n, 3 * sizeof *p, cmp_point);
	size_t m = 1;
	for (size_t i = 1; i < n; i++)
		if (cmp_point(p + 3 * i, p + 3 * (m - 1)) != 0)
			memmove(p + 3 * m++, p + 3 * i, 3 * sizeof *p);
	return m;
}

/* -xcheck: the cross-check of the two engines (etch(1), issue of the
 * fast-marching engine): the vertices of every set of the ray-string
 * curves.plot against the fast-marching surface T = t at its print time,
 * median and 95th percentile of their distances, in um and in rate-grid
 * z cells.  The solve is refined in z as -refine says, by default auto. */
static void xcheck(const struct ratefile *r, struct etch_opts *o)
{
	if (!o->refine_auto && o->refine[0] * o->refine[1] * o->refine[2] == 1)
		o->refine_auto = 1;
	int refine[3];
	refinement(r, o, refine);
	struct fmm *fm = fmm_solve(r, refine);
	struct plot_file *pf = fmt_plot_read(o->out3d, 3);
	int n;
	double *times = print_times(o, &n);
	/* the rate grid is anisotropic (a resist has ~0.002 um in z against
	 * ~0.1 um in x and y): report both cell sizes */
	double hz = (r->zmax - r->zmin) / (r->nz - 1);
	double hxy = fmax((r->xmax - r->xmin) / (r->nx - 1), (r->ymax - r->ymin) / (r->ny - 1));
	for (int k = 0; k < pf->nsets && k < n; k++) {
		const struct plot_set *set = &pf->sets[k];
		/* the mesh nodes: each triangle's three corners (its fourth
		 * point closes it), every node once */
		double *p = xreallocarray(NULL, (size_t)set->ncurves * 3 + 1, 3 * sizeof *p);
		size_t np = 0;
		for (int c = 0; c < set->ncurves; c++)
			for (int q = 0; q < 3 && q < set->curves[c].npts; q++)
				memcpy(p + 3 * np++, set->curves[c].p + 3 * q, 3 * sizeof *p);
		np = unique_points(p, np);
		double med, p95;
		fmm_distance_stats(fm, p, np, times[k], &med, &p95);
		fprintf(stderr, "%s: xcheck t = %g s: %zu nodes from the fast-marching "
			"surface (z x%d): median %.3g um, 95%% %.3g um (%.2f and %.2f x-y cells, "
			"%.2f and %.2f z cells)\n", util_prog(), times[k], np, refine[2], med, p95,
			med / hxy, p95 / hxy, med / hz, p95 / hz);
		free(p);
	}
	free(times);
	fmt_plot_free(pf);
	fmm_free(fm);
}

/* The fast-marching engine (fmm.h): arrival times on the (refined) rate
 * grid, isosurfaces at the print times, and the same curves.cut as the
 * ray-string engine. */
static void run_fmm(const struct ratefile *r, const struct rfield *f,
		    const struct etch_opts *o)
{
	int refine[3];
	refinement(r, o, refine);
	struct fmm *fm = o->seed ? fmm_solve_points(r, refine, &o->seedp[0][0], o->seed)
				 : fmm_solve(r, refine);
	int n;
	double *times = print_times(o, &n);
	/* -last: only the final set is written */
	int first = o->last ? n - 1 : 0;
	fmm_write_curves(fm, times + first, n - first, o->out3d, o->out2d, o->dense, o->tol);
	if (o->cut_axis >= 0 && o->outcut) {
		/* bounds as the ray-string cut: the other axis' range, then z */
		int other = 1 - o->cut_axis;
		double bc[4] = {f->lo[other], f->hi[other], f->lo[2], f->hi[2]};
		struct plot_file *pf = fmt_plot_new(2);
		pf->labels = *fmt_labels_std(o->cut_axis == 0 ? LABELS_CUT_X : LABELS_CUT_Y);
		for (int k = first; k < n; k++)
			fmm_cut(fm, times[k], o->cut_axis, o->cut_value, pf, bc);
		fmt_plot_write(o->outcut, pf);
		fmt_plot_free(pf);
	}
	if (!o->quiet)
		fprintf(stderr, "%s: fast marching: refinement %d x %d x %d%s, %ld grid nodes "
			"reached, %d sets written\n", util_prog(), refine[0], refine[1],
			refine[2], o->refine_auto ? " (auto)" : "", fm->accepted, n);
	free(times);
	fmm_free(fm);
}

/* Seconds per triangle and time step of the ray-string engine, and per
 * (refined) grid node of fast marching, measured on the development
 * machine; bytes per triangle (with its nodes and segments) and per
 * fast-marching node. */
static const double T_TRI_STEP = 6e-7, T_FMM_NODE = 2e-6, B_TRI = 400, B_FMM_NODE = 48;

/* The estimate of the run before it starts (budget.h): time steps times
 * the triangles of the start, or the refined grid of fast marching. */
static void estimate(const struct ratefile *r, const struct rfield *f,
		     const struct etch_opts *o)
{
	char what[128];
	double secs, bytes;
	double sets = o->pt > 0 ? ceil(o->et / o->pt) : 1;
	if (o->method == METHOD_FMM || o->xcheck) {
		int refine[3];
		refinement(r, o, refine);
		double pts = (double)r->nx * r->ny * r->nz * refine[0] * refine[1] * refine[2];
		snprintf(what, sizeof what, "%.3g fast-marching nodes", pts);
		budget_check(o->input, what, pts * T_FMM_NODE, pts * B_FMM_NODE + sets * 16);
		if (o->method == METHOD_FMM)
			return;
	}
	double seg = o->seg > 0 ? o->seg : etch_default_seg(f);
	double dt = o->dt > 0 ? o->dt : etch_default_dt(f, seg, o->et);
	double steps = fmax(o->et / dt, sets);
	double wx = f->hi[0] - f->lo[0], wy = f->hi[1] - f->lo[1], wz = f->hi[2] - f->lo[2];
	double tris = o->seed ? 20.0 * o->seed : 2 * (wx / seg + 1) * (wy / (seg * sqrt(3) / 2) + 1);
	double bound = ETCH_MESH_FACTOR * 2 * (wx * wy + wx * wz + wy * wz) / (sqrt(3) / 4 * seg * seg);
	secs = steps * tris * T_TRI_STEP;
	bytes = fmin(bound, 1e9) * B_TRI + sets * 16;
	snprintf(what, sizeof what, "%.3g time steps of a mesh of %.3g triangles", steps, tris);
	budget_check(o->input, what, secs, bytes);
}

int main(int argc, char **argv)
{
	struct etch_opts o;
	parse_options(argc, argv, &o);
	if (o.dryrun)
		return 0;       /* -n: the options are good (sample3D asks first) */
	char *n2, *nc;
	output_names(&o, &n2, &nc);
	/* the rate only: bleach's other arrays (M) are not read into memory */
	static const char *const rate_only[] = {NULL};
	struct ratefile *r = fmt_rate_read_arrays(o.input, rate_only);
	if (r->ny == 1) {
		fmt_rate_free(r);
		die("%s:1: a 2D rate array (ny = 1): etch is 3D, develop it with etch2d", o.input);
	}
	struct rfield f;
	fmt_rate_field(&f, r, o.input);
	check_inside(&f, &o);
	estimate(r, &f, &o);
	/* curves.plot, its .2D and the cut are committed together (util.h) */
	aout_defer();
	if (o.method == METHOD_CELL || o.method == METHOD_HUYGENS) {
		run_cells(&f, &o);
		aout_finish();
	} else if (o.method == METHOD_FMM) {
		run_fmm(r, &f, &o);
		aout_finish();
	} else {
		struct etch_stats st = {0};
		o.rate = r;
		struct mesh *m = etch_run(&f, &o, &st);
		aout_finish();
		if (!o.quiet && st.capped)
			fprintf(stderr, "%s: the mesh reached its bound of %ld triangles "
				"(%d times the box's faces): %ld cuts not made; the rate "
				"varies faster than S_ideal %g um resolves\n", util_prog(),
				st.max_live_tri, ETCH_MESH_FACTOR, st.capped, st.seg);
		if (!o.quiet) {
			fprintf(stderr, "%s: done: %g s in %ld steps of %g s (%s); S_ideal %g um\n",
				util_prog(), o.et, st.steps, st.dt,
				o.dt > 0 ? "-dt" : "default: 0.25 / max|grad R|, at most S_ideal / max R",
				st.seg);
			fprintf(stderr, "%s: max|grad R| %g /s, max R %g um/s; %ld ray substeps, "
				"%ld recursive halvings\n", util_prog(), f.gmax, f.rmax,
				st.substeps, st.halvings);
			fprintf(stderr, "%s: final mesh %zu nodes, %zu segments, %zu triangles "
				"(largest %ld nodes, %ld triangles)\n", util_prog(),
				m->live_node, m->live_seg, m->live_tri, st.max_nodes, st.max_tris);
			fprintf(stderr, "%s: %ld cuts, %ld merges (%ld refused), %ld clips removing "
				"%ld triangles, %ld nodes stopped at the substrate\n",
				util_prog(), st.cuts, st.merges, st.refused, st.clips,
				st.clipped_tris, st.stopped);
			if (o.deloop)
				fprintf(stderr, "%s: deloop: %ld passes removed %ld loops (%ld "
					"triangles) in %.3g s (classifier %.3g s); %ld crossings "
					"left, %ld seam segments joined, %.3g um of border left "
					"open\n", util_prog(), st.deloops, st.loops, st.looped_tris,
					st.deloop_s, st.deloop_fmm_s, st.crossings_left,
					st.seam_joined, st.open_left);
		}
		mesh_free(m);
		if (o.xcheck)
			xcheck(r, &o);
	}
	if (o.outvtk) {
		/* from the plot file just written: the same surfaces whatever
		 * the engine */
		struct plot_file *pf = fmt_plot_read(o.out3d, 3);
		fmt_vtk_write(o.outvtk, pf);
		fmt_plot_free(pf);
	}
	fmt_rate_free(r);
	free(n2);
	free(nc);
	return 0;
}
