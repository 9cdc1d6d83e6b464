/*
 * drawplot - X-Y line plots of 2D plot files (thesis Appendix B,
 * drawplot(L)).  Each set of each file is one page: axes with round
 * limits (autorange) or the file's bounds divided into xticks/yticks,
 * optional log axes, the 11 line types and 18 markers of the guide, and
 * a template-file giving line type, marker and a legend label per curve.
 *
 * -section draws a resist cross-section (etch's curves.cut) as an SEM
 * picture would show it: every set of a file (one per print time) on one
 * page, the resist below the last set's profile filled grey, the
 * substrate a dark band under the box floor, the profiles on top.
 */
#include "args.h"
#include "draw.h"
#include "fmt_options.h"
#include "fmt_plot.h"
#include "fmt_template.h"
#include "plot_common.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage_head[] =
	"usage: drawplot [-o options-file] [-Pprinter] [-s scale] [-ar] [-clip] [-e] [-g]\n"
	"                [-l] [-noplot] [-print] [-ps] [-xlog] [-ylog] [-t template-file]\n"
	"                [-tl toplabel] [-xl xlabel] [-yl ylabel] [-svg file] [-big]\n"
	"                [-section] [-times t1,t2,...] [-fill] [X options] plot-file...\n"
	"  -ar              no automatic axis ranging\n"
	"  -clip            clip the curves to the plot box\n"
	"  -e               equal x and y scales\n"
	"  -g               draw a grid\n"
	"  -l               landscape\n"
	"  -xlog, -ylog     logarithmic x or y axis\n"
	"  -t template-file line type, marker and label per curve\n"
	"  -section         a resist cross-section: all sets on one page, the resist\n"
	"                   under the last profile filled, the substrate marked\n"
	"  -fill            closed curves (last point the first) filled light grey\n"
	"  -times t1,...    the sets' print times (s): with -section for the legend,\n"
	"                   else each page's title ends with its time\n"
	"  -big             draw plot files whose estimated memory or time (from\n"
	"                   their size) is beyond the limits (also SAMPLE3D_BIG=1)\n";

/* The options-file keywords of the guide, with its ranges. */
static const struct opt_spec spec[] = {
	PLOT_OPT_COMMON, PLOT_OPT_LINES, PLOT_OPT_ONOFF("autorange"), PLOT_OPT_ONOFF("clip"),
	PLOT_OPT_ONOFF("grid"), PLOT_OPT_ONOFF("landscape"), PLOT_OPT_ONOFF("xlog"),
	PLOT_OPT_ONOFF("ylog"),
	{"sleeptime", OPT_INT, 1, 20, NULL},    /* SunView only: accepted, unused */
	PLOT_OPT_STR("templatefile"),
	{NULL, 0, 0, 0, NULL}
};

struct options {
	struct plot_cmd cmd;
	int noauto, clip, equal, grid, xlog, ylog, section, fill;
	const char *templ, *times;
	int nfiles;
	char **files;
};

struct ctx {
	struct plot_settings s;
	int autorange, clip, xlog, ylog, section, fill;
	struct template *t;
	double *times;          /* -times without -section: page i's print time */
	int ntimes;
	int nfiles;
	struct plot_file **pf;
};

#define MARKER_SIZE 6.0     /* points across */
#define LEGEND_FONT 10.0

static void parse_options(int argc, char **argv, struct options *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage_head, plot_usage_common, plot_usage_x);
	memset(o, 0, sizeof *o);
	plot_cmd_init(&o->cmd);
	o->files = xcalloc((size_t)argc, sizeof *o->files);
	while (a.i < argc) {
		const char *s = argv[a.i];
		args_help_exit(&a, 1);
		if (args_flag(&a, "-ar")) o->noauto = 1;
		else if (args_flag(&a, "-clip")) o->clip = 1;
		else if (args_flag(&a, "-e")) o->equal = 1;
		else if (args_flag(&a, "-g")) o->grid = 1;
		else if (args_flag(&a, "-xlog")) o->xlog = 1;
		else if (args_flag(&a, "-ylog")) o->ylog = 1;
		else if (args_str(&a, "-t", &o->templ)) ;
		else if (args_flag(&a, "-section")) o->section = 1;
		else if (args_flag(&a, "-fill")) o->fill = 1;
		else if (args_str(&a, "-times", &o->times)) ;
		else if (plot_cmd_arg(&a, &o->cmd, PC_LANDSCAPE | PC_XDISPLAY | PC_BIG)) ;
		else if (s[0] == '-' && s[1] != '\0') args_unknown(&a);
		else o->files[o->nfiles++] = argv[a.i++];
	}
	if (o->nfiles == 0)
		args_error(&a, "no plot-file");
	if (o->section && (o->xlog || o->ylog))
		args_error(&a, "-section draws linear axes: not with -xlog or -ylog");
	args_done(&a, NULL);
}

