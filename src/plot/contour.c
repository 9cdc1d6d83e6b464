/*
 * contour - contour plots of a contour-file (a z grid) or of a pdraw
 * triangle file (thesis Appendix B, contour(L)).
 *
 * Contours are found cell by cell: marching squares on the grid (the
 * saddle cells resolved by the cell-centre average), or the plane cut of
 * each triangle with -3D.  A crossing is interpolated linearly along its
 * grid edge, always from the same end of the edge, so the two cells
 * sharing an edge produce bit-identical points; segments are then joined
 * into curves by matching their end points exactly.  -j adds a thin
 * border layer at the highest or lowest z, which closes the curves along
 * the border as the guide describes.
 */
#include "args.h"
#include "draw.h"
#include "fmt_contour.h"
#include "fmt_options.h"
#include "fmt_plot.h"
#include "fmt_stack.h"
#include "num.h"
#include "plot_common.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

static const char usage_head[] =
	"usage: contour [-o options-file] [-Pprinter] [-s scale] [-c level] [-cstep step]\n"
	"               [-ex] [-g] [-j high|low] [-l] [-noplot] [-print] [-ps] [-old]\n"
	"               [-tl toplabel] [-xl xlabel] [-yl ylabel] [-svg file] [-3D [-big]]\n"
	"               [-map|-nomap] [-cutrow]\n"
	"               [X options] contour-file\n"
	"  -c level         only the contours at level, also written to image.cont\n"
	"  -cstep step      contour step (else asked at a terminal, else ~10 round levels)\n"
	"  -ex              write the triangle mesh to contour-file.3D\n"
	"  -g               draw a grid\n"
	"  -j high|low      join curves along the border (border at max or min z)\n"
	"  -l               no contour labels\n"
	"  -map             the image as a grey-scale map (black low, white high) under\n"
	"                   its contours, with a scale bar, and no contour labels (the\n"
	"                   default when a page has more than 100 contour curves: an\n"
	"                   array of features)\n"
	"  -nomap           contours and labels however many curves there are\n"
	"  -cutrow          print the y (um) of the grid row whose values vary most\n"
	"                   (of equals the one nearest the middle) and draw nothing:\n"
	"                   a cross-section there runs through a row of features\n"
	"  -old             old 50x50 contour-file format\n"
	"  -3D              the input is a pdraw file of triangles\n"
	"  -big             with -3D: read a file whose estimated memory or time (from\n"
	"                   its size) is beyond the limits (also SAMPLE3D_BIG=1)\n";

static const struct opt_spec spec[] = {
	PLOT_OPT_COMMON, PLOT_OPT_ONOFF("grid"), PLOT_OPT_ONOFF("contlabel"),
	{"joinlevel", OPT_WORD, 0, 0, "high|low"}, {"linetypes", OPT_INT, 1, 3, NULL},
	/* not in the guide's list: the step, so scripts need not pass -cstep */
	{"cstep", OPT_NUM, 0, 1e300, NULL},
	{NULL, 0, 0, 0, NULL}
};

/* At most this many levels: more would be a step far too small for a
 * readable plot (and a slow one). */
#define MAX_LEVELS 1000
/* -j: the border layer sits this fraction of a cell outside the grid, so
 * the joining pieces run along the border. */
#define JOIN_GAP 1e-3
#define LABEL_FONT 8.0

struct options {
	struct plot_cmd cmd;
	double level, cstep;
	int has_level, has_cstep, ex, grid, nolabel, old, tri;
	int map;                /* -map 1, -nomap -1, else 0 (by the curve count) */
	int cutrow;             /* -cutrow */
	const char *join;
	const char *input;
};

struct seg { double p[4]; };

struct curve {
	int level;              /* index into levels */
	int npts;
	double *xy;
};

struct page {
	char *label;            /* top label of an image stack's page, or NULL */
	const struct contour *grid;     /* the page's image, NULL for -3D */
	double bounds[4];
	int ncurves;
	struct curve *c;
};

