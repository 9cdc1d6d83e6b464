/*
 * pdraw - 3D line and polygon plots in parallel projection (thesis
 * Appendix B, pdraw(L)).
 *
 * The view vector v (the eye position relative to the origin) defines a
 * screen basis: w = v/|v| points to the eye, the screen's "up" is the z
 * axis projected on the screen plane (the y axis when looking along z),
 * and right = up x w.  Every set of every file is one page.
 *
 * Hidden lines (-h): the closed curves are polygons, filled white and
 * outlined, drawn back to front in the order of a BSP partition
 * (plot_bsp.c); open curves take part as segments.  Split pieces are
 * filled without an outline and only the parts of the original edges are
 * stroked, so no split seam shows.
 */
#include "args.h"
#include "draw.h"
#include "fmt_options.h"
#include "fmt_plot.h"
#include "num.h"
#include "plot_bsp.h"
#include "plot_common.h"
#include "plot_window.h"
#include "plot_zbuf.h"
#include "util.h"
#include "vec3.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage_head[] =
	"usage: pdraw [-v vx vy vz] [-o options-file] [-Pprinter] [-s scale] [-e]\n"
	"             [-zs factor|auto] [-times t1,t2,...] [-h [-walls] [-shade]]\n"
	"             [-raster|-vector] [-window x0 x1 y0 y1|auto]\n"
	"             [-nosort] [-noplot] [-print] [-ps] [-big] [-tl toplabel] [-xl xlabel]\n"
	"             [-yl ylabel] [-zl zlabel] [-svg file] [X options] plotfile...\n"
	"  -v vx vy vz      eye position (view vector), default -1 -2 1.5\n"
	"  -e               unequal axis scales (the bounding box becomes a cube)\n"
	"  -zs factor|auto  draw z factor times taller than x and y; auto: a box less\n"
	"                   than 1/4 as tall as wide is made about 1/2 (1, 2, 5 steps)\n"
	"  -times t1,...    the print times of the pages (s): each page's title says its time\n"
	"  -h               hidden-line drawing of the polygons (closed curves)\n"
	"  -walls           with -h: side walls from the surface's border down to\n"
	"                   the box floor, so a resist surface looks a solid block\n"
	"  -shade           with -h: grey polygons lit from the upper left, no mesh lines\n"
	"  -nosort          with -h: paint the polygons in file order\n"
	"  -raster          with -h: a shaded picture of 120 dpi, depth-buffered, no\n"
	"                   mesh lines (the default when the polygons are on average\n"
	"                   smaller than 2 x 2 points on the page)\n"
	"  -vector          with -h: polygons and lines however small they are\n"
	"  -window x0 x1 y0 y1  draw only the part of the data inside x0..x1, y0..y1\n"
	"                   (um), cut at its edges (with -walls, walls there)\n"
	"  -window auto     the central 6 x 6 um of data wider than 12 um (a large\n"
	"                   mask), the title saying so; smaller data whole\n"
	"  -big             draw plot files whose estimated memory or time (from\n"
	"                   their size) is beyond the limits (also SAMPLE3D_BIG=1)\n"
	"  -zl zlabel       z label\n"
	"  --help           this text (-h is hidden lines, as in the guide)\n"
	"  keys in the X11 window: h/l turn sideways, j/k up/down, a/d/s/f turn by\n"
	"  90 degrees, z/y/x project on the x-y, x-z, y-z planes, o original view,\n"
	"  q quit (the final view is written to the PostScript file)\n";

static const struct opt_spec spec[] = {
	PLOT_OPT_COMMON, PLOT_OPT_LINES, PLOT_OPT_STR("zlabel"), PLOT_OPT_TICKS("zticks"),
	PLOT_OPT_ONOFF("hiddenline"), PLOT_OPT_ONOFF("nosort"),
	{NULL, 0, 0, 0, NULL}
};

/* The default eye position: above the x-y plane, in front and to the
 * left, the angle of the thesis' profile figures. */
static const double DEFAULT_VIEW[3] = {-1, -2, 1.5};
/* Key rotations (degrees). */
#define STEP_ANGLE 15.0
/* Page area of the drawing (points): below the top label, above the foot. */
#define AREA_X0 70.0
#define AREA_X1 542.0
#define AREA_Y0 130.0
#define AREA_Y1 700.0
#define TICK_FRAC 0.03      /* tick length, fraction of the largest box side */
#define FONT_TICK 9.0
#define FONT_LABEL 12.0
#define FONT_TOP 16.0
#define MARKER_SIZE 5.0
struct options {
	struct plot_cmd cmd;
	double v[3];
	int has_v, unequal, hidden, nosort;
	double zs;          /* -zs factor, 0 for auto, 1 by default */
	int walls;          /* -walls */
	int shade;          /* -shade */
	int raster;         /* -raster 1, -vector -1, else 0 (by the polygons' size) */
	double win[4];      /* -window x0 x1 y0 y1 */
	int haswin;         /* 1 for a window, 2 for -window auto */
	const char *times;  /* -times list */
	int nfiles;
	char **files;
};

struct ctx {
	struct plot_settings s;
	double v[3], v0[3];
	int hidden, nosort, unequal;
	double zs;          /* z stretch, 0 for auto (per set) */
	int walls;          /* -walls */
	int shade;          /* -shade */
	int raster;         /* as in struct options */
	double win[4];
	int haswin;
	char winnote[96];   /* -window auto: what the title adds, or "" */
	double *times;      /* -times: page i's print time */
	int ntimes;
	int nsets;
	const struct plot_set **sets;
};