/* The data extent of a set (positive values only for a log axis). */
static void extent(const struct plot_set *st, int axis, int positive, double *lo, double *hi)
{
	*lo = INFINITY, *hi = -INFINITY;
	for (int c = 0; c < st->ncurves; c++)
		for (int k = 0; k < st->curves[c].npts; k++) {
			double v = st->curves[c].p[2 * k + axis];
			if (positive && !(v > 0))
				continue;
			if (v < *lo) *lo = v;
			if (v > *hi) *hi = v;
		}
}

static void make_axis(struct plot_axis *ax, const struct plot_set *st, int axis,
		      int log, int ndiv, int autorange)
{
	double lo = st->bounds[2 * axis], hi = st->bounds[2 * axis + 1];
	if (log) {
		if (!(lo > 0) || !(hi > lo))
			extent(st, axis, 1, &lo, &hi);
		if (plot_axis_log(ax, lo, hi, autorange))
			return;
		warn("no positive %c values for the log axis; using a linear axis",
		     axis ? 'y' : 'x');
		lo = st->bounds[2 * axis], hi = st->bounds[2 * axis + 1];
	}
	if (!(hi > lo)) {
		extent(st, axis, 0, &lo, &hi);
		if (!isfinite(lo))
			lo = 0, hi = 1;
	}
	plot_axis_linear(ax, lo, hi, ndiv, autorange);
}

/* Line type and marker of curve i (template, else linechange and
 * markerchange cycling, else solid line without marker). */
static void style(const struct ctx *c, int i, int *lt, int *mk, const char **label)
{
	*label = NULL;
	if (c->t) {
		const struct template_entry *e = &c->t->e[i % c->t->n];
		*lt = e->ln_type;
		*mk = e->mkr_type;
		*label = e->label;
	} else {
		*lt = c->s.linechange ? 1 + i % (DRAW_NLINETYPES - 1) : 1;
		*mk = c->s.markerchange ? 1 + i % (DRAW_NMARKERS - 1) : c->s.marker ? 2 : 0;
	}
	if (!c->s.line)
		*lt = 0;
	if (!c->s.marker && !c->s.markerchange && !c->t)
		*mk = 0;
}

static void draw_curve(struct draw *d, const struct plot_frame *f,
		       const struct plot_curve *cv, int lt, int mk)
{
	double *xy = xreallocarray(NULL, (size_t)cv->npts + 1, 2 * sizeof *xy);
	int n = 0;
	draw_set_line(d, lt, 1.0);
	for (int k = 0; k <= cv->npts; k++) {
		double px, py;
		if (k < cv->npts && plot_frame_map(f, cv->p[2 * k], cv->p[2 * k + 1], &px, &py)) {
			xy[2 * n] = px, xy[2 * n + 1] = py;
			n++;
			continue;
		}
		/* a point a log axis cannot show breaks the line */
		if (lt && n >= 2)
			draw_polyline(d, n, xy);
		if (mk)
			for (int m = 0; m < n; m++)
				draw_marker(d, mk, xy[2 * m], xy[2 * m + 1], MARKER_SIZE);
		n = 0;
	}
	free(xy);
}