struct ctx {
	struct plot_settings s;
	int contlabel, linetypes;
	int map;                /* as in struct options */
	double zmin, zmax;      /* over every page: one grey scale for all */
	int nlevels;
	double *levels;
	int npages;
	struct page *pages;
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
		if (args_num(&a, "-c", -1e300, 1e300, &o->level)) o->has_level = 1;
		else if (args_num(&a, "-cstep", 1e-300, 1e300, &o->cstep)) o->has_cstep = 1;
		else if (args_flag(&a, "-ex")) o->ex = 1;
		else if (args_flag(&a, "-g")) o->grid = 1;
		else if (args_str(&a, "-j", &o->join)) {
			if (o->join && strcasecmp(o->join, "high") != 0 && strcasecmp(o->join, "low") != 0)
				args_error(&a, "option -j: expected high or low, found \"%.40s\"", o->join);
		}
		else if (args_flag(&a, "-l")) o->nolabel = 1;
		else if (args_flag(&a, "-map")) o->map = 1;
		else if (args_flag(&a, "-nomap")) o->map = -1;
		else if (args_flag(&a, "-cutrow")) o->cutrow = 1;
		else if (args_flag(&a, "-old")) o->old = 1;
		else if (args_flag(&a, "-3D") || args_flag(&a, "-3d")) o->tri = 1;
		else if (plot_cmd_arg(&a, &o->cmd, PC_XDISPLAY | PC_BIG)) ;
		else args_operand(&a, (const char **[]){&o->input}, 1, "contour-file");
	}
	if (!o->input)
		args_error(&a, "no contour-file");
	if (o->tri && (o->old || o->ex || o->join))
		args_error(&a, "-3D cannot be combined with -old, -ex or -j");
	args_done(&a, NULL);
}

/* ---- segments ---- */

struct segs { struct seg *s; size_t n, cap; };

static void add_seg(struct segs *sg, double x0, double y0, double x1, double y1)
{
	/* a node exactly at the level gives zero-length pieces: they carry
	 * nothing and would confuse the joining of end points */
	if (x0 == x1 && y0 == y1)
		return;
	xgrow(&sg->s, &sg->cap, sg->n + 1, sizeof *sg->s);
	sg->s[sg->n++] = (struct seg){{x0, y0, x1, y1}};
}

/* Crossing of level on the edge a-b, interpolated from a (the caller
 * passes the edge's ends in a fixed order). */
static void cross(const double *a, const double *b, double level, double *x, double *y)
{
	double t = (level - a[2]) / (b[2] - a[2]);
	*x = a[0] + t * (b[0] - a[0]);
	*y = a[1] + t * (b[1] - a[1]);
}

/* Marching squares on a grid with node coordinates xs[nx], ys[ny]. */
static void grid_segments(const double *z, const double *xs, const double *ys,
			  int nx, int ny, double level, struct segs *sg)
{
	for (int j = 0; j + 1 < ny; j++)
		for (int i = 0; i + 1 < nx; i++) {
			double v[4][3];
			static const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
			int up[4];
			for (int k = 0; k < 4; k++) {
				v[k][0] = xs[i + di[k]];
				v[k][1] = ys[j + dj[k]];
				v[k][2] = z[(size_t)(j + dj[k]) * (size_t)nx + (size_t)(i + di[k])];
				up[k] = v[k][2] >= level;
			}
			/* edges e0 v0-v1, e1 v1-v2, e2 v3-v2, e3 v0-v3: each from its
			 * lower-indexed node, shared alike by both cells */
			static const int ea[4] = {0, 1, 3, 0}, eb[4] = {1, 2, 2, 3};
			double px[4], py[4];
			int hit[4], nhit = 0;
			for (int e = 0; e < 4; e++) {
				hit[e] = up[ea[e]] != up[eb[e]];
				if (hit[e]) {
					cross(v[ea[e]], v[eb[e]], level, &px[e], &py[e]);
					nhit++;
				}
			}
			if (nhit == 2) {
				int a = -1, b = -1;
				for (int e = 0; e < 4; e++)
					if (hit[e]) {
						if (a < 0) a = e; else b = e;
					}
				add_seg(sg, px[a], py[a], px[b], py[b]);
			} else if (nhit == 4) {
				/* saddle: the centre value says which corners connect */
				double c = (v[0][2] + v[1][2] + v[2][2] + v[3][2]) / 4;
				if ((c >= level) == up[0]) {
					add_seg(sg, px[0], py[0], px[1], py[1]);
					add_seg(sg, px[2], py[2], px[3], py[3]);
				} else {
					add_seg(sg, px[3], py[3], px[0], py[0]);
					add_seg(sg, px[1], py[1], px[2], py[2]);
				}
			}
		}
}

static int vless(const double *a, const double *b)
{
	for (int k = 0; k < 3; k++)
		if (a[k] != b[k])
			return a[k] < b[k];
	return 0;
}

/* The plane z = level cut through one triangle. */
static void tri_segments(const double *t, double level, struct segs *sg)
{
	double px[3], py[3];
	int n = 0;
	for (int e = 0; e < 3 && n < 3; e++) {
		const double *a = t + 3 * e, *b = t + 3 * ((e + 1) % 3);
		if ((a[2] >= level) == (b[2] >= level))
			continue;
		if (vless(b, a)) {
			const double *s = a; a = b; b = s;
		}
		cross(a, b, level, &px[n], &py[n]);
		n++;
	}
	if (n == 2)
		add_seg(sg, px[0], py[0], px[1], py[1]);
}

