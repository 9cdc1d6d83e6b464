/*
 * cut.c - a splat input cut into tiles (stitch -cut).
 *
 * The layout's grid (its window and grid statement: a step d) is the
 * unit: every core is a whole number of steps, the last of a row taking
 * what is left, and the halo is rounded up to whole steps, so each
 * tile's image grid is the layout's grid and the tiles' images join
 * point for point.  splat images a window as one period of a periodic
 * mask (splat(5)); a tile's halo past the layout's edge therefore holds
 * the layout's other side, so that the tiles join into the image of the
 * untiled run.  A tile is written in its own coordinates, its window
 * from (0, 0), its shapes clipped to it and rounded to TILE_ROUND_UM:
 * tiles of the same content (the cells of a periodic array) are the same
 * file, byte for byte, and a driver simulates them once.
 */
#include "checked.h"
#include "fmt_splat.h"
#include "num.h"
#include "poly.h"
#include "stitch.h"
#include "util.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Shape coordinates in a tile are rounded to this (um): a picometre, far
 * below any layout's database unit, far above the rounding of the shift
 * to the tile's origin. */
#define TILE_ROUND_UM 1e-6
/* The default halo, in optical radii lambda / NA: the image of an edge
 * has settled to well under 1e-3 of its step there (stitch(1)). */
#define HALO_RADII 3.0
/* Most tiles of one cut. */
enum { TILE_MAX = 10000 };

static double rnd(double v)
{
	return nearbyint(v / TILE_ROUND_UM) * TILE_ROUND_UM + 0.0;
}

struct cutter {
	const struct splat_input *in;
	double d;               /* the grid step, um */
	long nsx, nsy;          /* the layout's steps in x and y */
	double win[4];          /* the tile's window, layout coordinates */
	double org[2];          /* the tile's origin, layout coordinates */
	struct splat_rect *rects;
	int nrects;
	size_t rcap;
	struct splat_layer *layers;
	int nlayers;
	size_t lcap;
};

/* The copies of rect r shifted by whole periods that meet the window. */
static void cut_rect(struct cutter *c, const struct splat_rect *r, long kmax)
{
	const struct splat_mask *m = &c->in->mask;
	double px = m->xmax - m->xmin, py = m->ymax - m->ymin;
	for (long ky = -kmax; ky <= kmax; ky++)
		for (long kx = -kmax; kx <= kmax; kx++) {
			double x1 = fmax(r->x1 + kx * px, c->win[0]), x2 = fmin(r->x2 + kx * px, c->win[1]);
			double y1 = fmax(r->y1 + ky * py, c->win[2]), y2 = fmin(r->y2 + ky * py, c->win[3]);
			x1 = rnd(x1 - c->org[0]), x2 = rnd(x2 - c->org[0]);
			y1 = rnd(y1 - c->org[1]), y2 = rnd(y2 - c->org[1]);
			if (!(x1 < x2 && y1 < y2))
				continue;
			xgrow(&c->rects, &c->rcap, (size_t)c->nrects + 1, sizeof *c->rects);
			struct splat_rect *o = &c->rects[c->nrects++];
			*o = *r;
			o->x1 = x1, o->x2 = x2, o->y1 = y1, o->y2 = y2;
		}
}

/* The polygons of layer l shifted by whole periods, clipped to the
 * window: one polygon statement each (the same paint, so their union is
 * the layer's). */
static void cut_layer(struct cutter *c, const struct splat_layer *l, long kmax)
{
	const struct splat_mask *m = &c->in->mask;
	double px = m->xmax - m->xmin, py = m->ymax - m->ymin;
	for (int i = 0; i < l->shapes.n; i++) {
		int nv = poly_set_nv(&l->shapes, i);
		const double *xy = poly_set_xy(&l->shapes, i);
		double *s = xreallocarray(NULL, 2 * (size_t)nv, sizeof *s);
		for (long ky = -kmax; ky <= kmax; ky++)
			for (long kx = -kmax; kx <= kmax; kx++) {
				for (int v = 0; v < nv; v++) {
					s[2 * v] = xy[2 * v] + kx * px;
					s[2 * v + 1] = xy[2 * v + 1] + ky * py;
				}
				double *out;
				int n = poly_clip_rect(s, nv, c->win[0], c->win[1], c->win[2], c->win[3], &out);
				for (int v = 0; v < n; v++) {
					out[2 * v] = rnd(out[2 * v] - c->org[0]);
					out[2 * v + 1] = rnd(out[2 * v + 1] - c->org[1]);
				}
				if (n >= 3)
					n = poly_dedup(out, n);
				if (n < 3 || fabs(poly_area(out, n)) <= 0) {
					free(out);
					continue;
				}
				xgrow(&c->layers, &c->lcap, (size_t)c->nlayers + 1, sizeof *c->layers);
				struct splat_layer *o = &c->layers[c->nlayers++];
				memset(o, 0, sizeof *o);
				o->t = l->t, o->phase = l->phase, o->line = l->line;
				o->after = c->nrects;
				o->pxy = out;
				o->pn = n;
			}
		free(s);
	}
}

