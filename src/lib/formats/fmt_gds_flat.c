/*
 * fmt_gds_flat.c - the GDSII reader's flattening (see fmt_gds.h): the
 * cells' bounding boxes, the bottom-up counts that refuse a runaway
 * flattening before it starts, and the walk of the reference tree from the
 * chosen cell with the composed transform, culled by the window.
 */
#include "fmt_gds_int.h"
#include "budget.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- flattening ---- */

struct xform {
	double a, b, c, d, tx, ty;      /* x' = a x + b y + tx, y' = c x + d y + ty (dbu) */
	double mag, angle;              /* degrees */
	int reflect;
};

static void cos_sin(double deg, double *c, double *s)
{
	double q = deg / 90;
	if (q == floor(q) && fabs(q) < 1e9) {
		static const double cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
		long k = ((long)q % 4 + 4) % 4;
		*c = cs[k][0];
		*s = cs[k][1];
		return;
	}
	*c = cos(deg * (M_PI / 180));
	*s = sin(deg * (M_PI / 180));
}

/* The transform of a reference placed at (x, y) of the parent's frame. */
static struct xform compose(const struct xform *p, const struct elem *e, double x, double y)
{
	struct xform t;
	t.mag = e->absmag ? e->mag : p->mag * e->mag;
	t.angle = e->absang ? e->angle : p->angle + (p->reflect ? -e->angle : e->angle);
	t.reflect = p->reflect ^ e->reflect;
	double c, s;
	cos_sin(t.angle, &c, &s);
	double f = t.reflect ? -1 : 1;
	t.a = t.mag * c;
	t.b = -t.mag * s * f;
	t.c = t.mag * s;
	t.d = t.mag * c * f;
	t.tx = p->a * x + p->b * y + p->tx;
	t.ty = p->c * x + p->d * y + p->ty;
	return t;
}

static void apply(const struct xform *t, double x, double y, double *ox, double *oy)
{
	*ox = t->a * x + t->b * y + t->tx;
	*oy = t->c * x + t->d * y + t->ty;
}

struct flat {
	const struct gds_lib *g;
	int layer, datatype;
	int cull;
	double win[4];          /* dbu of the top frame */
	struct poly_set *out;
	long shapes;
	long visits;
};

static double to_um(const struct gds_lib *g, double v)
{
	return g->div ? v / (double)g->div : v * g->um;
}

static int box_misses(const struct flat *f, double x0, double x1, double y0, double y1)
{
	return f->cull && (x1 < f->win[0] || x0 > f->win[1] || y1 < f->win[2] || y0 > f->win[3]);
}

/* Adds polygon xy (n vertices, top-frame dbu) in micrometres. */
static void out_poly(struct flat *f, double *xy, int n)
{
	double x0 = xy[0], x1 = xy[0], y0 = xy[1], y1 = xy[1];
	for (int i = 1; i < n; i++) {
		x0 = fmin(x0, xy[2 * i]); x1 = fmax(x1, xy[2 * i]);
		y0 = fmin(y0, xy[2 * i + 1]); y1 = fmax(y1, xy[2 * i + 1]);
	}
	if (box_misses(f, x0, x1, y0, y1))
		return;
	for (int i = 0; i < 2 * n; i++)
		xy[i] = to_um(f->g, xy[i]);
	n = poly_dedup(xy, n);
	if (n >= 3)
		poly_set_add(f->out, xy, n);
}

static void shape(struct flat *f, const struct elem *e, const struct xform *t)
{
	struct gds_lib *g = (struct gds_lib *)f->g;
	const unsigned char *p = g->buf + e->xy;
	xgrow(&g->tmp, &g->tcap, 2 * (size_t)e->nxy + 2, sizeof *g->tmp);
	double *tmp = g->tmp;
	for (int i = 0; i < e->nxy; i++)
		apply(t, si32(p + 8 * i), si32(p + 8 * i + 4), &tmp[2 * i], &tmp[2 * i + 1]);
	f->shapes++;
	if (e->kind != R_PATH) {
		out_poly(f, tmp, e->nxy);
		return;
	}
	/* a negative width is absolute: not scaled by the magnification */
	double hw = e->width < 0 ? -(double)e->width / 2 : (double)e->width * t->mag / 2;
	double e0 = 0, e1 = 0, rt = 0;
	if (e->pathtype == 2)
		e0 = e1 = hw;
	else if (e->pathtype == 4) {
		e0 = e->bgnextn * t->mag;
		e1 = e->endextn * t->mag;
	} else if (e->pathtype == 1)
		rt = 1e-3 / f->g->um;   /* 1 nm in dbu */
	struct poly_set *ps = &g->path_out;
	ps->n = 0;
	if (ps->start)
		ps->start[0] = 0;
	poly_path(ps, tmp, e->nxy, hw, e0, e1, rt);
	for (int i = 0; i < ps->n; i++) {
		int nv = poly_set_nv(ps, i);
		double q[2 * 4096];
		if (nv > 4096)
			continue;
		memcpy(q, poly_set_xy(ps, i), 2 * (size_t)nv * sizeof *q);
		out_poly(f, q, nv);
	}
}