/* The estimate before reading (plot_budget): the peak bytes and the
 * seconds per number of the plot files, measured on the contact example's
 * unbaked curves.plot (26 MB, 1.27 M numbers, 105642 triangles, one core):
 * -h holds the numbers, the painter's fragments and the display list
 * (105 MB, 0.64 s); without -h (or -nosort) the numbers and the list
 * (39 MB with the text, 0.16 s; 0.08 to 0.1 us a number on grids of
 * 201^2 to 1001^2 as triangles, tests/bench/estimate.sh). */
#define B_HIDDEN 90.0
#define T_HIDDEN 6e-7
#define B_LINES 32.0
#define T_LINES 1.1e-7

static void parse_options(int argc, char **argv, struct options *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage_head, plot_usage_common, plot_usage_x);
	memset(o, 0, sizeof *o);
	o->zs = 1;
	plot_cmd_init(&o->cmd);
	o->files = xcalloc((size_t)argc, sizeof *o->files);
	while (a.i < argc) {
		const char *s = argv[a.i];
		args_help_exit(&a, 0); /* -h is hidden lines here */
		if (args_flag(&a, "-v")) {
			for (int k = 0; k < 3; k++) {
				if (a.i >= argc || !num_parse(argv[a.i], &o->v[k])) {
					args_error(&a, "option -v needs three numbers vx vy vz");
					break;
				}
				a.i++;
			}
			o->has_v = 1;
			if (o->v[0] == 0 && o->v[1] == 0 && o->v[2] == 0)
				args_error(&a, "option -v: the view vector must not be zero");
		}
		else if (args_flag(&a, "-e")) o->unequal = 1;
		else if (args_flag(&a, "-walls")) o->walls = 1;
		else if (args_flag(&a, "-shade")) o->shade = 1;
		else if (args_flag(&a, "-raster")) o->raster = 1;
		else if (args_flag(&a, "-vector")) o->raster = -1;
		else if (a.i + 1 < argc && strcmp(s, "-window") == 0 &&
			 strcmp(argv[a.i + 1], "auto") == 0) {
			o->haswin = 2;
			a.i += 2;
		}
		else if (args_flag(&a, "-window")) {
			for (int k = 0; k < 4; k++) {
				if (a.i >= argc || !num_parse(argv[a.i], &o->win[k])) {
					args_error(&a, "option -window needs four numbers x0 x1 y0 y1");
					break;
				}
				a.i++;
			}
			o->haswin = 1;
			if (!(o->win[1] > o->win[0]) || !(o->win[3] > o->win[2]))
				args_error(&a, "option -window: x0 x1 y0 y1 with x0 < x1 and y0 < y1");
		}
		else if (a.i + 1 < argc && strcmp(s, "-zs") == 0 &&
			 strcmp(argv[a.i + 1], "auto") == 0) {
			o->zs = 0;
			a.i += 2;
		}
		else if (args_num(&a, "-zs", 1e-3, 1e6, &o->zs)) ;
		else if (args_str(&a, "-times", &o->times)) ;
		else if (args_flag(&a, "-h")) o->hidden = 1;
		else if (args_flag(&a, "-nosort")) o->nosort = 1;
		else if (plot_cmd_arg(&a, &o->cmd, PC_ZLABEL | PC_XDISPLAY | PC_BIG)) ;
		else if (s[0] == '-' && s[1] != '\0') args_unknown(&a);
		else o->files[o->nfiles++] = argv[a.i++];
	}
	if (o->nfiles == 0)
		args_error(&a, "no plotfile");
	args_done(&a, NULL);
}

/* ---- view ---- */

struct view {
	double e1[3], e2[3], w[3];  /* screen right, up, towards the eye */
	double c[3], sc[3];         /* data -> unit box: (p - c) * sc */
	double a, bx, by;           /* view plane -> page: a*X + bx, a*Y + by */
};

static int normalize3(double *a)
{
	double n = sqrt(vec3_dot(a, a));
	if (!(n > 0))
		return 0;
	a[0] /= n, a[1] /= n, a[2] /= n;
	return 1;
}

/* Screen basis of a view vector: up is z projected on the screen, or y
 * when looking along z. */
static void basis(const double *v, double *e1, double *e2, double *w)
{
	memcpy(w, v, 3 * sizeof *w);
	normalize3(w);
	double z[3] = {0, 0, 1};
	double t = vec3_dot(z, w);
	for (int k = 0; k < 3; k++)
		e2[k] = z[k] - t * w[k];
	if (sqrt(vec3_dot(e2, e2)) < 1e-9) {
		double y[3] = {0, 1, 0};
		t = vec3_dot(y, w);
		for (int k = 0; k < 3; k++)
			e2[k] = y[k] - t * w[k];
	}
	normalize3(e2);
	vec3_cross(e2, w, e1);
}

/* Data point -> view coordinates X (right), Y (up), D (towards the eye). */
static void to_view(const struct view *vw, const double *p, double *o)
{
	double q[3];
	for (int k = 0; k < 3; k++)
		q[k] = (p[k] - vw->c[k]) * vw->sc[k];
	o[0] = vec3_dot(q, vw->e1);
	o[1] = vec3_dot(q, vw->e2);
	o[2] = vec3_dot(q, vw->w);
}

static void to_page(const struct view *vw, const double *p, double *px, double *py)
{
	double o[3];
	to_view(vw, p, o);
	*px = vw->a * o[0] + vw->bx;
	*py = vw->a * o[1] + vw->by;
}

/* The box of a set: its bounds, or the data's extent where a bound pair
 * is empty. */