/* ---- joining segments into curves ---- */

static const struct seg *sort_segs;
static int cmp_end(const void *pa, const void *pb)
{
	long a = *(const long *)pa, b = *(const long *)pb;
	const double *p = sort_segs[a >> 1].p + 2 * (a & 1), *q = sort_segs[b >> 1].p + 2 * (b & 1);
	if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
	if (p[1] != q[1]) return p[1] < q[1] ? -1 : 1;
	return a < b ? -1 : a > b;
}

static void chain(const struct segs *sg, int level, struct page *pg, size_t *cap)
{
	size_t n = sg->n;
	if (!n)
		return;
	long *ord = xreallocarray(NULL, 2 * n, sizeof *ord);
	long *partner = xreallocarray(NULL, 2 * n, sizeof *partner);
	char *used = xcalloc(n, 1);
	for (size_t k = 0; k < 2 * n; k++)
		ord[k] = (long)k, partner[k] = -1;
	sort_segs = sg->s;
	qsort(ord, 2 * n, sizeof *ord, cmp_end);
	/* equal end points pair up two by two */
	for (size_t k = 0; k + 1 < 2 * n; k++) {
		const double *p = sg->s[ord[k] >> 1].p + 2 * (ord[k] & 1);
		const double *q = sg->s[ord[k + 1] >> 1].p + 2 * (ord[k + 1] & 1);
		if (p[0] == q[0] && p[1] == q[1] && (ord[k] >> 1) != (ord[k + 1] >> 1)) {
			partner[ord[k]] = ord[k + 1];
			partner[ord[k + 1]] = ord[k];
			k++;
		}
	}
	double *xy = xreallocarray(NULL, n + 1, 2 * sizeof *xy);
	for (int pass = 0; pass < 2; pass++)
		for (size_t s0 = 0; s0 < n; s0++) {
			if (used[s0])
				continue;
			/* open curves first, started at a free end; then loops */
			int e0;
			if (partner[2 * s0] < 0) e0 = 0;
			else if (partner[2 * s0 + 1] < 0) e0 = 1;
			else if (pass == 1) e0 = 0;
			else continue;
			int np = 0;
			long s = (long)s0, ein = e0;
			xy[np * 2] = sg->s[s].p[2 * ein], xy[np * 2 + 1] = sg->s[s].p[2 * ein + 1];
			np++;
			for (;;) {
				used[s] = 1;
				long eout = 1 - ein;
				xy[np * 2] = sg->s[s].p[2 * eout], xy[np * 2 + 1] = sg->s[s].p[2 * eout + 1];
				np++;
				long nx = partner[2 * s + eout];
				if (nx < 0 || used[nx >> 1])
					break;
				s = nx >> 1, ein = nx & 1;
			}
			xgrow(&pg->c, cap, (size_t)pg->ncurves + 1, sizeof *pg->c);
			struct curve *cv = &pg->c[pg->ncurves++];
			cv->level = level;
			cv->npts = np;
			cv->xy = xreallocarray(NULL, (size_t)np, 2 * sizeof *cv->xy);
			memcpy(cv->xy, xy, (size_t)np * 2 * sizeof *xy);
		}
	free(xy);
	free(used);
	free(partner);
	free(ord);
}

/* ---- levels ---- */

static double ask_step(double zmin, double zmax)
{
	char buf[128];
	char a[NUM_BUFSZ], b[NUM_BUFSZ];
	fprintf(stderr, "zmin = %s, zmax = %s\ncontour step-size? ",
		num_fmt(a, zmin), num_fmt(b, zmax));
	fflush(stderr);
	if (!fgets(buf, sizeof buf, stdin))
		return 0;
	buf[strcspn(buf, "\r\n")] = '\0';
	double v;
	if (buf[0] == '\0')
		return 0;
	if (!num_parse(buf, &v) || !(v > 0))
		die("-: expected a positive contour step, found \"%.40s\"", buf);
	return v;
}

static int make_levels(double zmin, double zmax, double step, double **out)
{
	double a = ceil(zmin / step), b = floor(zmax / step);
	/* %.3g: a step of 1e-300 gives a count of 300 digits (or none) */
	if (!(b - a + 1 <= MAX_LEVELS))
		die("contour step %g gives %.3g levels between %g and %g (at most %d)",
		    step, b - a + 1, zmin, zmax, MAX_LEVELS);
	double *lv = xreallocarray(NULL, (size_t)(b - a + 2 > 1 ? b - a + 2 : 1), sizeof *lv);
	int n = 0, count = b >= a ? (int)(b - a + 1) : 0;
	/* counted in integers: past 2^53, k + 1 == k and a loop on k never
	 * ends (a step of 1e-300 on a flat image) */
	for (int i = 0; i < count; i++) {
		double v = (a + i) * step;
		/* a level at the extreme z only touches points */
		if (v > zmin && v < zmax)
			lv[n++] = v;
	}
	*out = lv;
	return n;
}