static void legend(struct draw *d, const struct ctx *c, const struct plot_frame *f, int ncurves)
{
	int n = c->t ? (c->t->n < ncurves ? c->t->n : ncurves) : 0, shown = 0;
	for (int i = 0; i < n; i++)
		if (c->t->e[i].label)
			shown++;
	if (!shown)
		return;
	double row = LEGEND_FONT * 1.6, w = 0;
	for (int i = 0; i < n; i++)
		if (c->t->e[i].label) {
			double tw = strlen(c->t->e[i].label) * LEGEND_FONT * 0.55;
			if (tw > w) w = tw;
		}
	double bx1 = f->x1 - 8, bx0 = bx1 - (w + 50), by1 = f->y1 - 8, by0 = by1 - shown * row - 6;
	double box[8] = {bx0, by0, bx1, by0, bx1, by1, bx0, by1};
	draw_set_line(d, 1, 0.5);
	draw_polygon(d, 4, box, 1.0, 1);
	double y = by1 - 3 - row / 2;
	for (int i = 0; i < n; i++) {
		int lt, mk;
		const char *lab;
		style(c, i, &lt, &mk, &lab);
		if (!lab)
			continue;
		draw_set_line(d, lt, 1.0);
		if (lt)
			draw_segment(d, bx0 + 6, y, bx0 + 36, y);
		if (mk)
			draw_marker(d, mk, bx0 + 21, y, MARKER_SIZE);
		draw_set_line(d, 1, 0.8);
		draw_text(d, bx0 + 42, y, LEGEND_FONT, 0, DRAW_LEFT, DRAW_MIDDLE, lab);
		y -= row;
	}
}

/* -section: the substrate band's height below the box floor, as a
 * fraction of the box's height, and the greys (0 black, 1 white). */
#define SECTION_SUBSTRATE 0.15
#define SECTION_RESIST_GRAY 0.78
/* -section: z drawn within this fraction of x's scale counts as unstretched */
#define SECTION_SAME_SCALE 0.02
#define SECTION_SUBSTRATE_GRAY 0.5

/* One page per file: every set's profile, the resist under the last. */
static void section_page(struct draw *d, const struct ctx *c, const struct plot_file *pf)
{
	const struct plot_set *first = &pf->sets[0], *last = &pf->sets[pf->nsets - 1];
	struct plot_set frame = *first;
	double x0 = first->bounds[0], x1 = first->bounds[1];
	double floor = first->bounds[2], top = first->bounds[3];
	if (!(x1 > x0))
		extent(first, 0, 0, &x0, &x1);
	if (!(top > floor))
		extent(first, 1, 0, &floor, &top);
	if (!(x1 > x0) || !(top > floor))
		die("-section: the first set has no extent to draw");
	frame.bounds[0] = x0, frame.bounds[1] = x1;
	frame.bounds[2] = floor - SECTION_SUBSTRATE * (top - floor);
	frame.bounds[3] = top;
	struct plot_axis xa, ya;
	make_axis(&xa, &frame, 0, 0, c->s.xticks, c->autorange);
	make_axis(&ya, &frame, 1, 0, c->s.yticks, c->autorange);
	struct plot_frame f = {0, 0, 0, 0, &xa, &ya};
	plot_frame_place(&f, d, c->s.equalscale);
	/* the substrate: from the frame's bottom up to the box floor */
	double fx0, fx1, fy0, fy1;
	plot_frame_map(&f, x0, floor, &fx0, &fy1);
	plot_frame_map(&f, x1, floor, &fx1, &fy1);
	fy0 = f.y0;
	double band[8] = {fx0, fy0, fx1, fy0, fx1, fy1, fx0, fy1};
	draw_set_line(d, 1, 0.8);
	draw_polygon(d, 4, band, SECTION_SUBSTRATE_GRAY, 1);
	draw_text(d, (fx0 + fx1) / 2, (fy0 + fy1) / 2, LEGEND_FONT, 0, DRAW_CENTER,
		  DRAW_MIDDLE, "substrate");
	/* the resist left at the last print time: under each open profile,
	 * closed along the floor (closed loops are pockets: not filled) */
	for (int i = 0; i < last->ncurves; i++) {
		const struct plot_curve *cv = &last->curves[i];
		int n = cv->npts;
		if (n < 2 || (cv->p[0] == cv->p[2 * (n - 1)] && cv->p[1] == cv->p[2 * (n - 1) + 1]))
			continue;
		double *xy = xreallocarray(NULL, (size_t)n + 2, 2 * sizeof *xy);
		for (int k = 0; k < n; k++)
			plot_frame_map(&f, cv->p[2 * k], cv->p[2 * k + 1], &xy[2 * k], &xy[2 * k + 1]);
		plot_frame_map(&f, cv->p[2 * (n - 1)], floor, &xy[2 * n], &xy[2 * n + 1]);
		plot_frame_map(&f, cv->p[0], floor, &xy[2 * n + 2], &xy[2 * n + 3]);
		draw_polygon(d, n + 2, xy, SECTION_RESIST_GRAY, 0);
		free(xy);
	}
	/* the z scale against x's, stated in the z title when it differs */
	double zs = ((f.y1 - f.y0) / (ya.hi - ya.lo)) / ((f.x1 - f.x0) / (xa.hi - xa.lo));
	char yl[300];
	if (c->s.ylabel && *c->s.ylabel && fabs(zs - 1) > SECTION_SAME_SCALE)
		snprintf(yl, sizeof yl, "%.200s, stretched %.2gx", c->s.ylabel, zs);
	else
		snprintf(yl, sizeof yl, "%.250s", c->s.ylabel ? c->s.ylabel : "");
	plot_frame_draw(d, &f, c->s.grid, c->s.toplabel, c->s.xlabel, yl);
	for (int si = 0; si < pf->nsets; si++) {
		int lt, mk;
		const char *lab;
		style(c, si, &lt, &mk, &lab);
		for (int i = 0; i < pf->sets[si].ncurves; i++)
			draw_curve(d, &f, &pf->sets[si].curves[i], lt, mk);
	}
	legend(d, c, &f, pf->nsets);
}

