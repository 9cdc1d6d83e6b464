/*
 * splat - aerial image of a periodic 2D mask by Hopkins partially
 * coherent imaging (thesis 2.2.1, 9.2-9.3; SPLAT, "Simulation of
 * Projection Lens Aberrations via TCCs").  Reads a splat input file
 * (man/man5/splat.5), writes the image as a contour-file (or, with a
 * resist statement, the image at several depths in the resist as an
 * image stack, man/man5/stack.5) and any cutlines as 2D plot files.
 */
#include "args.h"
#include "budget.h"
#include "fmt_contour.h"
#include "fmt_plot.h"
#include "fmt_splat.h"
#include "fmt_stack.h"
#include "num.h"
#include "par.h"
#include "splat.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
	"usage: splat [-o contour-file] [-q] [-big] [-name] [-defocus d] [-grid nx ny]\n"
	"             [-method hopkins|abbe|auto] [-bf resist-file] [-threads n]\n"
	"             [-cutline x1 y1 x2 y2 npts file] input-file\n"
	"  -o contour-file  output image (default: the input's contour statement,\n"
	"                   else splat.cont)\n"
	"  -q               quiet: no progress lines on stderr\n"
	"  -big             run work estimated beyond the limits (an hour, the\n"
	"                   machine's memory; also SAMPLE3D_BIG=1)\n"
	"  -defocus d       defocus in micrometres, replacing the input's defocus\n"
	"  -grid nx ny      the image grid (points, ends included), replacing the\n"
	"                   input's grid statement\n"
	"  -method m        hopkins (pairs of orders, exact source integral), abbe\n"
	"                   (source points and FFTs, for large windows) or auto\n"
	"                   (default: the one estimated cheaper)\n"
	"  -bf resist-file  with imaging vector: the film stack (ambient, resist,\n"
	"                   layers, substrate) of bleach's input file, which the\n"
	"                   image stack then passes through\n"
	"  -threads n       threads to use (default $SAMPLE3D_THREADS, else every core)\n"
	"  -name            print the name of the contour-file it would write, and\n"
	"                   exit (for scripts such as sample3D)\n"
	"  -cutline x1 y1 x2 y2 npts file\n"
	"                   write this cutline in place of the input's cutlines\n"
	"                   (the cutline statement of splat(5); for sample2D)\n";

struct options {
	const char *output;
	int quiet;
	int name_only;
	const char *defocus;    /* -defocus value, checked after parsing */
	const char *grid[2];    /* -grid values, checked after parsing */
	const char *method;     /* -method value */
	const char *bf;         /* -bf resist file */
	long threads;
	const char *cut[6];     /* -cutline's words, checked after parsing */
	const char *input;
};

/* Largest |defocus| accepted on the command line, micrometres: the same
 * bound as splat(5)'s defocus statement (50 um is beyond any depth of
 * focus; 500 is a slip of nanometres). */
static const double DEFOCUS_MAX = 50;
/* -method auto keeps the exact Hopkins sum while it is estimated under
 * this many seconds, or under twice the Abbe estimate (the examples and
 * the thesis figures are all far below it). */
static const double AUTO_EXACT_SECONDS = 1;

