/*
 * splat - aerial image of a periodic 2D mask by Hopkins partially
 * coherent imaging (thesis 2.2.1, 9.2-9.3; SPLAT, "Simulation of
 * Projection Lens Aberrations via TCCs").  Reads a splat input file
 * (man/man5/splat.5), writes the image as a contour-file and any
 * cutlines as 2D plot files.
 */
#include "args.h"
#include "fmt_contour.h"
#include "fmt_plot.h"
#include "fmt_splat.h"
#include "splat.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
	"usage: splat [-o contour-file] [-q] [-name] input-file\n"
	"  -o contour-file  output image (default: the input's contour statement,\n"
	"                   else splat.cont)\n"
	"  -q               quiet: no progress lines on stderr\n"
	"  -name            print the name of the contour-file it would write, and\n"
	"                   exit (for scripts such as sample3D)\n";

struct options {
	const char *output;
	int quiet;
	int name_only;
	const char *input;
};

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
		else if (args_flag(&a, "-name"))
			o->name_only = 1;
		else if (args_str(&a, "-o", &o->output))
			;
		else
			args_operand(&a, (const char **[]){&o->input}, 1, "input file");
	}
	if (!o->input)
		args_error(&a, "no input file");
	args_done(&a, NULL);
}

static void write_cutline(const struct spectrum *sp, const struct splat_cutline *c)
{
	double *p = xreallocarray(NULL, (size_t)c->npts, 2 * sizeof *p);
	double len = hypot(c->x2 - c->x1, c->y2 - c->y1);
	double lo = 0, hi = 0;
	for (int k = 0; k < c->npts; k++) {
		double t = (double)k / (c->npts - 1);
		double v = image_at(sp, c->x1 + t * (c->x2 - c->x1), c->y1 + t * (c->y2 - c->y1));
		/* thesis Figure 2.7a: intensity against distance along the cut */
		p[2 * k] = t * len;
		p[2 * k + 1] = v;
		if (k == 0 || v > hi) hi = v;
		if (k == 0 || v < lo) lo = v;
	}
	/* the graph spans at least 0..1, clear-field intensity */
	double b[4] = {0, len, lo < 0 ? lo : 0, hi > 1 ? hi : 1};
	struct plot_file *pf = fmt_plot_new(2);
	struct plot_set *set = fmt_plot_add_set(pf, b);
	fmt_plot_add_curve(pf, set, c->npts, p);
	fmt_plot_write(c->file, pf);
	fmt_plot_free(pf);
	free(p);
}

int main(int argc, char **argv)
{
	struct options o;
	util_setprog(argv[0]);
	parse_options(argc, argv, &o);
	struct splat_input *in = fmt_splat_read(o.input);
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

	int norders;
	struct spectrum *sp = splat_spectrum(in, 0, 0, &norders);
	if (!sp)
		die("%s: the source lies outside the pupil: no light reaches the wafer",
		    o.input);
	if (!o.quiet)
		fprintf(stderr, "splat: %d diffraction orders, %ld TCC pairs\n",
			norders, sp->pairs);

	struct contour *c = fmt_contour_new(m->xmin, m->xmax, m->ymin, m->ymax,
					    in->nx, in->ny);
	image_grid(sp, m->xmin, m->xmax, m->ymin, m->ymax, in->nx, in->ny, c->z);
	fmt_contour_write(out, c);
	if (!o.quiet)
		fprintf(stderr, "splat: wrote %s\n", out);
	for (int k = 0; k < in->ncutlines; k++) {
		write_cutline(sp, &in->cutlines[k]);
		if (!o.quiet)
			fprintf(stderr, "splat: wrote cutline %s\n", in->cutlines[k].file);
	}
	fmt_contour_free(c);
	spectrum_free(sp);
	fmt_splat_free(in);
	return 0;
}
