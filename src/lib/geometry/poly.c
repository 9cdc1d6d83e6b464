/*
 * poly.c - polygon geometry for masks (see poly.h).
 *
 * The union of many polygons is never built as polygons: every use we
 * have (the exact Fourier transform of a painted mask, a point query)
 * needs only where the covering layer changes.  A slab sweep gives that
 * robustly: the plane is cut at every vertex y and every edge crossing,
 * so inside a slab the edges are ordered left to right and never cross;
 * walking them with a winding count per layer tells which layer is on
 * top between consecutive edges.  Crossings are found per slab from the
 * order of the edges at the slab's ends (an inversion between neighbours
 * is a crossing), and the slab is split there.  Coordinates at a slab's
 * ends that are an edge's own end points are taken exactly, never
 * interpolated, so axis-parallel input gives exact pieces.
 */
#include "poly.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void poly_set_add(struct poly_set *s, const double *xy, int nv)
{
	if (!s->start) {
		s->cap_p = 0;
		xgrow(&s->start, &s->cap_p, 1, sizeof *s->start);
		s->start[0] = 0;
	}
	xgrow(&s->start, &s->cap_p, (size_t)s->n + 2, sizeof *s->start);
	size_t nvt = (size_t)s->start[s->n] + (size_t)nv;
	if (nvt > 0x7fffffff)
		die("polygon set: more than 2^31 vertices");
	xgrow(&s->xy, &s->cap_v, 2 * nvt, sizeof *s->xy);
	memcpy(s->xy + 2 * (size_t)s->start[s->n], xy, 2 * (size_t)nv * sizeof *xy);
	s->n++;
	s->start[s->n] = (int)nvt;
}

void poly_set_free(struct poly_set *s)
{
	free(s->start);
	free(s->xy);
	memset(s, 0, sizeof *s);
}

double poly_area(const double *xy, int n)
{
	double a = 0;
	for (int i = 0; i < n; i++) {
		int j = i + 1 == n ? 0 : i + 1;
		a += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
	}
	return a / 2;
}

int poly_dedup(double *xy, int n)
{
	int k = 0;
	for (int i = 0; i < n; i++) {
		if (k > 0 && xy[2 * i] == xy[2 * (k - 1)] && xy[2 * i + 1] == xy[2 * (k - 1) + 1])
			continue;
		xy[2 * k] = xy[2 * i];
		xy[2 * k + 1] = xy[2 * i + 1];
		k++;
	}
	while (k > 1 && xy[0] == xy[2 * (k - 1)] && xy[1] == xy[2 * (k - 1) + 1])
		k--;
	return k;
}