static void set_box(const struct plot_set *st, double *b)
{
	memcpy(b, st->bounds, 6 * sizeof *b);
	for (int k = 0; k < 3; k++) {
		if (b[2 * k + 1] > b[2 * k])
			continue;
		double lo = INFINITY, hi = -INFINITY;
		for (int c = 0; c < st->ncurves; c++)
			for (int i = 0; i < st->curves[c].npts; i++) {
				double v = st->curves[c].p[3 * i + k];
				lo = fmin(lo, v), hi = fmax(hi, v);
			}
		if (!(hi > lo)) {
			double m = isfinite(lo) ? lo : 0;
			lo = m - 0.5, hi = m + 0.5;
		}
		b[2 * k] = lo, b[2 * k + 1] = hi;
	}
}

/* -zs auto: when the box is less than a quarter as tall as wide (a resist
 * film on a mask cell), the z stretch that makes it about half as tall as
 * wide, rounded to the nearest (in ratio) 1, 2 or 5 times a power of ten;
 * otherwise 1. */
static double auto_stretch(const double *box)
{
	double wide = fmax(box[1] - box[0], box[3] - box[2]), tall = box[5] - box[4];
	if (!(tall > 0) || !(tall * 4 < wide))
		return 1;
	double want = wide / 2 / tall, p = pow(10, floor(log10(want)));
	double f = want / p;        /* 1 <= f < 10 */
	/* nearest in ratio: the boundaries are the geometric means */
	double step = f < sqrt(2.0) ? 1 : f < sqrt(10.0) ? 2 : f < sqrt(50.0) ? 5 : 10;
	return step * p;
}

/* The z stretch of a set's page (1 with -e, which scales every side). */
static double stretch_of(const struct ctx *c, const double *box)
{
	if (c->unequal)
		return 1;
	return c->zs > 0 ? c->zs : auto_stretch(box);
}

static void make_view(struct view *vw, const struct ctx *c, const double *box)
{
	basis(c->v, vw->e1, vw->e2, vw->w);
	double big = 0, zs = stretch_of(c, box);
	for (int k = 0; k < 3; k++)
		big = fmax(big, (box[2 * k + 1] - box[2 * k]) * (k == 2 ? zs : 1));
	for (int k = 0; k < 3; k++) {
		vw->c[k] = (box[2 * k] + box[2 * k + 1]) / 2;
		/* -e: each side scaled to 1 (a cube); else one scale for all,
		 * z stretched by -zs */
		vw->sc[k] = c->unequal ? 1 / (box[2 * k + 1] - box[2 * k])
				       : (k == 2 ? zs : 1) / big;
	}
	double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
	for (int i = 0; i < 8; i++) {
		double p[3] = {box[i & 1], box[2 + ((i >> 1) & 1)], box[4 + ((i >> 2) & 1)]}, o[3];
		to_view(vw, p, o);
		for (int k = 0; k < 2; k++)
			lo[k] = fmin(lo[k], o[k]), hi[k] = fmax(hi[k], o[k]);
	}
	/* a margin for the tick labels */
	double m = 0.12 * fmax(hi[0] - lo[0], hi[1] - lo[1]);
	lo[0] -= m, lo[1] -= m, hi[0] += m, hi[1] += m;
	double ax = (AREA_X1 - AREA_X0) / (hi[0] - lo[0]);
	double ay = (AREA_Y1 - AREA_Y0) / (hi[1] - lo[1]);
	vw->a = fmin(ax, ay);
	vw->bx = (AREA_X0 + AREA_X1) / 2 - vw->a * (lo[0] + hi[0]) / 2;
	vw->by = (AREA_Y0 + AREA_Y1) / 2 - vw->a * (lo[1] + hi[1]) / 2;
}

/* ---- axes ---- */

/* The page boxes of the texts an axis frame has placed, so that a tick
 * label that would overlap another text is left out rather than drawn on
 * top of it (axis titles are placed first and always drawn).  Widths are
 * estimated from Helvetica's mean advance, 0.56 of the font size. */
#define TEXT_ADVANCE 0.56
#define MAX_TEXTS 128
struct texts {
	int n;
	double box[MAX_TEXTS][4];
};

static void text_box(double x, double y, double size, double angle, const char *s, double *b)
{
	double w = TEXT_ADVANCE * size * (double)strlen(s) / 2 + 1, h = size / 2 + 1;
	double ca = fabs(cos(angle * M_PI / 180)), sa = fabs(sin(angle * M_PI / 180));
	double hw = w * ca + h * sa, hh = w * sa + h * ca;
	b[0] = x - hw, b[1] = y - hh, b[2] = x + hw, b[3] = y + hh;
}

/* Places a centred text unless it overlaps one placed before (force:
 * always); returns whether it was drawn. */
static int place_text(struct draw *d, struct texts *tx, double x, double y, double size,
		      double angle, const char *s, int force)
{
	double b[4];
	text_box(x, y, size, angle, s, b);
	if (!force)
		for (int i = 0; i < tx->n; i++)
			if (b[0] < tx->box[i][2] && tx->box[i][0] < b[2] &&
			    b[1] < tx->box[i][3] && tx->box[i][1] < b[3])
				return 0;
	if (tx->n < MAX_TEXTS)
		memcpy(tx->box[tx->n++], b, sizeof b);
	draw_text(d, x, y, size, angle, DRAW_CENTER, DRAW_MIDDLE, s);
	return 1;
}

/* One axis along the box edge from p0 (at the axis' low end) in direction
 * k, ticks pointing along out (unit box units): pass 0 its title, 1 its
 * line and ticks, 2 its tick labels. */