/* Rects painted alike, one after another, in the order of their place:
 * the order among them changes nothing, and the same content in two
 * tiles gives the same file. */
static int cmp_rect(const void *pa, const void *pb)
{
	const struct splat_rect *a = pa, *b = pb;
	double ka[4] = {a->y1, a->x1, a->y2, a->x2}, kb[4] = {b->y1, b->x1, b->y2, b->x2};
	for (int k = 0; k < 4; k++)
		if (ka[k] != kb[k])
			return ka[k] < kb[k] ? -1 : 1;
	return 0;
}

/* Polygon statements painted alike over the same rects, in the order of
 * their place (lowest vertex, then vertex by vertex), as the rects. */
static int cmp_layer(const void *pa, const void *pb)
{
	const struct splat_layer *a = pa, *b = pb;
	double ka[2] = {INFINITY, INFINITY}, kb[2] = {INFINITY, INFINITY};
	for (int v = 0; v < a->pn; v++)
		if (a->pxy[2 * v + 1] < ka[0] || (a->pxy[2 * v + 1] == ka[0] && a->pxy[2 * v] < ka[1]))
			ka[0] = a->pxy[2 * v + 1], ka[1] = a->pxy[2 * v];
	for (int v = 0; v < b->pn; v++)
		if (b->pxy[2 * v + 1] < kb[0] || (b->pxy[2 * v + 1] == kb[0] && b->pxy[2 * v] < kb[1]))
			kb[0] = b->pxy[2 * v + 1], kb[1] = b->pxy[2 * v];
	for (int k = 0; k < 2; k++)
		if (ka[k] != kb[k])
			return ka[k] < kb[k] ? -1 : 1;
	if (a->pn != b->pn)
		return a->pn - b->pn;
	for (int v = 0; v < 2 * a->pn; v++)
		if (a->pxy[v] != b->pxy[v])
			return a->pxy[v] < b->pxy[v] ? -1 : 1;
	return 0;
}

static void sort_layers(struct cutter *c)
{
	for (int i = 0; i < c->nlayers;) {
		const struct splat_layer *l = &c->layers[i];
		int j = i + 1;
		while (j < c->nlayers && c->layers[j].after == l->after && c->layers[j].t == l->t &&
		       c->layers[j].phase == l->phase)
			j++;
		if (j - i > 1)
			qsort(c->layers + i, (size_t)(j - i), sizeof *c->layers, cmp_layer);
		i = j;
	}
}