static double orient(const double *a, const double *b, const double *c)
{
	return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static int on_segment(const double *a, const double *b, const double *p)
{
	return fmin(a[0], b[0]) <= p[0] && p[0] <= fmax(a[0], b[0]) &&
	       fmin(a[1], b[1]) <= p[1] && p[1] <= fmax(a[1], b[1]);
}

/* Closed segments ab and cd share a point. */
static int seg_meet(const double *a, const double *b, const double *c, const double *d)
{
	double o1 = orient(a, b, c), o2 = orient(a, b, d);
	double o3 = orient(c, d, a), o4 = orient(c, d, b);
	if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) &&
	    ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
		return 1;
	return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
	       (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

int poly_simple(const double *xy, int n, int *ei, int *ej)
{
	*ei = *ej = 0;
	if (n < 3)
		return 0;
	for (int i = 0; i < n; i++) {
		const double *a = xy + 2 * i, *b = xy + 2 * ((i + 1) % n);
		/* the next edge may only touch at the shared vertex: not fold back */
		const double *c = xy + 2 * ((i + 2) % n);
		if (orient(a, b, c) == 0 && (b[0] - a[0]) * (c[0] - b[0]) +
		    (b[1] - a[1]) * (c[1] - b[1]) < 0) {
			*ei = i;
			*ej = (i + 1) % n;
			return 0;
		}
		for (int j = i + 2; j < n; j++) {
			if (i == 0 && j == n - 1)
				continue;       /* adjacent through the closing vertex */
			const double *p = xy + 2 * j, *q = xy + 2 * ((j + 1) % n);
			if (fmax(a[0], b[0]) < fmin(p[0], q[0]) || fmax(p[0], q[0]) < fmin(a[0], b[0]) ||
			    fmax(a[1], b[1]) < fmin(p[1], q[1]) || fmax(p[1], q[1]) < fmin(a[1], b[1]))
				continue;
			if (seg_meet(a, b, p, q)) {
				*ei = i;
				*ej = j;
				return 0;
			}
		}
	}
	return poly_area(xy, n) != 0;
}

/* One Sutherland-Hodgman stage: keeps the side where s*(coord - v) >= 0
 * of the line x = v (axis 0) or y = v (axis 1). */
static int clip_stage(const double *in, int n, double *out, int axis, double v, double s)
{
	int k = 0;
	for (int i = 0; i < n; i++) {
		const double *p = in + 2 * i, *q = in + 2 * ((i + 1) % n);
		double dp = s * (p[axis] - v), dq = s * (q[axis] - v);
		if (dp >= 0) {
			out[2 * k] = p[0];
			out[2 * k + 1] = p[1];
			k++;
		}
		if ((dp >= 0) != (dq >= 0) && dp != 0 && dq != 0) {
			double t = dp / (dp - dq);
			double *o = out + 2 * k;
			o[axis] = v;
			o[1 - axis] = p[1 - axis] + t * (q[1 - axis] - p[1 - axis]);
			k++;
		}
	}
	return k;
}

int poly_clip_rect(const double *xy, int n, double x0, double x1, double y0,
		   double y1, double **out)
{
	*out = NULL;
	double bx0 = xy[0], bx1 = xy[0], by0 = xy[1], by1 = xy[1];
	for (int i = 1; i < n; i++) {
		bx0 = fmin(bx0, xy[2 * i]); bx1 = fmax(bx1, xy[2 * i]);
		by0 = fmin(by0, xy[2 * i + 1]); by1 = fmax(by1, xy[2 * i + 1]);
	}
	if (bx1 <= x0 || bx0 >= x1 || by1 <= y0 || by0 >= y1)
		return 0;
	/* each stage adds at most one vertex per crossing: 2n is enough */
	size_t cap = 2 * (size_t)n + 8;
	double *a = xreallocarray(NULL, cap, 2 * sizeof *a);
	double *b = xreallocarray(NULL, cap, 2 * sizeof *b);
	memcpy(a, xy, 2 * (size_t)n * sizeof *a);
	int k = n;
	if (bx0 < x0) { k = clip_stage(a, k, b, 0, x0, 1); double *t = a; a = b; b = t; }
	if (k && bx1 > x1) { k = clip_stage(a, k, b, 0, x1, -1); double *t = a; a = b; b = t; }
	if (k && by0 < y0) { k = clip_stage(a, k, b, 1, y0, 1); double *t = a; a = b; b = t; }
	if (k && by1 > y1) { k = clip_stage(a, k, b, 1, y1, -1); double *t = a; a = b; b = t; }
	free(b);
	k = poly_dedup(a, k);
	if (k < 3 || poly_area(a, k) == 0) {
		free(a);
		return 0;
	}
	*out = a;
	return k;
}

int poly_winding(const double *xy, int n, double x, double y)
{
	int w = 0;
	for (int i = 0; i < n; i++) {
		const double *p = xy + 2 * i, *q = xy + 2 * ((i + 1) % n);
		if (p[1] <= y) {
			if (q[1] > y && orient(p, q, (double[]){x, y}) > 0)
				w++;
		} else if (q[1] <= y && orient(p, q, (double[]){x, y}) < 0) {
			w--;
		}
	}
	return w;
}

int poly_circle_sides(double r, double tol)
{
	if (!(r > 0) || !(tol > 0) || tol >= r)
		return 8;
	double a = acos(1 - tol / r);           /* half the angle per side */
	double n = ceil(M_PI / a);
	return n < 8 ? 8 : n > 4096 ? 4096 : (int)n;
}

static void add_circle(struct poly_set *out, double cx, double cy, double r, double tol)
{
	int n = poly_circle_sides(r, tol);
	/* vertices slightly outside the circle so that the polygon has the
	 * circle's area: the error changes sign along the edge instead of
	 * always cutting area (vertices r(s-1) ~ sagitta/3 out, edge middles
	 * ~ 2 sagitta/3 in, both within tol) */
	double s = sqrt(2 * M_PI / (n * sin(2 * M_PI / n)));
	double *c = xreallocarray(NULL, (size_t)n, 2 * sizeof *c);
	for (int i = 0; i < n; i++) {
		double a = 2 * M_PI * i / n;
		c[2 * i] = cx + r * s * cos(a);
		c[2 * i + 1] = cy + r * s * sin(a);
	}
	poly_set_add(out, c, n);
	free(c);
}

void poly_path(struct poly_set *out, const double *xy, int n, double hw,
	       double ext0, double ext1, double round_tol)
{
	if (!(hw > 0) || n < 1)
		return;
	double *p = xreallocarray(NULL, (size_t)n, 2 * sizeof *p);
	memcpy(p, xy, 2 * (size_t)n * sizeof *p);
	int k = 0;      /* consecutive duplicates only: a closed path keeps its end */
	for (int i = 0; i < n; i++)
		if (k == 0 || p[2 * i] != p[2 * (k - 1)] || p[2 * i + 1] != p[2 * (k - 1) + 1]) {
			p[2 * k] = p[2 * i];
			p[2 * k + 1] = p[2 * i + 1];
			k++;
		}
	n = k;
	if (round_tol > 0) {
		add_circle(out, p[0], p[1], hw, round_tol);
		if (n > 1)
			add_circle(out, p[2 * (n - 1)], p[2 * (n - 1) + 1], hw, round_tol);
	}
	for (int i = 0; i + 1 < n; i++) {
		double dx = p[2 * i + 2] - p[2 * i], dy = p[2 * i + 3] - p[2 * i + 1];
		double len = hypot(dx, dy);
		dx /= len;
		dy /= len;
		double nx = -dy * hw, ny = dx * hw;
		double e0 = i == 0 ? ext0 : 0, e1 = i + 2 == n ? ext1 : 0;
		double sx = p[2 * i] - e0 * dx, sy = p[2 * i + 1] - e0 * dy;
		double ex = p[2 * i + 2] + e1 * dx, ey = p[2 * i + 3] + e1 * dy;
		/* exact for axis-parallel segments: no rounding of dx, dy, nx, ny */
		double q[8] = {sx - nx, sy - ny, ex - nx, ey - ny, ex + nx, ey + ny, sx + nx, sy + ny};
		if (len + e0 + e1 > 0)
			poly_set_add(out, q, 4);
		if (i == 0)
			continue;
		/* mitre wedge at p[i] between segment i-1 and segment i */
		double ax = p[2 * i] - p[2 * i - 2], ay = p[2 * i + 1] - p[2 * i - 1];
		double al = hypot(ax, ay);
		ax /= al;
		ay /= al;
		double cr = ax * dy - ay * dx, dot = ax * dx + ay * dy;
		if (cr == 0 || 1 + dot < 1e-9)
			continue;       /* straight on, or folding back: no outer corner */
		double s = cr > 0 ? -1 : 1;     /* the outer side of the turn */
		double n1x = -ay, n1y = ax, n2x = -dy, n2y = dx;
		double cx = p[2 * i], cy = p[2 * i + 1];
		double mx = cx + s * hw * (n1x + n2x) / (1 + dot);
		double my = cy + s * hw * (n1y + n2y) / (1 + dot);
		double w[8] = {cx, cy, cx + s * hw * n1x, cy + s * hw * n1y, mx, my,
			       cx + s * hw * n2x, cy + s * hw * n2y};
		poly_set_add(out, w, 4);
	}
	free(p);
}

/* ---- the slab sweep ---- */

struct edge {
	double ya, yb, xa, xb;  /* ya < yb; x at ya and at yb */
	int layer;
	int wind;               /* added to the layer's count when crossed left to right */
};

struct sweep {
	const struct edge *e;
	int *act;               /* active edges of the slab */
	int nact;
	double *x0, *x1;        /* x of active edge k at the sub-slab ends */
	int *ord;
	int *count;             /* winding count per layer */
	int nlayers;
	double eps;             /* crossings closer than this are not split */
	struct poly_piece *pc;
	size_t npc, cap;
};

static double edge_x(const struct edge *e, double y)
{
	if (y == e->ya)
		return e->xa;
	if (y == e->yb)
		return e->xb;
	if (e->xa == e->xb)
		return e->xa;
	return e->xa + (e->xb - e->xa) * ((y - e->ya) / (e->yb - e->ya));
}

/* qsort has no context argument in C11: the slab being sorted (the sweep
 * is single-threaded; a threaded caller would need its own sort) */
static const struct sweep *cmp_sw;
static int cmp_active(const void *pa, const void *pb)
{
	int a = *(const int *)pa, b = *(const int *)pb;
	const struct sweep *s = cmp_sw;
	double ma = s->x0[a] + s->x1[a], mb = s->x0[b] + s->x1[b];
	if (ma != mb)
		return ma < mb ? -1 : 1;
	if (s->x0[a] != s->x0[b])
		return s->x0[a] < s->x0[b] ? -1 : 1;
	if (s->x1[a] != s->x1[b])
		return s->x1[a] < s->x1[b] ? -1 : 1;
	return (a > b) - (a < b);
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static int top_layer(const int *count, int top)
{
	while (top >= 0 && count[top] == 0)
		top--;
	return top;
}

static void emit_slab(struct sweep *s, double y0, double y1)
{
	int n = s->nact;
	for (int k = 0; k < n; k++) {
		const struct edge *e = &s->e[s->act[k]];
		s->x0[k] = edge_x(e, y0);
		s->x1[k] = edge_x(e, y1);
		s->ord[k] = k;
	}
	cmp_sw = s;
	qsort(s->ord, (size_t)n, sizeof *s->ord, cmp_active);
	/* crossings: neighbours out of order at either end */
	double *cut = NULL;
	size_t ncut = 0, ccap = 0;
	for (int k = 0; k + 1 < n; k++) {
		int a = s->ord[k], b = s->ord[k + 1];
		double d0 = s->x0[a] - s->x0[b], d1 = s->x1[a] - s->x1[b];
		if (d0 <= s->eps && d1 <= s->eps)
			continue;
		/* x_a - x_b goes linearly from d0 to d1: zero at t */
		if ((d0 > 0) == (d1 > 0))
			continue;
		double t = d0 / (d0 - d1);
		double yc = y0 + t * (y1 - y0);
		if (yc > y0 && yc < y1 && (yc - y0) > s->eps && (y1 - yc) > s->eps) {
			xgrow(&cut, &ccap, ncut + 1, sizeof *cut);
			cut[ncut++] = yc;
		}
	}
	if (ncut) {
		qsort(cut, ncut, sizeof *cut, cmp_double);
		double ya = y0;
		for (size_t i = 0; i <= ncut; i++) {
			double yb = i < ncut ? cut[i] : y1;
			if (yb > ya)
				emit_slab(s, ya, yb);
			ya = yb;
		}
		free(cut);
		return;
	}
	/* walk left to right; identical edges form one breakpoint */
	int top = -1;
	for (int k = 0; k < n;) {
		int a = s->ord[k];
		double xa = s->x0[a], xb = s->x1[a];
		int before = top, g = k;
		while (g < n && s->x0[s->ord[g]] == xa && s->x1[s->ord[g]] == xb) {
			const struct edge *e = &s->e[s->act[s->ord[g]]];
			s->count[e->layer] += e->wind;
			if (s->count[e->layer] != 0 && e->layer > top)
				top = e->layer;
			g++;
		}
		top = top_layer(s->count, top);
		if (top != before) {
			xgrow(&s->pc, &s->cap, s->npc + 1, sizeof *s->pc);
			s->pc[s->npc++] = (struct poly_piece){xa, y0, xb, y1, before, top};
		}
		k = g;
	}
	/* a closed set of polygons brings every count back to zero; rounding
	 * in a degenerate slab cannot break that, since counts are integers */
	for (int k = 0; k < n; k++)
		s->count[s->e[s->act[k]].layer] = 0;
}

static int cmp_edge_ya(const void *pa, const void *pb)
{
	const struct edge *a = pa, *b = pb;
	if (a->ya != b->ya)
		return a->ya < b->ya ? -1 : 1;
	if (a->yb != b->yb)
		return a->yb < b->yb ? -1 : 1;
	if (a->xa != b->xa)
		return a->xa < b->xa ? -1 : 1;
	if (a->xb != b->xb)
		return a->xb < b->xb ? -1 : 1;
	if (a->layer != b->layer)
		return a->layer - b->layer;
	return a->wind - b->wind;
}

/* Vertical pieces of consecutive slabs along one line with the same
 * layers either side become one. */
static int cmp_piece(const void *pa, const void *pb)
{
	const struct poly_piece *a = pa, *b = pb;
	int va = a->x0 == a->x1, vb = b->x0 == b->x1;
	if (va != vb)
		return va - vb;
	if (a->x0 != b->x0)
		return a->x0 < b->x0 ? -1 : 1;
	if (a->left != b->left)
		return a->left - b->left;
	if (a->right != b->right)
		return a->right - b->right;
	if (a->y0 != b->y0)
		return a->y0 < b->y0 ? -1 : 1;
	if (a->x1 != b->x1)
		return a->x1 < b->x1 ? -1 : 1;
	return (a->y1 > b->y1) - (a->y1 < b->y1);
}

static size_t merge_vertical(struct poly_piece *p, size_t n)
{
	qsort(p, n, sizeof *p, cmp_piece);
	size_t k = 0;
	for (size_t i = 0; i < n; i++) {
		if (k > 0) {
			struct poly_piece *q = &p[k - 1];
			if (q->x0 == q->x1 && p[i].x0 == p[i].x1 && q->x0 == p[i].x0 &&
			    q->left == p[i].left && q->right == p[i].right && q->y1 == p[i].y0) {
				q->y1 = p[i].y1;
				continue;
			}
		}
		p[k++] = p[i];
	}
	return k;
}

size_t poly_boundary(const struct poly_set *layers, int nlayers, struct poly_piece **out)
{
	*out = NULL;
	size_t ne = 0, ecap = 0;
	struct edge *e = NULL;
	double lo = INFINITY, hi = -INFINITY;
	for (int l = 0; l < nlayers; l++) {
		const struct poly_set *s = &layers[l];
		for (int i = 0; i < s->n; i++) {
			int nv = poly_set_nv(s, i);
			const double *xy = poly_set_xy(s, i);
			double a = poly_area(xy, nv);
			if (a == 0 || nv < 3)
				continue;
			int sg = a > 0 ? 1 : -1;
			for (int v = 0; v < nv; v++) {
				const double *p = xy + 2 * v, *q = xy + 2 * ((v + 1) % nv);
				lo = fmin(lo, fmin(p[0], p[1]));
				hi = fmax(hi, fmax(p[0], p[1]));
				if (p[1] == q[1])
					continue;
				xgrow(&e, &ecap, ne + 1, sizeof *e);
				struct edge *d = &e[ne++];
				int up = q[1] > p[1];
				d->ya = up ? p[1] : q[1];
				d->yb = up ? q[1] : p[1];
				d->xa = up ? p[0] : q[0];
				d->xb = up ? q[0] : p[0];
				d->layer = l;
				/* a positive polygon is entered across its downward edges */
				d->wind = up ? -sg : sg;
			}
		}
	}
	if (ne == 0)
		return 0;
	qsort(e, ne, sizeof *e, cmp_edge_ya);
	double *ys = xreallocarray(NULL, 2 * ne, sizeof *ys);
	for (size_t i = 0; i < ne; i++) {
		ys[2 * i] = e[i].ya;
		ys[2 * i + 1] = e[i].yb;
	}
	qsort(ys, 2 * ne, sizeof *ys, cmp_double);
	size_t ny = 0;
	for (size_t i = 0; i < 2 * ne; i++)
		if (ny == 0 || ys[i] > ys[ny - 1])
			ys[ny++] = ys[i];

	struct sweep s;
	memset(&s, 0, sizeof s);
	s.e = e;
	s.act = xreallocarray(NULL, ne, sizeof *s.act);
	s.x0 = xreallocarray(NULL, ne, sizeof *s.x0);
	s.x1 = xreallocarray(NULL, ne, sizeof *s.x1);
	s.ord = xreallocarray(NULL, ne, sizeof *s.ord);
	s.count = xcalloc((size_t)nlayers, sizeof *s.count);
	s.nlayers = nlayers;
	/* well below any feature, well above rounding of the coordinates */
	s.eps = 1e-12 * fmax(hi - lo, fmax(fabs(hi), fabs(lo)));
	size_t next = 0;
	for (size_t j = 0; j + 1 < ny; j++) {
		double y0 = ys[j], y1 = ys[j + 1];
		int k = 0;
		for (int i = 0; i < s.nact; i++)
			if (e[s.act[i]].yb > y0)
				s.act[k++] = s.act[i];
		s.nact = k;
		while (next < ne && e[next].ya <= y0)
			s.act[s.nact++] = (int)next++;
		if (s.nact)
			emit_slab(&s, y0, y1);
	}
	free(ys);
	free(s.act);
	free(s.x0);
	free(s.x1);
	free(s.ord);
	free(s.count);
	free(e);
	s.npc = merge_vertical(s.pc, s.npc);
	*out = s.pc;
	return s.npc;
}