/* ---- drawing ---- */

/* The label boxes placed on a page, so that no label is drawn over
 * another: a curve whose every candidate place is taken goes without. */
struct placed {
	int n, cap;
	double *box;            /* x0 y0 x1 y1 each */
};

/* A label of value v at one of a curve's candidate points (its middle,
 * then its quarters, eighths, ...) whose box is free and inside the
 * frame; returns whether one was drawn. */
static int label_curve(struct draw *d, const struct plot_frame *f, struct placed *pl,
		       const struct curve *cv, double v)
{
	static const double at[] = {0.5, 0.25, 0.75, 0.125, 0.875, 0.375, 0.625};
	char buf[32];
	snprintf(buf, sizeof buf, "%.4g", v);
	double w = strlen(buf) * LABEL_FONT * 0.55 + 2, h = LABEL_FONT * 0.9;
	for (size_t t = 0; t < sizeof at / sizeof at[0]; t++) {
		int m = (int)(at[t] * (cv->npts - 1));
		double x, y;
		if (!plot_frame_map(f, cv->xy[2 * m], cv->xy[2 * m + 1], &x, &y))
			continue;
		double b[4] = {x - w / 2, y - h / 2, x + w / 2, y + h / 2};
		if (b[0] < f->x0 || b[2] > f->x1 || b[1] < f->y0 || b[3] > f->y1)
			continue;
		int free_place = 1;
		for (int i = 0; i < pl->n && free_place; i++) {
			const double *o = pl->box + 4 * i;
			free_place = !(b[0] < o[2] && o[0] < b[2] && b[1] < o[3] && o[1] < b[3]);
		}
		if (!free_place)
			continue;
		if (pl->n == pl->cap) {
			pl->cap = pl->cap ? 2 * pl->cap : 64;
			pl->box = xreallocarray(pl->box, (size_t)pl->cap, 4 * sizeof *pl->box);
		}
		memcpy(pl->box + 4 * pl->n++, b, sizeof b);
		double box[8] = {b[0], b[1], b[2], b[1], b[2], b[3], b[0], b[3]};
		draw_polygon(d, 4, box, 1.0, 0);
		draw_text(d, x, y, LABEL_FONT, 0, DRAW_CENTER, DRAW_MIDDLE, buf);
		return 1;
	}
	return 0;
}

/* -map: more curves than this on a page (an array of features, each with
 * its rings) are drawn as a grey-scale map instead of labelled contours. */
#define MAP_CURVES 100
/* -map: the map's pixels at most this many a side (a finer grid is
 * sampled at the nearest point), and the scale bar's size (points). */
#define MAP_PIXELS 1000
#define BAR_W 200.0
#define BAR_H 10.0
#define BAR_FONT 10.0   /* the size of the axes' tick labels */

/* The grey of value v on the page's scale: black at zmin, white at zmax. */
static unsigned char map_gray(const struct ctx *c, double v)
{
	double t = c->zmax > c->zmin ? (v - c->zmin) / (c->zmax - c->zmin) : 1;
	return (unsigned char)lround(255 * (t < 0 ? 0 : t > 1 ? 1 : t));
}

/* The image as a grey map over the frame (each grid point a pixel, cells
 * centred on the points) and, under the x label, its scale bar with round
 * ticks. */
static void draw_map(struct draw *d, const struct ctx *c, const struct plot_frame *f,
		     const struct contour *g)
{
	int cols = g->nx < MAP_PIXELS ? g->nx : MAP_PIXELS;
	int rows = g->ny < MAP_PIXELS ? g->ny : MAP_PIXELS;
	unsigned char *px = xmalloc((size_t)cols * (size_t)rows);
	for (int j = 0; j < rows; j++)
		for (int i = 0; i < cols; i++) {
			int gi = cols > 1 ? (int)lround((double)i * (g->nx - 1) / (cols - 1)) : 0;
			int gj = rows > 1 ? (int)lround((double)(rows - 1 - j) * (g->ny - 1) / (rows - 1)) : 0;
			px[(size_t)j * cols + i] = map_gray(c, g->z[(size_t)gj * g->nx + gi]);
		}
	double hx = g->nx > 1 ? (g->xmax - g->xmin) / (cols - 1) / 2 : 0;
	double hy = g->ny > 1 ? (g->ymax - g->ymin) / (rows - 1) / 2 : 0;
	double x0, y0, x1, y1;
	plot_frame_map(f, g->xmin - hx, g->ymin - hy, &x0, &y0);
	plot_frame_map(f, g->xmax + hx, g->ymax + hy, &x1, &y1);
	draw_image(d, x0, y0, x1, y1, cols, rows, px);
	free(px);
}

