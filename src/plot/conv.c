/*
 * conv - convert a contour-file to a pdraw plot file (thesis Appendix B,
 * conv(L)): a rectangular wire mesh by default (one curve per grid row and
 * per grid column), or with -t a triangular solid mesh (two triangles per
 * grid cell, each written as a closed 4-point curve), which suits pdraw's
 * hidden-line drawing.  With -vtk it instead turns a 3D plot file of
 * triangles (etch's curves.plot) into VTK XML PolyData for ParaView.
 */
#include "args.h"
#include "budget.h"
#include "fmt_contour.h"
#include "fmt_plot.h"
#include "fmt_vtk.h"
#include "plot_common.h"
#include "util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
	"usage: conv [-t] [-old] [-o output-file] input-file\n"
	"       conv -vtk [-big] [-o output-file] plot3d-file\n"
	"  -t               triangular mesh (better for hidden lines)\n"
	"  -vtk             a 3D plot file (triangles, lines) to VTK XML PolyData;\n"
	"                   default output: input-file with .plot replaced by .vtp\n"
	"  -big             with -vtk: read a file whose estimated memory or time (from\n"
	"                   its size) is beyond the limits (also SAMPLE3D_BIG=1)\n"
	"  -old             read the old 50x50 contour format\n"
	"  -o output-file   default: input-file.3D\n";

struct options {
	int triangles;
	int old;
	int vtk;
	const char *output;
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
		if (args_flag(&a, "-t"))
			o->triangles = 1;
		else if (args_flag(&a, "-old"))
			o->old = 1;
		else if (args_flag(&a, "-vtk"))
			o->vtk = 1;
		else if (args_flag(&a, "-big"))
			budget_allow_big();
		else if (args_str(&a, "-o", &o->output))
			;
		else
			args_operand(&a, (const char **[]){&o->input}, 1, "input file");
	}
	if (!o->input)
		args_error(&a, "no input file");
	if (o->vtk && (o->triangles || o->old))
		args_error(&a, "-vtk converts a plot3d file: not with -t or -old");
	args_done(&a, NULL);
}

static void zrange(const struct contour *c, double *lo, double *hi)
{
	size_t n = (size_t)c->nx * (size_t)c->ny;
	*lo = *hi = c->z[0];
	for (size_t k = 1; k < n; k++) {
		if (c->z[k] < *lo) *lo = c->z[k];
		if (c->z[k] > *hi) *hi = c->z[k];
	}
}

static void point(const struct contour *c, int i, int j, double *p)
{
	p[0] = fmt_contour_x(c, i);
	p[1] = fmt_contour_y(c, j);
	p[2] = c->z[(size_t)j * (size_t)c->nx + (size_t)i];
}

/* -vtk: input.plot -> input.vtp (any other name: input.vtp appended) */
static int to_vtk(const struct options *o)
{
	char *outname;
	if (o->output) {
		outname = xstrdup(o->output);
	} else {
		const char *base = strcmp(o->input, "-") == 0 ? "stdin" : o->input;
		size_t len = strlen(base);
		outname = xmalloc(len + 5);
		if (len > 5 && strcmp(base + len - 5, ".plot") == 0)
			sprintf(outname, "%.*s.vtp", (int)(len - 5), base);
		else
			sprintf(outname, "%s.vtp", base);
	}
	/* the estimate (plot_budget), measured on the unbaked contact's
	 * curves.plot (1.27 M numbers, 26 MB): 40 MB, 0.13 s */
	plot_budget(1, (char *const[]){(char *)o->input}, 32, 1e-7);
	struct plot_file *pf = fmt_plot_read(o->input, 3);
	fmt_vtk_write(outname, pf);
	fmt_plot_free(pf);
	free(outname);
	return 0;
}

int main(int argc, char **argv)
{
	struct options o;
	parse_options(argc, argv, &o);
	if (o.vtk)
		return to_vtk(&o);
	struct contour *c = fmt_contour_read(o.input, o.old);

	char *outname;
	if (o.output) {
		outname = xstrdup(o.output);
	} else {
		const char *base = strcmp(o.input, "-") == 0 ? "stdin" : o.input;
		outname = xmalloc(strlen(base) + 4);
		sprintf(outname, "%s.3D", base);
	}
	double b[6] = {c->xmin, c->xmax, c->ymin, c->ymax, 0, 0};
	zrange(c, &b[4], &b[5]);

	struct plot_writer *w = fmt_plot_open(outname, 3);
	fmt_plot_labels(w, &c->labels);        /* the labels travel (contour.5) */
	if (o.triangles) {
		long n = 2L * (c->nx - 1) * (c->ny - 1);
		fmt_plot_begin_set(w, b, n);
		for (int j = 0; j + 1 < c->ny; j++)
			for (int i = 0; i + 1 < c->nx; i++) {
				double p[12], q[12];
				/* split each cell along its (i,j)-(i+1,j+1) diagonal */
				point(c, i, j, p);
				point(c, i + 1, j, p + 3);
				point(c, i + 1, j + 1, p + 6);
				memcpy(p + 9, p, 3 * sizeof *p);
				point(c, i, j, q);
				point(c, i + 1, j + 1, q + 3);
				point(c, i, j + 1, q + 6);
				memcpy(q + 9, q, 3 * sizeof *q);
				fmt_plot_curve(w, 4, p);
				fmt_plot_curve(w, 4, q);
			}
	} else {
		int nmax = c->nx > c->ny ? c->nx : c->ny;
		double *p = xreallocarray(NULL, (size_t)nmax, 3 * sizeof *p);
		fmt_plot_begin_set(w, b, (long)c->nx + c->ny);
		for (int j = 0; j < c->ny; j++) {
			for (int i = 0; i < c->nx; i++)
				point(c, i, j, p + 3 * i);
			fmt_plot_curve(w, c->nx, p);
		}
		for (int i = 0; i < c->nx; i++) {
			for (int j = 0; j < c->ny; j++)
				point(c, i, j, p + 3 * j);
			fmt_plot_curve(w, c->ny, p);
		}
		free(p);
	}
	fmt_plot_close(w);
	free(outname);
	fmt_contour_free(c);
	return 0;
}