static void axis3(struct draw *d, const struct view *vw, const double *box, int k,
		  const double *p0, const double *out, int ndiv, const char *label,
		  double angle, struct texts *tx, int pass)
{
	struct plot_axis ax;
	plot_axis_linear(&ax, box[2 * k], box[2 * k + 1], ndiv, 0);
	double a[3], b[3], x0, y0, x1, y1;
	memcpy(a, p0, sizeof a);
	memcpy(b, p0, sizeof b);
	a[k] = box[2 * k], b[k] = box[2 * k + 1];
	if (pass == 0) {       /* the title first: it is always drawn */
		if (label && *label) {
			double m[3];
			for (int j = 0; j < 3; j++)
				m[j] = (a[j] + b[j]) / 2 + out[j] * 7 * TICK_FRAC / vw->sc[j];
			double lx, ly;
			to_page(vw, m, &lx, &ly);
			place_text(d, tx, lx, ly, FONT_LABEL, angle, label, 1);
		}
		return;
	}
	to_page(vw, a, &x0, &y0);
	to_page(vw, b, &x1, &y1);
	draw_set_line(d, 1, 0.8);
	if (pass == 1)
		draw_segment(d, x0, y0, x1, y1);
	double t[3], tl[3];
	for (int i = 0; i < ax.nticks; i++) {
		double p[3];
		memcpy(p, p0, sizeof p);
		p[k] = ax.tick[i];
		for (int j = 0; j < 3; j++) {
			t[j] = p[j] + out[j] * TICK_FRAC / vw->sc[j];
			tl[j] = p[j] + out[j] * 3 * TICK_FRAC / vw->sc[j];
		}
		double px, py, qx, qy, lx, ly;
		to_page(vw, p, &px, &py);
		to_page(vw, t, &qx, &qy);
		to_page(vw, tl, &lx, &ly);
		if (pass == 1)
			draw_segment(d, px, py, qx, qy);
		else
			place_text(d, tx, lx, ly, FONT_TICK, 0, ax.label[i], 0);
	}
}

/* The axes run along silhouette edges of the box, so the data never
 * hides them: x and y along the bottom edges of the faces turned to the
 * eye, z up the vertical edge at the left of the picture. */
static void axes(struct draw *d, const struct view *vw, const double *box, const struct ctx *c)
{
	int xf = vw->w[0] >= 0, yf = vw->w[1] >= 0;     /* front faces: max sides? */
	double xfront = box[xf], yfront = box[2 + yf];
	double sx = xf ? 1 : -1, sy = yf ? 1 : -1;
	double px[3] = {0, yfront, box[4]}, ox[3] = {0, sy, 0};
	double py[3] = {xfront, 0, box[4]}, oy[3] = {sx, 0, 0};
	/* of the two side corners (xfront, yback) and (xback, yfront), the
	 * one further left on the screen */
	double ca[3] = {xfront, box[2 + !yf], 0}, cb[3] = {box[!xf], yfront, 0};
	double *pz = vec3_dot(ca, vw->e1) * vw->sc[0] <= vec3_dot(cb, vw->e1) * vw->sc[0] ? ca : cb;
	double oz[3] = {-vw->e1[0], -vw->e1[1], 0};
	/* z ticks point to the screen's left, in the x-y plane */
	if (!normalize3(oz))
		oz[0] = -sx;
	/* the z title says how much z is stretched */
	double zs = stretch_of(c, box);
	char zlabel[256];
	if (zs != 1 && c->s.zlabel && *c->s.zlabel) {
		char f[NUM_BUFSZ];
		snprintf(zlabel, sizeof zlabel, "%.200s, stretched %sx", c->s.zlabel,
			 num_fmt(f, zs));
	} else {
		snprintf(zlabel, sizeof zlabel, "%.250s", c->s.zlabel ? c->s.zlabel : "");
	}
	struct texts tx = {0};
	/* the titles, the lines, then the tick labels with z's before x's
	 * and y's: where the axes meet at a corner the z axis keeps its
	 * bottom label (x and y have the other end) */
	for (int pass = 0; pass < 2; pass++) {
		axis3(d, vw, box, 0, px, ox, c->s.xticks, c->s.xlabel, 0, &tx, pass);
		axis3(d, vw, box, 1, py, oy, c->s.yticks, c->s.ylabel, 0, &tx, pass);
		axis3(d, vw, box, 2, pz, oz, c->s.zticks, zlabel, 90, &tx, pass);
	}
	axis3(d, vw, box, 2, pz, oz, c->s.zticks, zlabel, 90, &tx, 2);
	axis3(d, vw, box, 0, px, ox, c->s.xticks, c->s.xlabel, 0, &tx, 2);
	axis3(d, vw, box, 1, py, oy, c->s.yticks, c->s.ylabel, 0, &tx, 2);
}

/* ---- drawing ---- */

static int curve_linetype(const struct ctx *c, int i)
{
	if (!c->s.line)
		return 0;
	return c->s.linechange ? 1 + i % (DRAW_NLINETYPES - 1) : 1;
}

static int curve_marker(const struct ctx *c, int i)
{
	if (c->s.markerchange)
		return 1 + i % (DRAW_NMARKERS - 1);
	return c->s.marker ? 2 : 0;
}

/* Closed curve with at least 3 distinct corners: a polygon. */
static int is_polygon(const struct plot_curve *cv)
{
	return cv->npts >= 4 && memcmp(cv->p, cv->p + 3 * (cv->npts - 1), 3 * sizeof *cv->p) == 0;
}