static void draw_scale_bar(struct draw *d, const struct ctx *c, const struct plot_frame *f)
{
	enum { STEPS = 64 };
	unsigned char ramp[STEPS];
	for (int i = 0; i < STEPS; i++)
		ramp[i] = map_gray(c, c->zmin + (c->zmax - c->zmin) * i / (STEPS - 1));
	double cx = (f->x0 + f->x1) / 2, y0 = f->y0 - 62;
	draw_image(d, cx - BAR_W / 2, y0, cx + BAR_W / 2, y0 + BAR_H, STEPS, 1, ramp);
	double box[8] = {cx - BAR_W / 2, y0, cx + BAR_W / 2, y0, cx + BAR_W / 2, y0 + BAR_H,
			 cx - BAR_W / 2, y0 + BAR_H};
	draw_set_line(d, 1, 0.5);
	draw_polygon(d, 4, box, DRAW_NOFILL, 1);
	struct plot_axis ax;
	plot_axis_linear(&ax, c->zmin, c->zmax, 4, 0);
	for (int k = 0; k < ax.nticks; k++) {
		double x = cx - BAR_W / 2 + BAR_W * (ax.tick[k] - ax.lo) / (ax.hi - ax.lo);
		draw_segment(d, x, y0, x, y0 - 3);
		draw_text(d, x, y0 - 4, BAR_FONT, 0, DRAW_CENTER, DRAW_TOP, ax.label[k]);
	}
}

static struct draw *render(void *vc)
{
	const struct ctx *c = vc;
	static const int lts[3] = {1, 2, 3};
	struct draw *d = plot_new_page(0);
	for (int pi = 0; pi < c->npages; pi++) {
		const struct page *pg = &c->pages[pi];
		if (pi)
			draw_page(d);
		struct plot_axis xa, ya;
		plot_axis_linear(&xa, pg->bounds[0], pg->bounds[1], c->s.xticks, 0);
		plot_axis_linear(&ya, pg->bounds[2], pg->bounds[3], c->s.yticks, 0);
		struct plot_frame f = {0, 0, 0, 0, &xa, &ya};
		plot_frame_place(&f, d, c->s.equalscale);
		int map = pg->grid && (c->map > 0 || (c->map == 0 && pg->ncurves > MAP_CURVES));
		draw_clip(d, f.x0, f.y0, f.x1, f.y1);
		if (map)
			draw_map(d, c, &f, pg->grid);
		/* the many curves of a map's page would hide it: the map alone */
		for (int i = 0; i < pg->ncurves && !(map && pg->ncurves > MAP_CURVES); i++) {
			const struct curve *cv = &pg->c[i];
			double *xy = xreallocarray(NULL, (size_t)cv->npts, 2 * sizeof *xy);
			for (int k = 0; k < cv->npts; k++)
				plot_frame_map(&f, cv->xy[2 * k], cv->xy[2 * k + 1], &xy[2 * k], &xy[2 * k + 1]);
			draw_set_line(d, lts[cv->level % c->linetypes], 0.8);
			draw_polyline(d, cv->npts, xy);
			free(xy);
		}
		if (c->contlabel && !map) {
			struct placed pl = {0, 0, NULL};
			draw_set_line(d, 1, 0.8);
			for (int i = 0; i < pg->ncurves; i++) {
				const struct curve *cv = &pg->c[i];
				if (cv->npts >= 4)      /* else too short to carry a label */
					label_curve(d, &f, &pl, cv, c->levels[cv->level]);
			}
			free(pl.box);
		}
		draw_unclip(d);
		plot_frame_draw(d, &f, c->s.grid, pg->label ? pg->label : c->s.toplabel,
				c->s.xlabel, c->s.ylabel);
		if (map)
			draw_scale_bar(d, c, &f);
	}
	return d;
}

/* -cutrow: rows whose variances differ by less than this fraction are
 * equals (the rows of a periodic array differ by rounding) */
#define CUTROW_SAME 1e-6

/* -cutrow: the y of the row of g with the largest variance of its values,
 * the rows visited from the middle outwards so that of equals the middle
 * one wins. */