/* -fill: the closed curves of a set (a region's outline) filled light
 * grey under every curve's line, so the region reads as an area even
 * where its outline runs along the frame. */
#define FILL_GRAY 0.85
static void fill_closed(struct draw *d, const struct plot_frame *f, const struct plot_set *st)
{
	for (int i = 0; i < st->ncurves; i++) {
		const struct plot_curve *cv = &st->curves[i];
		int n = cv->npts;
		if (n < 4 || cv->p[0] != cv->p[2 * (n - 1)] || cv->p[1] != cv->p[2 * (n - 1) + 1])
			continue;
		double *xy = xreallocarray(NULL, (size_t)n, 2 * sizeof *xy);
		int m = 0;
		for (int k = 0; k < n - 1; k++)
			if (plot_frame_map(f, cv->p[2 * k], cv->p[2 * k + 1], &xy[2 * m], &xy[2 * m + 1]))
				m++;
		draw_polygon(d, m, xy, FILL_GRAY, 0);
		free(xy);
	}
}

static struct draw *render(void *vc)
{
	const struct ctx *c = vc;
	struct draw *d = plot_new_page(c->s.landscape);
	int first = 1;
	if (c->section) {
		for (int fi = 0; fi < c->nfiles; fi++) {
			if (c->pf[fi]->nsets == 0)
				continue;
			if (!first)
				draw_page(d);
			first = 0;
			section_page(d, c, c->pf[fi]);
		}
		return d;
	}
	for (int fi = 0; fi < c->nfiles; fi++)
		for (int si = 0; si < c->pf[fi]->nsets; si++) {
			const struct plot_set *st = &c->pf[fi]->sets[si];
			if (!first)
				draw_page(d);
			first = 0;
			struct plot_axis xa, ya;
			make_axis(&xa, st, 0, c->xlog, c->s.xticks, c->autorange);
			make_axis(&ya, st, 1, c->ylog, c->s.yticks, c->autorange);
			struct plot_frame f = {0, 0, 0, 0, &xa, &ya};
			plot_frame_place(&f, d, c->s.equalscale);
			/* -times: the page's print time after the title */
			int page = d->npages ? d->npages - 1 : 0;
			char title[320];
			snprintf(title, sizeof title, "%.250s", c->s.toplabel ? c->s.toplabel : "");
			if (page < c->ntimes) {
				char tf[NUM_BUFSZ];
				size_t n = strlen(title);
				snprintf(title + n, sizeof title - n, "%st = %s s", n ? ", " : "",
					 num_fmt(tf, c->times[page]));
			}
			plot_frame_draw(d, &f, c->s.grid, title, c->s.xlabel, c->s.ylabel);
			if (c->clip)
				draw_clip(d, f.x0, f.y0, f.x1, f.y1);
			if (c->fill)
				fill_closed(d, &f, st);
			for (int i = 0; i < st->ncurves; i++) {
				int lt, mk;
				const char *lab;
				style(c, i, &lt, &mk, &lab);
				draw_curve(d, &f, &st->curves[i], lt, mk);
			}
			if (c->clip)
				draw_unclip(d);
			legend(d, c, &f, st->ncurves);
		}
	return d;
}