/* What paint_frag draws with: the page, its view and the settings. */
struct paint_ctx {
	struct draw *d;
	const struct view *vw;
	const struct ctx *c;
};

/* A fragment as the painter hands it over (plot_bsp_paint), far ones first. */
static void paint_frag(void *pctx, const struct plot_frag *f)
{
	const struct paint_ctx *pc = pctx;
	struct draw *d = pc->d;
	const struct view *vw = pc->vw;
	const struct ctx *c = pc->c;
	double *xy = xreallocarray(NULL, (size_t)f->n + 1, 2 * sizeof *xy);
	for (int i = 0; i < f->n; i++) {
		xy[2 * i] = vw->a * f->p[3 * i] + vw->bx;
		xy[2 * i + 1] = vw->a * f->p[3 * i + 1] + vw->by;
	}
	draw_set_line(d, curve_linetype(c, f->curve), 0.6);
	if (f->seg) {
		if (f->orig[0])
			draw_polyline(d, 2, xy);
		free(xy);
		return;
	}
	if (c->shade) {
		/* a hairline of the fill's own grey closes the seams that an
		 * anti-aliasing viewer shows between adjacent fills */
		draw_set_line(d, 1, 0.25);
		draw_set_gray(d, f->gray);
		draw_polygon(d, f->n, xy, f->gray, 1);
		draw_set_gray(d, 0);
		draw_set_line(d, curve_linetype(c, f->curve), 0.6);
	} else {
		draw_polygon(d, f->n, xy, f->gray, 0);
	}
	/* stroke the runs of original edges */
	int start = 0;
	while (start < f->n && f->orig[start])
		start++;
	if (start == f->n) {
		draw_polygon(d, f->n, xy, DRAW_NOFILL, 1);
		free(xy);
		return;
	}
	double *run = xreallocarray(NULL, (size_t)f->n + 1, 2 * sizeof *run);
	int m = 0;
	for (int k = 1; k <= f->n; k++) {
		int i = (start + k) % f->n;     /* edge i starts at vertex i */
		if (f->orig[i]) {
			if (m == 0)
				run[0] = xy[2 * i], run[1] = xy[2 * i + 1], m = 1;
			int j = (i + 1) % f->n;
			run[2 * m] = xy[2 * j], run[2 * m + 1] = xy[2 * j + 1];
			m++;
		} else if (m) {
			draw_polyline(d, m, run);
			m = 0;
		}
	}
	if (m)
		draw_polyline(d, m, run);
	free(run);
	free(xy);
}

/* -walls: the resist block's side walls.  An edge of a surface polygon
 * lying in one of the box's side planes (x or y at a bound) is extended
 * down to the box's floor as a grey quadrilateral, so the developed
 * surface is seen as the top of a solid block, not a sheet in the air.
 * Only the floor edge is stroked, and the vertical edges at the box's
 * corners, so the wall does not show the mesh. */
#define WALL_GRAY 0.82
/* A border node counts as on a side within this fraction of the box's
 * width (0.5 nm on a 5 um cell, far below a pixel): a node a hair inside
 * the side, as etch's clipping once left them, failed a tighter test, its
 * two edges got no wall and the page showed through as a white slit down
 * the block's face. */
#define WALL_SNAP 1e-4
static int on_side(const double *p, const double *box, int k)
{
	double eps = WALL_SNAP * (box[2 * k + 1] - box[2 * k]);
	if (fabs(p[k] - box[2 * k]) <= eps)
		return 1;
	if (fabs(p[k] - box[2 * k + 1]) <= eps)
		return 2;
	return 0;
}

static void add_walls(struct plot_frag_list *all, const struct view *vw, const double *box,
		      const struct plot_curve *cv, int curve)
{
	for (int e = 0; e + 1 < cv->npts; e++) {
		const double *a = cv->p + 3 * e, *b = cv->p + 3 * e + 3;
		for (int k = 0; k < 2; k++) {
			int sa = on_side(a, box, k);
			if (!sa || sa != on_side(b, box, k))
				continue;
			if (a[2] <= box[4] && b[2] <= box[4])
				continue;       /* on the floor: no wall */
			double q[4][3] = {{a[0], a[1], a[2]}, {b[0], b[1], b[2]},
					  {b[0], b[1], box[4]}, {a[0], a[1], box[4]}};
			struct plot_frag *f = plot_frag_new(4, curve, 0);
			f->gray = WALL_GRAY;
			for (int j = 0; j < 4; j++)
				to_view(vw, q[j], f->p + 3 * j);
			f->orig[2] = 1;         /* the floor edge */
			f->orig[1] = on_side(b, box, 1 - k) != 0;   /* a box corner */
			f->orig[3] = on_side(a, box, 1 - k) != 0;
			plot_frag_plane(f);
			plot_frag_list_add(all, f);
		}
	}
}

/* -shade: a polygon's grey from its facing (Lambert, a light from the
 * upper left behind the eye), in view coordinates, so the shading follows
 * the picture as drawn (z stretched or not). */
#define SHADE_AMBIENT 0.3
static double shade_normal(const double *un)
{
	static const double light[3] = {-0.42, 0.56, 0.71};   /* unit length */
	double n[3] = {un[0], un[1], un[2]};
	if (n[2] < 0)                   /* the side turned to the eye */
		n[0] = -n[0], n[1] = -n[1], n[2] = -n[2];
	double l = vec3_dot(n, light);
	return SHADE_AMBIENT + (1 - SHADE_AMBIENT) * (l > 0 ? l : 0);
}

static double shade(const struct plot_frag *f)
{
	return f->hasplane ? shade_normal(f->pl) : 1.0;
}

