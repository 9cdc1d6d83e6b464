/*
 * drawmask - the mask of a splat input file, drawn to scale (thesis
 * Appendix B, drawmask(L)).  The window is painted with the background,
 * then every rect, polygon and gds union in file order, so the picture
 * shows what splat sees (later ones win where they overlap).
 *
 * Beyond the guide's BUGS: every transmission is drawn, as a gray level
 * from the intensity transmission |t|^2 (opaque dark, clear white), and a
 * feature with a phase other than 0 is hatched, the hatch direction
 * telling 90, 180 and 270 degrees apart, and labelled with its phase.
 * Overlapping rects are reported on stderr.
 */
#include "args.h"
#include "draw.h"
#include "fmt_options.h"
#include "fmt_splat.h"
#include "plot_common.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage_head[] =
	"usage: drawmask [-o options-file] [-Pprinter] [-l] [-lbl] [-s scale] [-noplot]\n"
	"                [-ps] [-print] [-tl toplabel] [-xl xlabel] [-yl ylabel]\n"
	"                [-svg file] [X options] mask-file\n"
	"  -l               landscape\n"
	"  -lbl             label each feature (number, transmission, phase)\n";

static const struct opt_spec spec[] = {
	PLOT_OPT_COMMON, PLOT_OPT_ONOFF("landscape"), PLOT_OPT_ONOFF("nolabel"),
	{NULL, 0, 0, 0, NULL}
};

/* Gray of an opaque area; clear is white (1).  Not black, so that
 * outlines and hatching stay visible on chrome. */
#define GRAY_OPAQUE 0.3
#define HATCH_STEP 7.0      /* points between hatch lines */
#define LABEL_FONT 8.0
/* Phases within this many degrees of a multiple of 360 count as 0. */
#define PHASE_TOL 1e-6

struct options {
	struct plot_cmd cmd;
	int lbl;
	const char *input;
};

struct ctx {
	struct plot_settings s;
	int labels;
	const struct splat_mask *m;
};

static void parse_options(int argc, char **argv, struct options *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage_head, plot_usage_common, plot_usage_x);
	memset(o, 0, sizeof *o);
	plot_cmd_init(&o->cmd);
	while (a.i < argc) {
		args_help_exit(&a, 1);
		if (args_flag(&a, "-lbl")) o->lbl = 1;
		else if (plot_cmd_arg(&a, &o->cmd, PC_LANDSCAPE)) ;
		else args_operand(&a, (const char **[]){&o->input}, 1, "mask-file");
	}
	if (!o->input)
		args_error(&a, "no mask-file");
	args_done(&a, NULL);
}

static double phase_norm(double ph)
{
	double p = fmod(ph, 360);
	if (p < 0)
		p += 360;
	if (p < PHASE_TOL || 360 - p < PHASE_TOL)
		p = 0;
	return p;
}

static double fill_gray(double t)
{
	double i = fmin(t * t, 1.0);    /* intensity transmission */
	return GRAY_OPAQUE + (1 - GRAY_OPAQUE) * i;
}

/* Diagonal hatching over a page rectangle: "/" for phases up to 90
 * degrees, "\" up to 180, both beyond (so 90, 180 and 270 differ). */
static void hatch(struct draw *d, double x0, double y0, double x1, double y1, double ph)
{
	int up = ph <= 90 || ph > 180, down = ph > 90;
	draw_clip(d, x0, y0, x1, y1);
	draw_set_gray(d, 0);
	draw_set_line(d, 1, 0.4);
	double w = x1 - x0, h = y1 - y0;
	for (double k = -h; k < w; k += HATCH_STEP) {
		if (up)
			draw_segment(d, x0 + k, y0, x0 + k + h, y1);
		if (down)
			draw_segment(d, x0 + k, y1, x0 + k + h, y0);
	}
	draw_unclip(d);
}

static void area(struct draw *d, const struct plot_frame *f, double xa, double ya,
		 double xb, double yb, double t, double ph, int outline)
{
	double x0, y0, x1, y1;
	plot_frame_map(f, xa, ya, &x0, &y0);
	plot_frame_map(f, xb, yb, &x1, &y1);
	double box[8] = {x0, y0, x1, y0, x1, y1, x0, y1};
	draw_set_line(d, 1, 0.8);
	draw_polygon(d, 4, box, fill_gray(t), 0);
	ph = phase_norm(ph);
	if (ph != 0)
		hatch(d, x0, y0, x1, y1, ph);
	if (outline) {
		draw_set_line(d, 1, 0.8);
		draw_polygon(d, 4, box, DRAW_NOFILL, 1);
	}
}

/* The shapes of a polygon or gds statement, filled by transmission; a
 * phase other than 0 is shown by a dashed outline and the label (the
 * hatching of rects needs a rectangular clip). */
static void layer_area(struct draw *d, const struct plot_frame *f, const struct splat_layer *l)
{
	double *pg = NULL;
	size_t cap = 0;
	double ph = phase_norm(l->phase);
	for (int i = 0; i < l->shapes.n; i++) {
		int nv = poly_set_nv(&l->shapes, i);
		const double *xy = poly_set_xy(&l->shapes, i);
		xgrow(&pg, &cap, 2 * (size_t)nv, sizeof *pg);
		for (int v = 0; v < nv; v++)
			plot_frame_map(f, xy[2 * v], xy[2 * v + 1], &pg[2 * v], &pg[2 * v + 1]);
		draw_set_line(d, 1, 0.8);
		draw_polygon(d, nv, pg, fill_gray(l->t), 0);
		if (ph != 0) {
			draw_set_gray(d, 0);
			draw_set_line(d, 2, 0.8);
			draw_polygon(d, nv, pg, DRAW_NOFILL, 1);
		}
	}
	free(pg);
}