/* Bounding box of a cell's contents (every layer), dbu, with loop check. */
static void cell_bbox(struct gds_lib *g, int ci, size_t from, int depth)
{
	struct cell *c = &g->c[ci];
	if (c->state == 2)
		return;
	if (c->state == 1)
		gds_die(g, from, "reference loop: cell \"%.60s\" contains itself", c->name);
	if (depth > GDS_MAX_DEPTH)
		gds_die(g, from, "references nested more than %d deep", GDS_MAX_DEPTH);
	c->state = 1;
	double bb[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
	for (size_t k = c->first; k < c->first + c->n; k++) {
		const struct elem *e = &g->e[k];
		const unsigned char *p = g->buf + e->xy;
		if (e->kind == R_SREF || e->kind == R_AREF) {
			cell_bbox(g, e->ref, e->off, depth + 1);
			const struct cell *s = &g->c[e->ref];
			if (s->empty)
				continue;
			struct xform id = {1, 0, 0, 1, 0, 0, 1, 0, 0};
			double px[3], py[3];
			for (int i = 0; i < e->nxy; i++) {
				px[i] = si32(p + 8 * i);
				py[i] = si32(p + 8 * i + 4);
			}
			struct xform t = compose(&id, e, 0, 0);
			/* the corners of the child's box at the array's four corners */
			for (int a = 0; a < 2; a++)
				for (int b = 0; b < 2; b++) {
					double ox = px[0], oy = py[0];
					if (e->kind == R_AREF) {
						ox += a * (px[1] - px[0]) * (e->cols - 1) / e->cols +
						      b * (px[2] - px[0]) * (e->rows - 1) / e->rows;
						oy += a * (py[1] - py[0]) * (e->cols - 1) / e->cols +
						      b * (py[2] - py[0]) * (e->rows - 1) / e->rows;
					}
					for (int u = 0; u < 2; u++)
						for (int v = 0; v < 2; v++) {
							double x, y;
							apply(&t, (double)s->bb[u], (double)s->bb[2 + v], &x, &y);
							x += ox;
							y += oy;
							bb[0] = fmin(bb[0], x); bb[1] = fmax(bb[1], x);
							bb[2] = fmin(bb[2], y); bb[3] = fmax(bb[3], y);
						}
				}
		} else {
			/* paths reach out by their half-width and extensions */
			double grow = 0;
			if (e->kind == R_PATH) {
				double w = fabs((double)e->width);
				grow = w / 2 + fmax(fabs((double)e->bgnextn), fabs((double)e->endextn)) + w;
			}
			for (int i = 0; i < e->nxy; i++) {
				double x = si32(p + 8 * i), y = si32(p + 8 * i + 4);
				bb[0] = fmin(bb[0], x - grow); bb[1] = fmax(bb[1], x + grow);
				bb[2] = fmin(bb[2], y - grow); bb[3] = fmax(bb[3], y + grow);
			}
		}
	}
	c->empty = !(bb[1] >= bb[0]);
	for (int i = 0; i < 4 && !c->empty; i++)
		c->bb[i] = (int64_t)(i % 2 ? ceil(fmin(bb[i], 9e18)) : floor(fmax(bb[i], -9e18)));
	c->state = 2;
}

static void flatten(struct flat *f, int ci, const struct xform *t)
{
	const struct gds_lib *g = f->g;
	const struct cell *c = &g->c[ci];
	if (c->empty)
		return;
	if (f->cull) {
		double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
		for (int u = 0; u < 2; u++)
			for (int v = 0; v < 2; v++) {
				double x, y;
				apply(t, (double)c->bb[u], (double)c->bb[2 + v], &x, &y);
				x0 = fmin(x0, x); x1 = fmax(x1, x);
				y0 = fmin(y0, y); y1 = fmax(y1, y);
			}
		if (box_misses(f, x0, x1, y0, y1))
			return;
	}
	for (size_t k = c->first; k < c->first + c->n; k++) {
		const struct elem *e = &g->e[k];
		if (++f->visits > g->max_visit)
			gds_die(g, e->off, "flattening visits more than %ld elements (arrays of "
				"arrays?); refusing", g->max_visit);
		if (e->kind == R_SREF || e->kind == R_AREF) {
			const unsigned char *p = g->buf + e->xy;
			double px[3], py[3];
			for (int i = 0; i < e->nxy; i++) {
				px[i] = si32(p + 8 * i);
				py[i] = si32(p + 8 * i + 4);
			}
			/* an array is refused whole before its first copy (the
			 * counts of shapes() make this a last guard) */
			if ((double)e->cols * e->rows > (double)(g->max_visit - f->visits))
				gds_die(g, e->off, "%s takes flattening past %ld elements; refusing",
					e->kind == R_AREF ? "an AREF" : "an SREF", g->max_visit);
			for (int j = 0; j < e->rows; j++)
				for (int i = 0; i < e->cols; i++) {
					double x = px[0], y = py[0];
					if (e->kind == R_AREF) {
						x += (px[1] - px[0]) * i / e->cols + (px[2] - px[0]) * j / e->rows;
						y += (py[1] - py[0]) * i / e->cols + (py[2] - py[0]) * j / e->rows;
						if ((i || j) && ++f->visits > g->max_visit)
							gds_die(g, e->off, "flattening visits more than %ld "
								"elements (arrays of arrays?); refusing",
								g->max_visit);
					}
					struct xform ct = compose(t, e, x, y);
					flatten(f, e->ref, &ct);
				}
			continue;
		}
		if (e->layer != f->layer || (f->datatype >= 0 && e->datatype != f->datatype))
			continue;
		shape(f, e, t);
	}
}

/* Per-operation costs of flattening, for the estimate made before it:
 * seconds per element visited and per vertex written, and bytes per
 * vertex and per shape of the output (measured on the development
 * machine, a 2020 x86-64 core, with tests/lib/mkgds arrays). */
static const double T_VISIT = 3e-8, T_VERT = 1.5e-8, B_VERT = 16, B_SHAPE = 24;

/* The vertices a shape element adds to the output: its points, or for a
 * path its outline (two sides, the ends, round ends as polygons). */
static double elem_verts(const struct gds_lib *g, const struct elem *e)
{
	if (e->kind != R_PATH)
		return e->nxy;
	double v = 2.0 * e->nxy + 4;
	if (e->pathtype == 1)
		v += 2.0 * poly_circle_sides(fabs((double)e->width) / 2, 1e-3 / g->um);
	return v;
}

static int on_layer(const struct flat *f, const struct elem *e)
{
	return e->layer == f->layer && (f->datatype < 0 || e->datatype == f->datatype);
}

/* Bottom-up counts of a cell flattened whole (no window): its shapes on
 * the layer, their vertices and the elements flattening visits, from
 * those of the cells it references times their copies.  Doubles: 40
 * levels of two SREFs are 2^40 copies.  cell_bbox has run from the top
 * cell, so there is no loop and the depth is bounded. */
static void cell_count(const struct flat *f, int ci)
{
	struct cell *c = &((struct gds_lib *)f->g)->c[ci];
	if (c->counted)
		return;
	double n[3] = {0, 0, 0};
	for (size_t k = c->first; k < c->first + c->n; k++) {
		const struct elem *e = &f->g->e[k];
		n[2] += 1;
		if (e->kind == R_SREF || e->kind == R_AREF) {
			cell_count(f, e->ref);
			const double *s = f->g->c[e->ref].cnt, m = (double)e->cols * e->rows;
			n[0] += m * s[0];
			n[1] += m * s[1];
			n[2] += m * s[2] + (m - 1);
		} else if (on_layer(f, e)) {
			n[0] += 1;
			n[1] += elem_verts(f->g, e);
		}
	}
	memcpy(c->cnt, n, sizeof n);
	c->counted = 1;
}

/* walk_count's count of the last `left` copies of the reference e once
 * its steps are spent: each copy's cell counted whole (as walk_count adds
 * a cell it no longer walks into), and for an array each copy but the
 * first one more element visited (`past_first`: the first is not among
 * them). */
static void count_rest(const struct flat *f, const struct elem *e, double left, int past_first,
		       double *n)
{
	const struct cell *c = &f->g->c[e->ref];
	if (!c->empty)
		for (int k = 0; k < 3; k++)
			n[k] += left * c->cnt[k];
	if (e->kind == R_AREF)
		n[2] += left - !past_first;
}

/* The counts of what flattening cell ci under t keeps with the window:
 * a cell wholly inside adds its bottom-up counts, one wholly outside
 * nothing, and one across the window's edge is walked into.  After
 * COUNT_STEPS steps the rest is counted whole (an upper bound), so the
 * count itself never runs away. */
enum { COUNT_STEPS = 2000000 };
static void walk_count(struct flat *f, int ci, const struct xform *t, double *n, long *steps)
{
	const struct gds_lib *g = f->g;
	const struct cell *c = &g->c[ci];
	if (c->empty)
		return;
	int inside = !f->cull || *steps > COUNT_STEPS;
	if (!inside) {
		double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
		for (int u = 0; u < 2; u++)
			for (int v = 0; v < 2; v++) {
				double x, y;
				apply(t, (double)c->bb[u], (double)c->bb[2 + v], &x, &y);
				x0 = fmin(x0, x); x1 = fmax(x1, x);
				y0 = fmin(y0, y); y1 = fmax(y1, y);
			}
		if (box_misses(f, x0, x1, y0, y1))
			return;
		inside = x0 >= f->win[0] && x1 <= f->win[1] && y0 >= f->win[2] && y1 <= f->win[3];
	}
	if (inside) {
		for (int i = 0; i < 3; i++)
			n[i] += c->cnt[i];
		return;
	}
	for (size_t k = c->first; k < c->first + c->n; k++) {
		const struct elem *e = &g->e[k];
		++*steps;
		n[2] += 1;
		if (e->kind != R_SREF && e->kind != R_AREF) {
			if (on_layer(f, e)) {
				n[0] += 1;
				n[1] += elem_verts(g, e);
			}
			continue;
		}
		const unsigned char *p = g->buf + e->xy;
		double px[3], py[3];
		for (int i = 0; i < e->nxy; i++) {
			px[i] = si32(p + 8 * i);
			py[i] = si32(p + 8 * i + 4);
		}
		for (int j = 0; j < e->rows; j++)
			for (int i = 0; i < e->cols; i++) {
				if (*steps > COUNT_STEPS) {
					/* the copies left are counted whole at once, as
					 * the walk would add each (an array of 32767 x
					 * 32767 is 1e9 copies) */
					count_rest(f, e, (double)(e->rows - j) * e->cols - i, i || j, n);
					j = e->rows;
					break;
				}
				double x = px[0], y = py[0];
				if (e->kind == R_AREF) {
					x += (px[1] - px[0]) * i / e->cols + (px[2] - px[0]) * j / e->rows;
					y += (py[1] - py[0]) * i / e->cols + (py[2] - py[0]) * j / e->rows;
					n[2] += i || j;
				}
				struct xform ct = compose(t, e, x, y);
				walk_count(f, e->ref, &ct, n, steps);
				++*steps;
			}
	}
}

/* Refuses, before flattening, what would run away: more visits than the
 * limit, or more vertices than the memory or an hour allow (then -big). */
static void check_counts(struct flat *f, int top)
{
	struct gds_lib *g = (struct gds_lib *)f->g;
	for (int i = 0; i < g->nc; i++)
		g->c[i].counted = 0;
	cell_count(f, top);
	double n[3] = {0, 0, 0};
	long steps = 0;
	struct xform id = {1, 0, 0, 1, 0, 0, 1, 0, 0};
	walk_count(f, top, &id, n, &steps);
	const char *name = g->c[top].name;
	double secs = n[2] * T_VISIT + n[1] * T_VERT, bytes = n[1] * B_VERT + n[0] * B_SHAPE;
	if (!budget_big() && !(secs <= BUDGET_SECONDS && bytes <= budget_memory())) {
		char b[16];
		gds_die(g, g->c[top].off, "flattening cell \"%.60s\" layer %d gives %.3g shapes "
			"of %.3g vertices, about %s of memory and %.2g s, beyond the limits: use "
			"-big or SAMPLE3D_BIG=1 to run it anyway", name, f->layer, n[0], n[1],
			budget_bytes(b, bytes), secs);
	}
	/* -big or not, the walk itself is bounded */
	if (n[2] > (double)g->max_visit)
		gds_die(g, g->c[top].off, "flattening cell \"%.60s\" visits %.3g elements, more "
			"than %ld (references of references, arrays of arrays); refusing", name,
			n[2], g->max_visit);
}

/* The names of the library's cells, "A, B, C" (cut short with "..."),
 * for the message of a cell that is not there. */
static void cell_names(const struct gds_lib *g, char *buf, size_t n)
{
	size_t ll = 0;
	buf[0] = '\0';
	for (int i = 0; i < g->nc && ll < n - 80; i++)
		ll += (size_t)snprintf(buf + ll, n - ll, "%s%.60s", i ? ", " : "", g->c[i].name);
	if (ll >= n - 80 && g->nc)
		snprintf(buf + ll, n - ll, ", ...");
}

/* Most distinct layer/datatype pairs listed by fmt_gds_layer_list. */
enum { GDS_LIST_PAIRS = 40 };

static int is_shape(const struct elem *e)
{
	return e->kind == R_BOUNDARY || e->kind == R_BOX || e->kind == R_PATH;
}

int fmt_gds_layer_list(const struct gds_lib *g, int layer, int datatype, char *buf, size_t n)
{
	buf[0] = '\0';
	for (size_t i = 0; i < g->ne; i++)
		if (is_shape(&g->e[i]) && g->e[i].layer == layer &&
		    (datatype < 0 || g->e[i].datatype == datatype))
			return 1;
	/* not there: the distinct pairs, in file order (one pass, against
	 * the few already listed) */
	int pl[GDS_LIST_PAIRS], pd[GDS_LIST_PAIRS], np = 0;
	size_t ll = 0;
	for (size_t i = 0; i < g->ne && np < GDS_LIST_PAIRS; i++) {
		const struct elem *e = &g->e[i];
		int seen = !is_shape(e);
		for (int k = 0; k < np && !seen; k++)
			seen = pl[k] == e->layer && pd[k] == e->datatype;
		if (seen || ll >= n - 40)
			continue;
		pl[np] = e->layer;
		pd[np] = e->datatype;
		ll += (size_t)snprintf(buf + ll, n - ll, "%s%d/%d", np++ ? ", " : "", e->layer,
				       e->datatype);
	}
	return 0;
}

static long shapes(struct gds_lib *g, const char *cell, int layer, int datatype,
		   const double *win, struct poly_set *out);

long fmt_gds_shapes(const struct gds_lib *cg, const char *cell, int layer, int datatype,
		    const double *win, struct poly_set *out)
{
	char err[640];
	long n = fmt_gds_shapes_try((struct gds_lib *)cg, cell, layer, datatype, win, out,
				    err, sizeof err);
	if (n < 0)
		die("%s", err);
	return n;
}

long fmt_gds_shapes_try(struct gds_lib *g, const char *cell, int layer, int datatype,
			const double *win, struct poly_set *out, char *err, size_t errlen)
{
	jmp_buf jb;
	g->jmp = &jb;
	if (setjmp(jb)) {
		g->jmp = NULL;
		snprintf(err, errlen, "%s", g->err);
		/* a walk cut short leaves cells marked as on the path */
		for (int i = 0; i < g->nc; i++)
			if (g->c[i].state == 1)
				g->c[i].state = 0;
		return -1;
	}
	long n = shapes(g, cell, layer, datatype, win, out);
	g->jmp = NULL;
	return n;
}

static long shapes(struct gds_lib *g, const char *cell, int layer, int datatype,
		   const double *win, struct poly_set *out)
{
	int top = -1;
	if (cell) {
		top = gds_find_cell(g, cell, strlen(cell));
		if (top < 0) {
			char names[400];
			cell_names(g, names, sizeof names);
			gds_die(g, 0, "no cell named \"%.60s\"; its cells: %s", cell, names);
		}
	} else {
		char list[400];
		size_t ll = 0;
		int ntop = 0;
		list[0] = '\0';
		for (int i = 0; i < g->nc; i++)
			if (!g->c[i].referenced) {
				if (ntop++ == 0)
					top = i;
				if (ll < sizeof list - 80)
					ll += (size_t)snprintf(list + ll, sizeof list - ll, "%s\"%.60s\"",
							       ntop > 1 ? ", " : "", g->c[i].name);
			}
		if (ntop == 0)
			gds_die(g, 0, g->nc ? "no top cell (every cell is referenced: a reference loop)"
				: "the library has no cell");
		if (ntop > 1)
			gds_die(g, 0, "%d top cells, give \"cell NAME\": %s", ntop, list);
	}
	cell_bbox(g, top, g->c[top].off, 0);
	struct flat f;
	memset(&f, 0, sizeof f);
	f.g = g;
	f.layer = layer;
	f.datatype = datatype;
	f.out = out;
	if (win) {
		f.cull = 1;
		for (int i = 0; i < 4; i++)
			f.win[i] = win[i] / g->um;
		/* a little slack: culling must never drop a shape that touches */
		double s = 1e-6 * (fabs(f.win[1] - f.win[0]) + fabs(f.win[3] - f.win[2]));
		f.win[0] -= s; f.win[1] += s; f.win[2] -= s; f.win[3] += s;
	}
	check_counts(&f, top);
	struct xform id = {1, 0, 0, 1, 0, 0, 1, 0, 0};
	flatten(&f, top, &id);
	return f.shapes;
}