static double cut_row(const struct contour *g)
{
	int best = g->ny / 2;
	double bestvar = -1;
	for (int k = 0; k < g->ny; k++) {
		/* middle, one above, one below, two above, ... */
		int j = g->ny / 2 + (k % 2 ? (k + 1) / 2 : -(k / 2));
		if (j < 0 || j >= g->ny)
			continue;
		const double *z = g->z + (size_t)j * g->nx;
		double mean = 0, var = 0;
		for (int i = 0; i < g->nx; i++)
			mean += z[i] / g->nx;
		for (int i = 0; i < g->nx; i++)
			var += (z[i] - mean) * (z[i] - mean) / g->nx;
		if (var > bestvar * (1 + CUTROW_SAME) + 1e-300) {
			bestvar = var;
			best = j;
		}
	}
	return fmt_contour_y(g, best);
}

/* ---- inputs ---- */

/* -j: the grid grown by a border layer at z = border, JOIN_GAP of a cell
 * outside. */
static double *join_grid(const struct contour *g, double border, double **xs, double **ys)
{
	int nx = g->nx + 2, ny = g->ny + 2;
	double *z = xreallocarray(NULL, (size_t)nx * (size_t)ny, sizeof *z);
	*xs = xreallocarray(NULL, (size_t)nx, sizeof **xs);
	*ys = xreallocarray(NULL, (size_t)ny, sizeof **ys);
	double dx = (g->xmax - g->xmin) / (g->nx - 1), dy = (g->ymax - g->ymin) / (g->ny - 1);
	for (int i = 0; i < g->nx; i++)
		(*xs)[i + 1] = fmt_contour_x(g, i);
	for (int j = 0; j < g->ny; j++)
		(*ys)[j + 1] = fmt_contour_y(g, j);
	(*xs)[0] = g->xmin - JOIN_GAP * dx;
	(*xs)[nx - 1] = g->xmax + JOIN_GAP * dx;
	(*ys)[0] = g->ymin - JOIN_GAP * dy;
	(*ys)[ny - 1] = g->ymax + JOIN_GAP * dy;
	for (int j = 0; j < ny; j++)
		for (int i = 0; i < nx; i++) {
			int in = i > 0 && j > 0 && i < nx - 1 && j < ny - 1;
			z[(size_t)j * nx + i] = in ? g->z[(size_t)(j - 1) * g->nx + (i - 1)] : border;
		}
	return z;
}

static void write_mesh(const struct contour *g, const char *input)
{
	const char *base = strcmp(input, "-") == 0 ? "stdin" : input;
	char *name = xmalloc(strlen(base) + 4);
	sprintf(name, "%s.3D", base);
	double b[6] = {g->xmin, g->xmax, g->ymin, g->ymax, g->z[0], g->z[0]};
	size_t n = (size_t)g->nx * g->ny;
	for (size_t k = 0; k < n; k++) {
		if (g->z[k] < b[4]) b[4] = g->z[k];
		if (g->z[k] > b[5]) b[5] = g->z[k];
	}
	struct plot_writer *w = fmt_plot_open(name, 3);
	fmt_plot_begin_set(w, b, 2L * (g->nx - 1) * (g->ny - 1));
	for (int j = 0; j + 1 < g->ny; j++)
		for (int i = 0; i + 1 < g->nx; i++) {
			/* two triangles per cell, split along (i,j)-(i+1,j+1), each a
			 * closed 4-point curve as conv -t writes them */
			static const int ti[2][4] = {{0, 1, 1, 0}, {0, 1, 0, 0}};
			static const int tj[2][4] = {{0, 0, 1, 0}, {0, 1, 1, 0}};
			for (int t = 0; t < 2; t++) {
				double p[12];
				for (int k = 0; k < 4; k++) {
					int a = i + ti[t][k], c = j + tj[t][k];
					p[3 * k] = fmt_contour_x(g, a);
					p[3 * k + 1] = fmt_contour_y(g, c);
					p[3 * k + 2] = g->z[(size_t)c * g->nx + a];
				}
				fmt_plot_curve(w, 4, p);
			}
		}
	fmt_plot_close(w);
	free(name);
}

/* A curve of a -3D file must be a triangle: 3 points, or 4 with the
 * first repeated. */
static void check_triangle(const char *path, const struct plot_file *pf, int si, int ci,
			   long line)
{
	const struct plot_curve *cv = &pf->sets[si].curves[ci];
	int ok = cv->npts == 3 ||
		 (cv->npts == 4 && cv->p[0] == cv->p[9] && cv->p[1] == cv->p[10] &&
		  cv->p[2] == cv->p[11]);
	if (!ok)
		die("%s:%ld: curve %d of set %d is not a triangle (3 points, or 4 "
		    "closing on the first)", path, line, ci + 1, si + 1);
}