/* Writes the tile of steps [i0, i1) x [j0, j1) with a halo of h steps. */
static void write_tile(struct cutter *c, const char *path, long i0, long i1, long j0, long j1,
		       long h)
{
	const struct splat_input *in = c->in;
	const struct splat_mask *m = &in->mask;
	c->win[0] = m->xmin + (i0 - h) * c->d, c->win[1] = m->xmin + (i1 + h) * c->d;
	c->win[2] = m->ymin + (j0 - h) * c->d, c->win[3] = m->ymin + (j1 + h) * c->d;
	c->org[0] = c->win[0], c->org[1] = c->win[2];
	c->nrects = c->nlayers = 0;
	long kmax = h / (c->nsx < c->nsy ? c->nsx : c->nsy) + 1;
	int nl = 0, run = 0;
	for (int r = 0; r <= m->nrects; r++) {
		int brk = r == m->nrects || (nl < m->nlayers && m->layers[nl].after == r) ||
			  (r > 0 && (m->rects[r].t != m->rects[r - 1].t ||
				     m->rects[r].phase != m->rects[r - 1].phase));
		if (brk) {
			if (c->nrects - run > 1)	/* qsort takes no null array */
				qsort(c->rects + run, (size_t)(c->nrects - run), sizeof *c->rects, cmp_rect);
			run = c->nrects;
		}
		for (; nl < m->nlayers && m->layers[nl].after == r; nl++)
			cut_layer(c, &m->layers[nl], kmax);
		if (r < m->nrects)
			cut_rect(c, &m->rects[r], kmax);
	}
	sort_layers(c);
	struct splat_input t = *in;
	t.mask.xmin = 0, t.mask.xmax = (double)(i1 - i0 + 2 * h) * c->d;
	t.mask.ymin = 0, t.mask.ymax = (double)(j1 - j0 + 2 * h) * c->d;
	t.mask.rects = c->rects, t.mask.nrects = c->nrects;
	t.mask.layers = c->layers, t.mask.nlayers = c->nlayers;
	t.nx = ck_int((double)(i1 - i0 + 2 * h + 1), 2, SPLAT_MAX_GRID, "the tile's grid");
	t.ny = ck_int((double)(j1 - j0 + 2 * h + 1), 2, SPLAT_MAX_GRID, "the tile's grid");
	t.contour = "image.cont";
	t.ncutlines = 0, t.cutlines = NULL;
	t.clip = 1, t.window_auto = 0;
	fmt_splat_write(path, &t);
	for (int k = 0; k < c->nlayers; k++)
		free(c->layers[k].pxy);
}

static void print_tile(const char *name, const struct cutter *c, long h, double x0, double x1,
		       double y0, double y1)
{
	char b[NUM_BUFSZ];
	fputs(name, stdout);
	double v[6] = {c->org[0], c->org[1], x0, x1, y0, y1};
	(void)h;
	for (int k = 0; k < 6; k++) {
		num_fmt(b, v[k]);
		printf(" %s", b);
	}
	putchar('\n');
}

void stitch_cut(const char *input, double w, double h, const char *dir)
{
	struct splat_input *in = fmt_splat_read(input);
	const struct splat_mask *m = &in->mask;
	struct cutter c = {.in = in};
	c.nsx = in->nx - 1, c.nsy = in->ny - 1;
	c.d = (m->xmax - m->xmin) / c.nsx;
	double dy = (m->ymax - m->ymin) / c.nsy;
	if (fabs(dy - c.d) > 1e-9 * c.d)
		die("%s: the grid steps in x and y differ (%g and %g um): tiles need a square grid",
		    input, c.d, dy);
	if (in->planes)
		die("%s: an image stack (resist ... planes) cannot be tiled yet", input);
	if (h < 0)
		h = HALO_RADII * in->wavelength / in->na;
	long ws = ck_long(nearbyint(w / c.d), 0, SPLAT_MAX_GRID, "-tile in grid steps");
	long hs = ck_long(ceil(h / c.d - 1e-9), 0, SPLAT_MAX_GRID, "-halo in grid steps");
	if (ws < 1)
		die("-tile %g: under the grid step %g um of %s", w, c.d, input);
	long tx = (c.nsx + ws - 1) / ws, ty = (c.nsy + ws - 1) / ws;
	if ((double)tx * ty > TILE_MAX)
		die("-tile %g: %ld x %ld tiles, over %d", w, tx, ty, (int)TILE_MAX);
	if (mkdir(dir, 0777) != 0 && errno != EEXIST)
		die("%s: cannot make the directory:", dir);
	size_t len = strlen(dir) + 32;
	char *path = xmalloc(len);
	for (long j = 0; j < ty; j++)
		for (long i = 0; i < tx; i++) {
			long i0 = i * ws, i1 = i0 + ws < c.nsx ? i0 + ws : c.nsx;
			long j0 = j * ws, j1 = j0 + ws < c.nsy ? j0 + ws : c.nsy;
			char name[32];
			snprintf(name, sizeof name, "t%04ld.in", j * tx + i);
			snprintf(path, len, "%s/%s", dir, name);
			write_tile(&c, path, i0, i1, j0, j1, hs);
			print_tile(name, &c, hs, m->xmin + i0 * c.d, m->xmin + i1 * c.d,
				   m->ymin + j0 * c.d, m->ymin + j1 * c.d);
		}
	free(path);
	free(c.rects);
	free(c.layers);
	fmt_splat_free(in);
}