static void parse_options(int argc, char **argv, struct options *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage, NULL, NULL);
	memset(o, 0, sizeof *o);
	while (a.i < argc) {
		args_help_exit(&a, 1);
		if (args_flag(&a, "-q"))
			o->quiet = 1;
		else if (args_flag(&a, "-big"))
			budget_allow_big();
		else if (args_flag(&a, "-name"))
			o->name_only = 1;
		else if (args_str(&a, "-o", &o->output))
			;
		else if (args_str(&a, "-defocus", &o->defocus))
			;
		else if (args_flag(&a, "-grid")) {
			/* two words: nx ny */
			if (a.i + 1 >= argc) {
				args_error(&a, "option -grid needs two counts, nx and ny");
				a.i = argc;
			} else {
				o->grid[0] = argv[a.i++];
				o->grid[1] = argv[a.i++];
			}
		} else if (args_str(&a, "-method", &o->method))
			;
		else if (args_str(&a, "-bf", &o->bf))
			;
		else if (args_int(&a, "-threads", 1, PAR_MAX_THREADS, &o->threads))
			;
		else if (args_flag(&a, "-cutline")) {
			if (a.i + 6 > argc) {
				args_error(&a, "option -cutline needs x1 y1 x2 y2 npts file");
				a.i = argc;
			} else {
				for (int k = 0; k < 6; k++)
					o->cut[k] = argv[a.i++];
			}
		} else
			args_operand(&a, (const char **[]){&o->input}, 1, "input file");
	}
	if (!o->input)
		args_error(&a, "no input file");
	if (o->method && strcmp(o->method, "hopkins") && strcmp(o->method, "abbe") &&
	    strcmp(o->method, "auto"))
		args_error(&a, "-method: expected hopkins, abbe or auto");
	args_done(&a, NULL);
}

/* The value of an override option: a bad one is a one-line usage error
 * (sweep scripts read it in a log). */
static double override_value(const char *opt, const char *s, double min, double max)
{
	double v;
	if (!num_parse(s, &v) || !(v >= min && v <= max))
		die_status(EXIT_USAGE, "option %s: expected a number from %g to %g, found \"%.40s\"",
			   opt, min, max, s);
	return v;
}

/* Largest |coordinate| of a -cutline end and its largest point count:
 * the bounds of splat(5)'s cutline statement and of any window. */
static const double CUT_COORD_MAX = 1e6;
static const double CUT_MAX_PTS = 1000000;

/* -cutline: the one cutline written, in place of the input's. */
static void replace_cutlines(struct splat_input *in, const char *const w[6])
{
	struct splat_cutline c;
	c.x1 = override_value("-cutline x1", w[0], -CUT_COORD_MAX, CUT_COORD_MAX);
	c.y1 = override_value("-cutline y1", w[1], -CUT_COORD_MAX, CUT_COORD_MAX);
	c.x2 = override_value("-cutline x2", w[2], -CUT_COORD_MAX, CUT_COORD_MAX);
	c.y2 = override_value("-cutline y2", w[3], -CUT_COORD_MAX, CUT_COORD_MAX);
	double np = override_value("-cutline npts", w[4], 2, CUT_MAX_PTS);
	if (np != floor(np))
		die_status(EXIT_USAGE, "option -cutline npts: expected a whole number, found \"%.40s\"",
			   w[4]);
	c.npts = (int)np;
	c.line = 0;
	c.file = xstrdup(w[5]);
	for (int k = 0; k < in->ncutlines; k++)
		free(in->cutlines[k].file);
	if (!in->ncutlines)
		in->cutlines = xmalloc(sizeof c);
	in->cutlines[0] = c;
	in->ncutlines = 1;
}

/* A cutline: intensity against distance along the line (thesis Figure
 * 2.7a), one curve per plane of an image stack, top plane first. */
static void write_cutline(const struct spectrum *sp, const struct splat_cutline *c)
{
	double *p = xreallocarray(NULL, (size_t)c->npts, 2 * sizeof *p);
	double len = hypot(c->x2 - c->x1, c->y2 - c->y1);
	double lo = 0, hi = 0;
	struct plot_file *pf = fmt_plot_new(2);
	pf->labels = *fmt_labels_std(LABELS_CUTLINE);
	/* the graph spans at least 0..1, clear-field intensity */
	double b[4] = {0, len, 0, 1};
	struct plot_set *set = fmt_plot_add_set(pf, b);
	for (int l = 0; l < sp->nplanes; l++) {
		struct spectrum v = spectrum_plane(sp, l);
		for (int k = 0; k < c->npts; k++) {
			double t = (double)k / (c->npts - 1);
			double z = image_at(&v, c->x1 + t * (c->x2 - c->x1),
					    c->y1 + t * (c->y2 - c->y1));
			p[2 * k] = t * len;
			p[2 * k + 1] = z;
			if ((l == 0 && k == 0) || z > hi) hi = z;
			if ((l == 0 && k == 0) || z < lo) lo = z;
		}
		fmt_plot_add_curve(pf, set, c->npts, p);
	}
	set->bounds[2] = lo < 0 ? lo : 0;
	set->bounds[3] = hi > 1 ? hi : 1;
	fmt_plot_write(c->file, pf);
	fmt_plot_free(pf);
	free(p);
}