static void feature_label(struct draw *d, const struct plot_frame *f,
			  const struct splat_rect *r, int i, int full)
{
	double x0, y0, x1, y1;
	plot_frame_map(f, r->x1, r->y1, &x0, &y0);
	plot_frame_map(f, r->x2, r->y2, &x1, &y1);
	char buf[96];
	double ph = phase_norm(r->phase);
	if (full)
		snprintf(buf, sizeof buf, "#%d: transmission %g, phase %g deg", i + 1, r->t, ph);
	else
		snprintf(buf, sizeof buf, "%g deg", ph);
	double tw = strlen(buf) * LABEL_FONT * 0.55 + 2, th = LABEL_FONT * 1.1;
	double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
	double box[8] = {cx - tw / 2, cy - th / 2, cx + tw / 2, cy - th / 2,
			 cx + tw / 2, cy + th / 2, cx - tw / 2, cy + th / 2};
	draw_set_line(d, 1, 0.5);
	draw_polygon(d, 4, box, 1.0, 1);
	draw_text(d, cx, cy, LABEL_FONT, 0, DRAW_CENTER, DRAW_MIDDLE, buf);
}

static struct draw *render(void *vc)
{
	const struct ctx *c = vc;
	const struct splat_mask *m = c->m;
	struct draw *d = plot_new_page(c->s.landscape);
	struct plot_axis xa, ya;
	plot_axis_linear(&xa, m->xmin, m->xmax, c->s.xticks, 0);
	plot_axis_linear(&ya, m->ymin, m->ymax, c->s.yticks, 0);
	struct plot_frame f = {0, 0, 0, 0, &xa, &ya};
	plot_frame_place(&f, d, c->s.equalscale);
	area(d, &f, m->xmin, m->ymin, m->xmax, m->ymax, m->bg_t, m->bg_phase, 0);
	int nl = 0;
	for (int i = 0; i <= m->nrects; i++) {
		for (; nl < m->nlayers && m->layers[nl].after == i; nl++)
			layer_area(d, &f, &m->layers[nl]);
		if (i == m->nrects)
			break;
		const struct splat_rect *r = &m->rects[i];
		area(d, &f, r->x1, r->y1, r->x2, r->y2, r->t, r->phase, 1);
	}
	/* phase labels always (the hatching alone does not give the value),
	 * full labels with -lbl */
	for (int i = 0; i < m->nrects; i++) {
		const struct splat_rect *r = &m->rects[i];
		if (c->labels || phase_norm(r->phase) != 0)
			feature_label(d, &f, r, i, c->labels);
	}
	/* a layer (polygon or gds union) is labelled once, on its first shape */
	for (int k = 0; k < m->nlayers; k++) {
		const struct splat_layer *l = &m->layers[k];
		if (l->shapes.n == 0 || !(c->labels || phase_norm(l->phase) != 0))
			continue;
		const double *xy = poly_set_xy(&l->shapes, 0);
		struct splat_rect r = {xy[0], xy[1], xy[0], xy[1], l->t, l->phase, l->line};
		for (int v = 1; v < poly_set_nv(&l->shapes, 0); v++) {
			r.x1 = fmin(r.x1, xy[2 * v]); r.x2 = fmax(r.x2, xy[2 * v]);
			r.y1 = fmin(r.y1, xy[2 * v + 1]); r.y2 = fmax(r.y2, xy[2 * v + 1]);
		}
		feature_label(d, &f, &r, m->nrects + k, c->labels);
	}
	plot_frame_draw(d, &f, 0, c->s.toplabel, c->s.xlabel, c->s.ylabel);
	return d;
}

/* The guide's BUGS: "There is no rectangle-intersection checking." */
static void report_overlaps(const char *path, const struct splat_mask *m)
{
	for (int j = 1; j < m->nrects; j++)
		for (int i = 0; i < j; i++) {
			const struct splat_rect *a = &m->rects[i], *b = &m->rects[j];
			if (a->x1 < b->x2 && b->x1 < a->x2 && a->y1 < b->y2 && b->y1 < a->y2)
				fprintf(stderr, "%s: %s:%ld: rect overlaps the rect of line %ld "
					"(the later one is drawn on top)\n",
					util_prog(), path, b->line, a->line);
		}
}

int main(int argc, char **argv)
{
	struct options o;
	parse_options(argc, argv, &o);
	struct ctx c;
	memset(&c, 0, sizeof c);
	struct opt_value val[sizeof spec / sizeof spec[0]];
	plot_begin(&c.s, &(struct plot_settings){
		.toplabel = "mask", .xlabel = "x (um)", .ylabel = "y (um)",
		.equalscale = 1, .postscript = 1, .line = 1, .scale = 1.0,
		.xticks = 4, .yticks = 4,
	}, spec, val, &o.cmd);
	const struct opt_value *v = plot_opt(spec, val, "nolabel");
	c.labels = o.lbl || (v && !v->num);

	struct splat_input *in = fmt_splat_read(o.input);
	c.m = &in->mask;
	report_overlaps(o.input, c.m);
	plot_output(&c.s, &o.cmd, render, NULL, &c);
	fmt_splat_free(in);
	fmt_options_free(spec, val);
	return 0;
}
