/*
 * etch - 3D development of a resist (thesis chapters 7 and 8) through the
 * etch-rate array of bleach.  This file holds the options and the
 * dispatch: the ray-string engine (ray_run.c, the default), fast marching
 * (fmm_run.c) or the cell methods (cell_methods.c), then -xcheck
 * (xcheck.c) and -vtk.  See man/man1/etch.1 and etch.h.
 */
#include "args.h"
#include "budget.h"
#include "etch.h"
#include "fmt_plot.h"
#include "fmt_rate.h"
#include "fmt_vtk.h"
#include "num.h"
#include "par.h"
#include "ptimes.h"
#include "util.h"

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
	"       etch -et etchtime [-pt printtime] -print-times\n"
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
	"  -last            write only the final set (-pt still paces -deloop n)\n"
	"  -vtk file.vtp    also write the surfaces as VTK XML PolyData (ParaView)\n"
	"  -check           check the mesh's consistency after every step, and\n"
	"                   deloop's near searches against a full search\n"
	"  -n               check the command line only: read and write nothing\n"
	"  -print-times     print the print times, one a line (to 10 digits), and\n"
	"                   stop: the times of the sets etch writes\n"
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
		else if (args_flag(&a, "-print-times"))
			o->print_times = 1;
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
	if (!o->input && !o->print_times)
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
	args_hint();
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

/* -print-times: the times of the sets, one a line, for the sample3D
 * driver's picture titles; to 10 significant digits, so that a label
 * reads 0.3, not the 0.30000000000000004 that 3 x 0.1 is. */
static void print_times(const struct etch_opts *o)
{
	int n;
	double *times = ptimes_make(o->et, o->pt, &n);
	for (int k = 0; k < n; k++) {
		char buf[32];
		snprintf(buf, sizeof buf, "%.10g", times[k]);
		num_print(stdout, strtod(buf, NULL));
		putchar('\n');
	}
	free(times);
	fshut(stdout, "standard output");
}

int main(int argc, char **argv)
{
	struct etch_opts o;
	parse_options(argc, argv, &o);
	if (o.dryrun)
		return 0;       /* -n: the options are good (sample3D asks first) */
	if (o.print_times) {
		print_times(&o);
		return 0;
	}
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
	etch_estimate(r, &f, &o);
	/* curves.plot, its .2D and the cut are committed together (util.h) */
	aout_defer();
	/* interrupted, they keep the print times finished (util.h) */
	aout_keep_on_signal("print times");
	if (o.method == METHOD_CELL || o.method == METHOD_HUYGENS) {
		etch_run_cells(&f, &o);
		aout_finish();
	} else if (o.method == METHOD_FMM) {
		etch_run_fmm(r, &f, &o);
		aout_finish();
	} else {
		struct etch_stats st = {0};
		o.rate = r;
		struct mesh *m = etch_run(&f, &o, &st);
		aout_finish();
		etch_report(&o, &f, m, &st);
		mesh_free(m);
		if (o.xcheck)
			etch_xcheck(r, &o);
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