/* The image on the output grid, which spans one period: by the direct
 * sums of the exact method (whose output stays byte for byte what it
 * was), by FFT with the Abbe method. */
static void grid(const struct spectrum *sp, enum splat_method method,
		 const struct splat_mask *m, int nx, int ny, double *z)
{
	if (method == SPLAT_ABBE)
		image_grid_fft(sp, m->xmin, m->ymin, nx, ny, z);
	else
		image_grid(sp, m->xmin, m->xmax, m->ymin, m->ymax, nx, ny, z);
}

int main(int argc, char **argv)
{
	struct options o;
	util_setprog(argv[0]);
	parse_options(argc, argv, &o);
	double defocus = 0;
	if (o.defocus)
		defocus = override_value("-defocus", o.defocus, -DEFOCUS_MAX, DEFOCUS_MAX);
	long gnx = 0, gny = 0;
	if (o.grid[0] && (!num_parse_count(o.grid[0], 2, SPLAT_MAX_GRID, &gnx) ||
			  !num_parse_count(o.grid[1], 2, SPLAT_MAX_GRID, &gny)))
		die_status(EXIT_USAGE, "option -grid: expected two counts from 2 to %d, found "
			   "\"%.40s %.40s\"", SPLAT_MAX_GRID, o.grid[0], o.grid[1]);
	struct splat_input *in = fmt_splat_read(o.input);
	if (o.defocus)
		in->defocus = defocus;
	if (o.grid[0]) {
		/* the same bound as the grid statement's, and an image stack's */
		in->nx = (int)gnx;
		in->ny = (int)gny;
		if (in->planes && (double)in->planes * gnx * gny >
		    (double)SPLAT_MAX_GRID * SPLAT_MAX_GRID)
			die_status(EXIT_USAGE, "option -grid: %d planes of %dx%d points are more "
				   "than %d x %d values", in->planes, in->nx, in->ny, SPLAT_MAX_GRID,
				   SPLAT_MAX_GRID);
	}
	struct vfilm vf;
	vector_film_read(&vf, in, o.input, o.bf);
	if (o.cut[0])
		replace_cutlines(in, o.cut);
	const struct splat_mask *m = &in->mask;
	const char *out = o.output ? o.output : in->contour;
	if (o.name_only) {
		/* the driver passes this name on to bleach (SAMPLE3D(L) -if) */
		printf("%s\n", out);
		fshut(stdout, "stdout");
		fmt_splat_free(in);
		return 0;
	}
	if (!o.quiet)
		fprintf(stderr, "splat: %s: %d rects, lambda %g um, NA %g, %dx%d grid\n",
			o.input, m->nrects, in->wavelength, in->na, in->nx, in->ny);
	if (!o.quiet && m->nlayers) {
		long shapes = 0;
		for (int k = 0; k < m->nlayers; k++)
			shapes += m->layers[k].shapes.n;
		fprintf(stderr, "splat: %s: %d polygon and gds statements, %ld shapes in the "
			"window %g %g %g %g\n", o.input, m->nlayers, shapes, m->xmin, m->xmax,
			m->ymin, m->ymax);
	}

	double est_n, est_pairs, est_s, est_b, abbe_nodes, abbe_s, abbe_b;
	splat_estimate(in, &est_n, &est_pairs, &est_s, &est_b);
	(in->vector ? splat_estimate_vector : splat_estimate_abbe)(in, &abbe_nodes, &abbe_s,
								      &abbe_b);
	enum splat_method method = SPLAT_AUTO;
	if (in->vector && o.method && !strcmp(o.method, "hopkins"))
		die_status(EXIT_USAGE, "-method hopkins: %s asks for imaging vector, which is "
			   "summed over source points (abbe)", o.input);
	if (in->vector)
		method = SPLAT_ABBE;
	else if (o.method && !strcmp(o.method, "hopkins"))
		method = SPLAT_HOPKINS;
	else if (o.method && !strcmp(o.method, "abbe"))
		method = SPLAT_ABBE;
	else if (est_s > AUTO_EXACT_SECONDS && abbe_s < est_s / 2)
		method = SPLAT_ABBE;        /* auto */
	else
		method = SPLAT_HOPKINS;
	char what[160];
	if (method == SPLAT_ABBE)
		snprintf(what, sizeof what, "%.3g diffraction orders, %.3g source points "
			 "(-method abbe) and %.3g image points", est_n, abbe_nodes,
			 (double)in->nx * in->ny);
	else
		snprintf(what, sizeof what, "%.3g diffraction orders, %.3g TCC pairs "
			 "(-method hopkins) and %.3g image points", est_n, est_pairs,
			 (double)in->nx * in->ny);
	if (method == SPLAT_ABBE)
		budget_check(o.input, what, abbe_s, abbe_b);
	else
		budget_check(o.input, what, est_s, est_b);
	par_set_threads((int)o.threads);
	/* the image and the cutlines are committed together (util.h) */
	aout_defer();
	splat_quiet = o.quiet;

	int norders;
	struct spectrum *sp = in->vector ? splat_spectrum_vector(in, &vf, 0, &norders)
				 : splat_spectrum_method(in, method, 0, 0, &norders);
	if (!sp)
		die("%s: the source lies outside the pupil: no light reaches the wafer",
		    o.input);
	if (!o.quiet)
		fprintf(stderr, "splat: %d diffraction orders, %ld %s (estimated %.3g s by "
			"hopkins, %.3g s by abbe)\n", norders, sp->pairs,
			method == SPLAT_ABBE ? "source points by abbe" : "TCC pairs by hopkins",
			est_s, abbe_s);

	struct contour *c = fmt_contour_new(m->xmin, m->xmax, m->ymin, m->ymax,
					    in->nx, in->ny);
	c->labels = *fmt_labels_std(LABELS_IMAGE);
	if (in->planes) {
		/* the image stack (stack.5): plane k at depth k T/(N-1) */
		struct image_stack *st = fmt_stack_new(in->planes, in->resist_thick,
						       in->resist_index, c);
		st->wavelength = in->wavelength;        /* bleach checks it */
		st->film = vf.have;
		for (int k = 0; k < st->n; k++) {
			struct spectrum v = spectrum_plane(sp, k);
			grid(&v, method, m, in->nx, in->ny, st->plane[k]->z);
		}
		fmt_stack_write(out, st);
		fmt_stack_free(st);
		if (!o.quiet)
			fprintf(stderr, "splat: wrote %s, an image stack of %d planes through "
				"%g um of resist of index %g\n", out, in->planes,
				in->resist_thick, in->resist_index);
	} else {
		grid(sp, method, m, in->nx, in->ny, c->z);
		fmt_contour_write(out, c);
		if (!o.quiet)
			fprintf(stderr, "splat: wrote %s\n", out);
	}
	for (int k = 0; k < in->ncutlines; k++) {
		write_cutline(sp, &in->cutlines[k]);
		if (!o.quiet)
			fprintf(stderr, "splat: wrote cutline %s\n", in->cutlines[k].file);
	}
	aout_finish();
	fmt_contour_free(c);
	spectrum_free(sp);
	vector_film_free(&vf);
	fmt_splat_free(in);
	return 0;
}