/* ---- -raster: a depth-buffered picture ---- */

/* Pixels per point of the picture: 120 dpi, finer than the 80 dpi of a
 * slide and the 60-100 of a screen, so no pixel of it shows. */
#define RASTER_PPP (120.0 / 72)
/* Polygons smaller than this on the page on average (points^2, 2 x 2)
 * would be drawn as outlines closer than a pixel at 80 dpi (a black
 * noise): such a set is drawn as a picture. */
#define RASTER_AREA 4.0
/* The walls facing x and those facing y in two greys, so the block's
 * corner shows without an outline. */
#define WALL_GRAY_Y 0.7

/* A polygon of view points (n, not repeated) into the buffer as a fan,
 * grey g; its page points in xy. */
static void zbuf_polygon(struct plot_zbuf *zb, const struct view *vw, const double *o, int n,
			 double g)
{
	for (int i = 1; i + 1 < n; i++) {
		const int t[3] = {0, i, i + 1};
		double x[3], y[3], dd[3];
		for (int k = 0; k < 3; k++) {
			x[k] = vw->a * o[3 * t[k]] + vw->bx;
			y[k] = vw->a * o[3 * t[k] + 1] + vw->by;
			dd[k] = o[3 * t[k] + 2];
		}
		plot_zbuf_tri(zb, x, y, dd, g);
	}
}

/* Newell's normal of view points (unit, or 0 for a degenerate polygon). */
static int newell(const double *o, int n, double *nv)
{
	nv[0] = nv[1] = nv[2] = 0;
	for (int i = 0; i < n; i++) {
		const double *a = o + 3 * i, *b = o + 3 * ((i + 1) % n);
		nv[0] += (a[1] - b[1]) * (a[2] + b[2]);
		nv[1] += (a[2] - b[2]) * (a[0] + b[0]);
		nv[2] += (a[0] - b[0]) * (a[1] + b[1]);
	}
	return normalize3(nv);
}

/* The mean page area of a set's polygons (points^2), 0 without any. */
static double mean_area(const struct view *vw, const struct plot_set *st)
{
	double sum = 0;
	long n = 0;
	for (int i = 0; i < st->ncurves; i++) {
		const struct plot_curve *cv = &st->curves[i];
		if (!is_polygon(cv))
			continue;
		double o0[3], oa[3], ob[3], a = 0;
		to_view(vw, cv->p, o0);
		to_view(vw, cv->p + 3, oa);
		for (int k = 2; k + 1 < cv->npts; k++) {
			to_view(vw, cv->p + 3 * k, ob);
			a += ((oa[0] - o0[0]) * (ob[1] - o0[1]) - (ob[0] - o0[0]) * (oa[1] - o0[1])) / 2;
			memcpy(oa, ob, sizeof oa);
		}
		sum += fabs(a) * vw->a * vw->a;
		n++;
	}
	return n ? sum / (double)n : 0;
}

/* -h as a picture: every polygon shaded (Lambert, shade_normal) and the
 * -walls in two greys, kept where nearest the eye; open curves drawn on
 * top as lines. */
static void draw_raster(struct draw *d, const struct view *vw, const struct ctx *c,
			const struct plot_set *st, const double *box)
{
	double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
	for (int i = 0; i < 8; i++) {
		double p[3] = {box[i & 1], box[2 + ((i >> 1) & 1)], box[4 + ((i >> 2) & 1)]}, x, y;
		to_page(vw, p, &x, &y);
		lo[0] = fmin(lo[0], x), lo[1] = fmin(lo[1], y);
		hi[0] = fmax(hi[0], x), hi[1] = fmax(hi[1], y);
	}
	struct plot_zbuf zb;
	plot_zbuf_init(&zb, floor(lo[0]), floor(lo[1]), ceil(hi[0]), ceil(hi[1]), RASTER_PPP);
	double *o = NULL;
	size_t cap = 0;
	for (int i = 0; i < st->ncurves; i++) {
		const struct plot_curve *cv = &st->curves[i];
		if (!is_polygon(cv))
			continue;
		int n = cv->npts - 1;
		xgrow(&o, &cap, (size_t)n * 3, sizeof *o);
		for (int k = 0; k < n; k++)
			to_view(vw, cv->p + 3 * k, o + 3 * k);
		double nv[3];
		if (newell(o, n, nv))
			zbuf_polygon(&zb, vw, o, n, shade_normal(nv));
		if (!c->walls)
			continue;
		for (int e = 0; e < n; e++) {
			const double *a = cv->p + 3 * e, *b = cv->p + 3 * e + 3;
			for (int k = 0; k < 2; k++) {
				int sa = on_side(a, box, k);
				if (!sa || sa != on_side(b, box, k) || (a[2] <= box[4] && b[2] <= box[4]))
					continue;
				double q[4][3] = {{a[0], a[1], a[2]}, {b[0], b[1], b[2]},
						  {b[0], b[1], box[4]}, {a[0], a[1], box[4]}}, w[12];
				for (int j = 0; j < 4; j++)
					to_view(vw, q[j], w + 3 * j);
				zbuf_polygon(&zb, vw, w, 4, k == 0 ? WALL_GRAY : WALL_GRAY_Y);
			}
		}
	}
	free(o);
	plot_zbuf_draw(&zb, d);
	for (int i = 0; i < st->ncurves; i++) {
		const struct plot_curve *cv = &st->curves[i];
		if (is_polygon(cv))
			continue;
		double *xy = xreallocarray(NULL, (size_t)cv->npts + 1, 2 * sizeof *xy);
		for (int k = 0; k < cv->npts; k++)
			to_page(vw, cv->p + 3 * k, &xy[2 * k], &xy[2 * k + 1]);
		draw_set_line(d, curve_linetype(c, i), 0.6);
		draw_polyline(d, cv->npts, xy);
		free(xy);
	}
}