/* A -3D input: the triangles (each checked) and their z range. */
static struct plot_file *read_triangles(const char *input, double *zmin, double *zmax)
{
	/* the estimate (plot_budget), measured on a 401 x 401 grid as
	 * triangles (3.8 M numbers, 47 MB): 84 MB; one core's time on grids
	 * of 501^2 and 1001^2 (8.8 M and 41 M numbers): 0.05 to 0.06 us a
	 * number (tests/bench/estimate.sh) */
	plot_budget(1, (char *const[]){(char *)input}, 24, 6e-8);
	struct plot_file *pf = fmt_plot_read(input, 3);
	long line = pf->first_line;     /* after any comment lines */
	for (int si = 0; si < pf->nsets; si++) {
		line += 2;
		for (int ci = 0; ci < pf->sets[si].ncurves; ci++) {
			check_triangle(input, pf, si, ci, line);
			line += 1 + pf->sets[si].curves[ci].npts;
			const struct plot_curve *cv = &pf->sets[si].curves[ci];
			for (int k = 0; k < cv->npts; k++) {
				*zmin = fmin(*zmin, cv->p[3 * k + 2]);
				*zmax = fmax(*zmax, cv->p[3 * k + 2]);
			}
		}
		line++;
	}
	return pf;
}

/* A contour-file or an image stack (*stk, else NULL), its first image
 * and the z range over every plane; -ex writes the mesh. */
static struct contour *read_grid(const struct options *o, struct image_stack **stk,
				 double *zmin, double *zmax)
{
	struct contour *g;
	*stk = NULL;
	if (o->old) {
		g = fmt_contour_read(o->input, 1);
	} else {
		*stk = fmt_stack_read(o->input);
		g = (*stk)->plane[0];
		if ((*stk)->is_stack && o->ex)
			die("%s: -ex writes the mesh of a single image, not of an image "
			    "stack", o->input);
	}
	/* one set of levels for every plane, so that pages compare */
	for (int pl = 0; pl < (*stk ? (*stk)->n : 1); pl++) {
		const struct contour *gp = *stk ? (*stk)->plane[pl] : g;
		size_t n = (size_t)gp->nx * gp->ny;
		for (size_t k = 0; k < n; k++) {
			*zmin = fmin(*zmin, gp->z[k]);
			*zmax = fmax(*zmax, gp->z[k]);
		}
	}
	if (o->ex)
		write_mesh(g, o->input);
	return g;
}

/* The contour curves of every level, page by page: a page per plane of
 * an image stack (titled by its depth), per set of a -3D file, else one.
 * join: "high" or "low" joins the curves along the border (join_grid). */
static void make_pages(struct ctx *c, const struct contour *g, const struct image_stack *stk,
		       const struct plot_file *pf, const char *join, double zmin, double zmax)
{
	c->npages = pf ? pf->nsets : stk ? stk->n : 1;
	c->pages = xcalloc((size_t)c->npages, sizeof *c->pages);
	struct segs sg = {NULL, 0, 0};
	for (int pi = 0; pi < c->npages; pi++) {
		struct page *pg = &c->pages[pi];
		size_t cap = 0;
		double *xs = NULL, *ys = NULL, *zz = NULL;
		const struct contour *gp = stk ? stk->plane[pi] : g;
		if (stk && stk->is_stack) {
			char dbuf[NUM_BUFSZ];
			const char *tl = c->s.toplabel ? c->s.toplabel : "";
			pg->label = xmalloc(strlen(tl) + NUM_BUFSZ + 32);
			sprintf(pg->label, "%s%sdepth %s um", tl, *tl ? ", " : "",
				num_fmt(dbuf, stk->depth[pi]));
		}
		pg->grid = gp;
		if (gp) {
			pg->bounds[0] = gp->xmin, pg->bounds[1] = gp->xmax;
			pg->bounds[2] = gp->ymin, pg->bounds[3] = gp->ymax;
			if (join) {
				zz = join_grid(gp, strcmp(join, "high") == 0 ? zmax : zmin, &xs, &ys);
			} else {
				xs = xreallocarray(NULL, (size_t)gp->nx, sizeof *xs);
				ys = xreallocarray(NULL, (size_t)gp->ny, sizeof *ys);
				for (int i = 0; i < gp->nx; i++) xs[i] = fmt_contour_x(gp, i);
				for (int j = 0; j < gp->ny; j++) ys[j] = fmt_contour_y(gp, j);
			}
		} else {
			memcpy(pg->bounds, pf->sets[pi].bounds, 4 * sizeof *pg->bounds);
		}
		for (int l = 0; l < c->nlevels; l++) {
			sg.n = 0;
			if (gp)
				grid_segments(zz ? zz : gp->z, xs, ys, gp->nx + (zz ? 2 : 0),
					      gp->ny + (zz ? 2 : 0), c->levels[l], &sg);
			else
				for (int ci = 0; ci < pf->sets[pi].ncurves; ci++)
					tri_segments(pf->sets[pi].curves[ci].p, c->levels[l], &sg);
			chain(&sg, l, pg, &cap);
		}
		free(xs);
		free(ys);
		free(zz);
	}
	free(sg.s);
}