int main(int argc, char **argv)
{
	struct options o;
	parse_options(argc, argv, &o);
	struct ctx c;
	memset(&c, 0, sizeof c);
	struct opt_value val[sizeof spec / sizeof spec[0]];
	plot_begin(&c.s, &(struct plot_settings){
		.toplabel = "X-Y LINE PLOT", .xlabel = "X-AXIS", .ylabel = "Y-AXIS",
		.equalscale = 0, .postscript = 1, .line = 1, .scale = 1.0,
		.xticks = 4, .yticks = 4,
	}, spec, val, &o.cmd);
	const struct opt_value *v;
	c.autorange = (v = plot_opt(spec, val, "autorange")) ? (int)v->num : 1;
	if (o.noauto || c.s.ticks_set)  /* the guide: ticks in the file turn it off */
		c.autorange = 0;
	c.clip = o.clip || ((v = plot_opt(spec, val, "clip")) && v->num);
	c.xlog = o.xlog || ((v = plot_opt(spec, val, "xlog")) && v->num);
	c.ylog = o.ylog || ((v = plot_opt(spec, val, "ylog")) && v->num);
	if (o.equal) c.s.equalscale = 1;
	if (o.grid) c.s.grid = 1;
	const char *tf = o.templ;
	if (!tf && (v = plot_opt(spec, val, "templatefile")) && v->str[0])
		tf = v->str;
	if (tf)
		c.t = fmt_template_read(tf);
	c.section = o.section;
	c.fill = o.fill;
	if (c.section)          /* the box as it is: the fill ends at its sides */
		c.autorange = 0;
	if (o.times && !c.section) {
		/* -times: each page's title ends with its print time */
		c.ntimes = plot_parse_times(o.times, &c.times);
	} else if (o.times && !c.t) {
		/* -section -times: a legend of print times, a line type each */
		c.t = xcalloc(1, sizeof *c.t);
		double *tv;
		int n = plot_parse_times(o.times, &tv);
		c.t->e = xcalloc(n ? (size_t)n : 1, sizeof *c.t->e);
		for (; c.t->n < n; c.t->n++) {
			char f[NUM_BUFSZ], lab[64];
			snprintf(lab, sizeof lab, "t = %s s", num_fmt(f, tv[c.t->n]));
			c.t->e[c.t->n] = (struct template_entry){
				1 + c.t->n % (DRAW_NLINETYPES - 1), 0, xstrdup(lab), 0};
		}
		free(tv);
		if (c.t->n == 0)
			die_status(EXIT_USAGE, "-times: no time given");
	}

	c.nfiles = o.nfiles;
	/* the estimate (plot_budget), measured on the unbaked contact's
	 * curves.plot.2D (0.85 M numbers, 17 MB): 28 MB, 0.12 s */
	plot_budget(o.nfiles, o.files, 32, 1.5e-7);
	c.pf = xcalloc((size_t)o.nfiles, sizeof *c.pf);
	for (int i = 0; i < o.nfiles; i++)
		c.pf[i] = fmt_plot_read(o.files[i], 2);

	/* the first file that carries labels gives the default ones */
	for (int i = 0; i < o.nfiles; i++)
		if (!fmt_labels_empty(&c.pf[i]->labels)) {
			plot_settings_labels(&c.s, &c.pf[i]->labels, spec, val, &o.cmd);
			break;
		}
	plot_output(&c.s, &o.cmd, render, NULL, &c);

	for (int i = 0; i < o.nfiles; i++)
		fmt_plot_free(c.pf[i]);
	free(c.pf);
	fmt_template_free(c.t);
	free(c.times);
	fmt_options_free(spec, val);
	free(o.files);
	return 0;
}