static void draw_hidden(struct draw *d, const struct view *vw, const struct ctx *c,
			const struct plot_set *st, const double *box)
{
	struct plot_frag_list all = {0};
	for (int i = 0; i < st->ncurves; i++) {
		const struct plot_curve *cv = &st->curves[i];
		if (is_polygon(cv)) {
			struct plot_frag *f = plot_frag_new(cv->npts - 1, i, 0);
			for (int k = 0; k + 1 < cv->npts; k++) {
				to_view(vw, cv->p + 3 * k, f->p + 3 * k);
				f->orig[k] = 1;
			}
			plot_frag_plane(f);
			if (c->shade) {
				f->gray = shade(f);
				memset(f->orig, 0, (size_t)f->n);
			}
			plot_frag_list_add(&all, f);
			if (c->walls)
				add_walls(&all, vw, box, cv, i);
		} else {
			for (int k = 0; k + 1 < cv->npts; k++) {
				struct plot_frag *f = plot_frag_new(2, i, 1);
				to_view(vw, cv->p + 3 * k, f->p);
				to_view(vw, cv->p + 3 * k + 3, f->p + 3);
				f->orig[0] = 1;
				plot_frag_list_add(&all, f);
			}
		}
	}
	plot_bsp_paint(all, paint_frag, &(struct paint_ctx){d, vw, c});
}

static void draw_set(struct draw *d, const struct ctx *c, const struct plot_set *st,
		     int page)
{
	double box[6];
	set_box(st, box);
	struct view vw;
	make_view(&vw, c, box);
	char title[320];
	snprintf(title, sizeof title, "%.200s", c->s.toplabel ? c->s.toplabel : "");
	if (*c->winnote) {
		size_t n = strlen(title);
		snprintf(title + n, sizeof title - n, "%s%s", n ? ", " : "", c->winnote);
	}
	if (page < c->ntimes) {
		char f[NUM_BUFSZ];
		size_t n = strlen(title);
		snprintf(title + n, sizeof title - n, "%st = %s s", n ? ", " : "",
			 num_fmt(f, c->times[page]));
	}
	if (*title)
		draw_text(d, d->w / 2, AREA_Y1 + 40, FONT_TOP, 0, DRAW_CENTER, DRAW_BOTTOM,
			  title);
	if (!c->hidden)
		axes(d, &vw, box, c);
	double area = c->hidden && !c->nosort && c->raster >= 0 ? mean_area(&vw, st) : 0;
	if (area > 0 && (c->raster > 0 || area < RASTER_AREA)) {
		draw_raster(d, &vw, c, st, box);
	} else if (c->hidden && !c->nosort) {
		draw_hidden(d, &vw, c, st, box);
	} else {
		for (int i = 0; i < st->ncurves; i++) {
			const struct plot_curve *cv = &st->curves[i];
			double *xy = xreallocarray(NULL, (size_t)cv->npts + 1, 2 * sizeof *xy);
			for (int k = 0; k < cv->npts; k++)
				to_page(&vw, cv->p + 3 * k, &xy[2 * k], &xy[2 * k + 1]);
			draw_set_line(d, curve_linetype(c, i), 0.6);
			if (c->hidden && is_polygon(cv))        /* -nosort: file order */
				draw_polygon(d, cv->npts - 1, xy, 1.0, curve_linetype(c, i) != 0);
			else
				draw_polyline(d, cv->npts, xy);
			free(xy);
		}
	}
	if (c->hidden)     /* on top: polygons must not cover the labels */
		axes(d, &vw, box, c);
	for (int i = 0; i < st->ncurves; i++) {
		int mk = curve_marker(c, i);
		if (!mk)
			continue;
		const struct plot_curve *cv = &st->curves[i];
		for (int k = 0; k < cv->npts; k++) {
			double x, y;
			to_page(&vw, cv->p + 3 * k, &x, &y);
			draw_marker(d, mk, x, y, MARKER_SIZE);
		}
	}
}

static struct draw *render(void *vc)
{
	const struct ctx *c = vc;
	struct draw *d = plot_new_page(0);
	for (int i = 0; i < c->nsets; i++) {
		if (i)
			draw_page(d);
		draw_set(d, c, c->sets[i], i);
	}
	return d;
}

/* -window auto: data wider than AUTO_WIDE (um) on either side, a large
 * mask, is drawn in its central AUTO_SIDE x AUTO_SIDE um: a few features
 * of an array (6 x 6 contacts of a 1 um pitch), large enough to see each
 * feature's shape on a slide; the first set's box decides for every page. */
#define AUTO_WIDE 12.0
#define AUTO_SIDE 6.0
static void auto_window(struct ctx *c)
{
	double box[6];
	set_box(c->sets[0], box);
	c->haswin = 0;
	if (!(box[1] - box[0] > AUTO_WIDE) && !(box[3] - box[2] > AUTO_WIDE))
		return;
	for (int k = 0; k < 2; k++) {
		double m = (box[2 * k] + box[2 * k + 1]) / 2, h = AUTO_SIDE / 2;
		c->win[2 * k] = fmax(box[2 * k], m - h);
		c->win[2 * k + 1] = fmin(box[2 * k + 1], m + h);
	}
	char a[NUM_BUFSZ], b[NUM_BUFSZ];
	snprintf(c->winnote, sizeof c->winnote, "the central %s x %s um",
		 num_fmt(a, c->win[1] - c->win[0]), num_fmt(b, c->win[3] - c->win[2]));
	c->haswin = 1;
}