/* image.cont: the single level of -c in the 2D plot format, its curves
 * in the input's x-y plane (its title, x and y labels). */
static void write_image_cont(const struct ctx *c, const struct plot_labels *lab)
{
	struct plot_file *out = fmt_plot_new(2);
	fmt_labels_set(&out->labels, lab->title, lab->axis[0], lab->axis[1], NULL);
	for (int pi = 0; pi < c->npages; pi++) {
		struct plot_set *st = fmt_plot_add_set(out, c->pages[pi].bounds);
		for (int i = 0; i < c->pages[pi].ncurves; i++)
			fmt_plot_add_curve(out, st, c->pages[pi].c[i].npts, c->pages[pi].c[i].xy);
	}
	fmt_plot_write("image.cont", out);
	fmt_plot_free(out);
}

int main(int argc, char **argv)
{
	struct options o;
	parse_options(argc, argv, &o);
	struct ctx c;
	memset(&c, 0, sizeof c);
	struct opt_value val[sizeof spec / sizeof spec[0]];
	plot_begin(&c.s, &(struct plot_settings){
		.toplabel = "CONTOUR PLOT", .xlabel = "X-AXIS", .ylabel = "Y-AXIS",
		.equalscale = 1, .postscript = 1, .line = 1, .scale = 1.0,
		.xticks = 4, .yticks = 4,
	}, spec, val, &o.cmd);
	const struct opt_value *v;
	c.contlabel = (v = plot_opt(spec, val, "contlabel")) ? (int)v->num : 1;
	if (o.nolabel)
		c.contlabel = 0;
	c.linetypes = (v = plot_opt(spec, val, "linetypes")) ? (int)v->num : 2;
	if (o.grid)
		c.s.grid = 1;
	const char *join = o.join;
	if (!join && (v = plot_opt(spec, val, "joinlevel")))
		join = v->str;
	double step = o.has_cstep ? o.cstep : 0;
	if (!o.has_cstep && (v = plot_opt(spec, val, "cstep")) && v->num > 0)
		step = v->num;

	struct contour *g = NULL;
	struct image_stack *stk = NULL; /* an image stack: one page per plane */
	struct plot_file *pf = NULL;
	double zmin = INFINITY, zmax = -INFINITY;
	if (o.tri)
		pf = read_triangles(o.input, &zmin, &zmax);
	else
		g = read_grid(&o, &stk, &zmin, &zmax);

	if (o.cutrow) {
		if (!g)
			die_status(EXIT_USAGE, "-cutrow reads a contour-file, not a -3D file");
		char f[NUM_BUFSZ];
		printf("%s\n", num_fmt(f, cut_row(g)));
		fshut(stdout, "stdout");
		if (stk)
			fmt_stack_free(stk);
		else
			fmt_contour_free(g);
		fmt_options_free(spec, val);
		return 0;
	}
	/* the labels the input carries are the defaults (contour.5) */
	const struct plot_labels *lab = pf ? &pf->labels : &g->labels;
	plot_settings_labels(&c.s, lab, spec, val, &o.cmd);

	if (o.has_level) {
		c.levels = xmalloc(sizeof *c.levels);
		c.levels[0] = o.level;
		c.nlevels = 1;
	} else {
		if (!(step > 0) && isatty(0))
			step = ask_step(zmin, zmax);
		if (!(step > 0))
			step = plot_nice_step(zmin, zmax, 10);
		c.nlevels = make_levels(zmin, zmax, step, &c.levels);
	}
	c.map = o.map;
	c.zmin = zmin, c.zmax = zmax;
	make_pages(&c, g, stk, pf, join, zmin, zmax);
	if (o.has_level)
		write_image_cont(&c, lab);

	plot_output(&c.s, &o.cmd, render, NULL, &c);

	for (int pi = 0; pi < c.npages; pi++) {
		for (int i = 0; i < c.pages[pi].ncurves; i++)
			free(c.pages[pi].c[i].xy);
		free(c.pages[pi].c);
		free(c.pages[pi].label);
	}
	free(c.pages);
	free(c.levels);
	if (stk)
		fmt_stack_free(stk);
	else
		fmt_contour_free(g);
	fmt_plot_free(pf);
	fmt_options_free(spec, val);
	return 0;
}