/* ---- keys (the guide's H J K L O A S D F Z Y X) ---- */

/* Rotates v by angle (degrees) about the unit axis u (Rodrigues). */
static void rotate(double *v, const double *u, double angle)
{
	double t = angle * M_PI / 180, cs = cos(t), sn = sin(t), k = vec3_dot(u, v), x[3];
	vec3_cross(u, v, x);
	for (int i = 0; i < 3; i++)
		v[i] = v[i] * cs + x[i] * sn + u[i] * k * (1 - cs);
}

static int key(void *vc, int ch)
{
	struct ctx *c = vc;
	double e1[3], e2[3], w[3], z[3] = {0, 0, 1};
	basis(c->v, e1, e2, w);
	switch (ch) {
	case 'h': case 'H': rotate(c->v, z, -STEP_ANGLE); break;
	case 'l': case 'L': rotate(c->v, z, STEP_ANGLE); break;
	case 'j': case 'J': rotate(c->v, e1, -STEP_ANGLE); break;
	case 'k': case 'K': rotate(c->v, e1, STEP_ANGLE); break;
	case 'a': case 'A': rotate(c->v, z, -90); break;
	case 'd': case 'D': rotate(c->v, z, 90); break;
	case 's': case 'S': rotate(c->v, e1, 90); break;
	case 'f': case 'F': rotate(c->v, e1, -90); break;
	case 'o': case 'O': memcpy(c->v, c->v0, sizeof c->v); break;
	case 'z': case 'Z': c->v[0] = 0, c->v[1] = 0, c->v[2] = 1; break;
	case 'y': case 'Y': c->v[0] = 0, c->v[1] = -1, c->v[2] = 0; break;
	case 'x': case 'X': c->v[0] = 1, c->v[1] = 0, c->v[2] = 0; break;
	default: return 0;
	}
	/* clean rounding noise so the written view is reproducible */
	for (int i = 0; i < 3; i++)
		if (fabs(c->v[i]) < 1e-12)
			c->v[i] = 0;
	return 1;
}

int main(int argc, char **argv)
{
	struct options o;
	parse_options(argc, argv, &o);
	struct ctx c;
	memset(&c, 0, sizeof c);
	struct opt_value val[sizeof spec / sizeof spec[0]];
	plot_begin(&c.s, &(struct plot_settings){
		.toplabel = "3D Line Plot", .xlabel = "X-Axis", .ylabel = "Y-Axis",
		.zlabel = "Z-Axis", .equalscale = 1, .postscript = 1, .line = 1,
		.scale = 1.0, .xticks = 2, .yticks = 2, .zticks = 2,
	}, spec, val, &o.cmd);
	const struct opt_value *v;
	c.hidden = o.hidden || ((v = plot_opt(spec, val, "hiddenline")) && v->num);
	c.nosort = o.nosort || ((v = plot_opt(spec, val, "nosort")) && v->num);
	c.unequal = o.unequal || !c.s.equalscale;
	c.zs = o.zs;
	c.walls = o.walls;
	c.shade = o.shade;
	c.raster = o.raster;
	c.haswin = o.haswin;
	memcpy(c.win, o.win, sizeof c.win);
	if ((c.walls || c.shade || c.raster) && !c.hidden)
		die_status(EXIT_USAGE, "-walls, -shade, -raster and -vector go with a hidden-line plot: add -h");
	if (o.times)            /* one time per page */
		c.ntimes = plot_parse_times(o.times, &c.times);
	memcpy(c.v0, o.has_v ? o.v : DEFAULT_VIEW, sizeof c.v0);
	memcpy(c.v, c.v0, sizeof c.v);

	if (c.hidden && !c.nosort)
		plot_budget(o.nfiles, o.files, B_HIDDEN, T_HIDDEN);
	else
		plot_budget(o.nfiles, o.files, B_LINES, T_LINES);
	struct plot_file **pf = xcalloc((size_t)o.nfiles, sizeof *pf);
	for (int i = 0; i < o.nfiles; i++) {
		pf[i] = fmt_plot_read(o.files[i], 3);
		c.sets = xreallocarray(c.sets, (size_t)(c.nsets + pf[i]->nsets), sizeof *c.sets);
		for (int s = 0; s < pf[i]->nsets; s++)
			c.sets[c.nsets++] = &pf[i]->sets[s];
	}

	struct plot_file *winpf = NULL;
	if (c.haswin == 2 && c.nsets > 0)
		auto_window(&c);
	if (c.haswin) {         /* the sets cut to the window replace the sets read */
		winpf = plot_window_sets(c.sets, c.nsets, c.win);
		for (int s = 0; s < c.nsets; s++)
			c.sets[s] = &winpf->sets[s];
	}
	/* the first file that carries labels gives the default ones */
	for (int i = 0; i < o.nfiles; i++)
		if (!fmt_labels_empty(&pf[i]->labels)) {
			plot_settings_labels(&c.s, &pf[i]->labels, spec, val, &o.cmd);
			break;
		}
	plot_output(&c.s, &o.cmd, render, key, &c);

	for (int i = 0; i < o.nfiles; i++)
		fmt_plot_free(pf[i]);
	free(pf);
	if (winpf)
		fmt_plot_free(winpf);
	free(c.sets);
	free(c.times);
	fmt_options_free(spec, val);
	free(o.files);
	return 0;
}
