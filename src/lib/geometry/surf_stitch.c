/*
 * surf_stitch.c - tiles' surfaces cut to their cores and welded at the
 * seams (see surf_stitch.h for the design).
 *
 * The cut is Sutherland-Hodgman against the four sides of the core; a
 * cut point is computed from the lexicographically smaller end of its
 * edge, so both triangles of a shared edge get the same bits and the cut
 * surface stays closed inside the core.  The weld works one seam plane
 * at a time: each tile's seam edges are chained (vertices by their bits),
 * every chain of the tiles below the plane is paired with the chain of
 * the tiles above whose ends are nearest, and each pair is joined by a
 * strip that advances along whichever chain is behind in arc length
 * (the usual zip of two polylines).  A strip's end edges that lie on a
 * face of the output box need nothing; those on the vertical line where
 * four cores meet form closed cycles around that corner (one per crossing
 * of the line with the surface) and are closed by fans along the line.
 */
#include "surf_stitch.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Vertices of a triangle cut by four planes: at most 3 + 4. */
enum { POLY_MAX = 8 };

void stitch_init(struct stitch *st, const double *box)
{
	memset(st, 0, sizeof *st);
	memcpy(st->box, box, sizeof st->box);
}

void stitch_free(struct stitch *st)
{
	free(st->e);
	memset(st, 0, sizeof *st);
}

static int lexless(const double *a, const double *b)
{
	for (int k = 0; k < 3; k++)
		if (a[k] != b[k])
			return a[k] < b[k];
	return 0;
}

static int same(const double *a, const double *b)
{
	return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* The point where edge p q meets the plane axis = c, from its smaller end. */
static void cut_point(const double *p, const double *q, int axis, double c, double *r)
{
	const double *a = p, *b = q;
	if (lexless(q, p))
		a = q, b = p;
	double t = (c - a[axis]) / (b[axis] - a[axis]);
	for (int k = 0; k < 3; k++)
		r[k] = a[k] + t * (b[k] - a[k]);
	r[axis] = c;
}

/* One Sutherland-Hodgman pass: keeps the part with p[axis] >= c (above)
 * or <= c (below). */
static int clip_plane(const double *in, int n, int axis, double c, int above, double *out)
{
	int m = 0;
	for (int i = 0; i < n; i++) {
		const double *p = in + 3 * i, *q = in + 3 * ((i + 1) % n);
		int pin = above ? p[axis] >= c : p[axis] <= c;
		int qin = above ? q[axis] >= c : q[axis] <= c;
		if (pin != qin && m < POLY_MAX)
			cut_point(p, q, axis, c, out + 3 * m++);
		if (qin && m < POLY_MAX)
			memcpy(out + 3 * m++, q, 3 * sizeof *q);
	}
	/* a vertex on the plane and its cut point coincide: keep one */
	int k = 0;
	for (int i = 0; i < m; i++)
		if (k == 0 || !same(out + 3 * i, out + 3 * (k - 1)))
			memmove(out + 3 * k++, out + 3 * i, 3 * sizeof *out);
	while (k > 1 && same(out, out + 3 * (k - 1)))
		k--;
	return k;
}

static void keep_seam(struct stitch *st, int tile, int axis, int side, double c,
		      const double *p, const double *q)
{
	xgrow(&st->e, &st->cap, st->n + 1, sizeof *st->e);
	struct stitch_edge *e = &st->e[st->n++];
	e->axis = axis, e->side = side, e->tile = tile, e->c = c;
	memcpy(e->p, p, sizeof e->p);
	memcpy(e->q, q, sizeof e->q);
}

int stitch_clip(struct stitch *st, int tile, const double *core_in, const double *tri9,
		stitch_emit_fn *emit, void *ctx)
{
	double a[3 * POLY_MAX], b[3 * POLY_MAX], core[4];
	for (int k = 0; k < 4; k++) {
		core[k] = core_in[k];
		if (core[k] != st->box[k])
			core[k] += STITCH_SEAM_OFFSET_UM;
	}
	memcpy(a, tri9, 9 * sizeof *a);
	int n = 3;
	/* early outs: wholly outside, wholly inside */
	double lo[2], hi[2];
	for (int k = 0; k < 2; k++) {
		lo[k] = fmin(fmin(a[k], a[3 + k]), a[6 + k]);
		hi[k] = fmax(fmax(a[k], a[3 + k]), a[6 + k]);
		if (hi[k] < core[2 * k] || lo[k] > core[2 * k + 1])
			return 0;
	}
	if (lo[0] > core[0] && hi[0] < core[1] && lo[1] > core[2] && hi[1] < core[3]) {
		emit(ctx, a);
		return 1;
	}
	n = clip_plane(a, n, 0, core[0], 1, b);
	n = clip_plane(b, n, 0, core[1], 0, a);
	n = clip_plane(a, n, 1, core[2], 1, b);
	n = clip_plane(b, n, 1, core[3], 0, a);
	if (n < 3)
		return 0;
	for (int i = 0; i < n; i++) {
		const double *p = a + 3 * i, *q = a + 3 * ((i + 1) % n);
		for (int axis = 0; axis < 2; axis++)
			for (int side = 0; side < 2; side++) {
				/* side 1: the core's low side, the tile above the plane */
				double c = core[2 * axis + (1 - side)];
				if (p[axis] == c && q[axis] == c &&
				    c != st->box[2 * axis] && c != st->box[2 * axis + 1])
					keep_seam(st, tile, axis, side, c, p, q);
			}
	}
	int m = 0;
	for (int i = 1; i + 1 < n; i++) {
		double t[9];
		memcpy(t, a, 3 * sizeof *t);
		memcpy(t + 3, a + 3 * i, 6 * sizeof *t);
		emit(ctx, t);
		m++;
	}
	return m;
}

/* ---- chains of one tile's seam edges on one plane ---- */

struct chain {
	double *p;          /* 3 numbers a point */
	int n;
	int closed;         /* a loop: p[n-1] joins p[0] */
	int used;
};

struct vref {
	const double *x;
	int edge, end;
};

static int cmp_vref(const void *a, const void *b)
{
	const double *p = ((const struct vref *)a)->x, *q = ((const struct vref *)b)->x;
	if (lexless(p, q))
		return -1;
	return lexless(q, p);
}

/* Chains the n edges e[] (one tile, one plane) into *out; returns the count. */
static int build_chains(const struct stitch_edge *e, int n, struct chain **out)
{
	struct vref *r = xreallocarray(NULL, 2 * (size_t)n, sizeof *r);
	for (int i = 0; i < n; i++) {
		r[2 * i] = (struct vref){e[i].p, i, 0};
		r[2 * i + 1] = (struct vref){e[i].q, i, 1};
	}
	if (n > 0)
		qsort(r, 2 * (size_t)n, sizeof *r, cmp_vref);
	int *vid = xreallocarray(NULL, 2 * (size_t)n, sizeof *vid);  /* per edge end */
	int nv = 0;
	for (int i = 0; i < 2 * n; i++) {
		if (i > 0 && cmp_vref(&r[i], &r[i - 1]) != 0)
			nv++;
		vid[2 * r[i].edge + r[i].end] = nv;
	}
	nv++;
	int *adj = xreallocarray(NULL, 2 * (size_t)nv, sizeof *adj);
	for (int i = 0; i < 2 * nv; i++)
		adj[i] = -1;
	for (int i = 0; i < n; i++)
		for (int k = 0; k < 2; k++) {
			int v = vid[2 * i + k];
			if (adj[2 * v] < 0)
				adj[2 * v] = i;
			else if (adj[2 * v + 1] < 0)
				adj[2 * v + 1] = i;
		}
	char *done = xcalloc((size_t)n ? (size_t)n : 1, 1);
	struct chain *ch = NULL;
	size_t cap = 0;
	int nch = 0;
	/* open chains from their ends, then loops */
	for (int pass = 0; pass < 2; pass++)
		for (int v0 = 0; v0 < nv; v0++) {
			int deg = (adj[2 * v0] >= 0) + (adj[2 * v0 + 1] >= 0);
			if (pass == 0 ? deg != 1 : deg != 2)
				continue;
			int ed = adj[2 * v0] >= 0 && !done[adj[2 * v0]] ? adj[2 * v0] : adj[2 * v0 + 1];
			if (ed < 0 || done[ed])
				continue;
			xgrow(&ch, &cap, (size_t)nch + 1, sizeof *ch);
			struct chain *c = &ch[nch++];
			memset(c, 0, sizeof *c);
			size_t pc = 0;
			int v = v0;
			const double *pv = vid[2 * ed] == v ? e[ed].p : e[ed].q;
			xgrow(&c->p, &pc, 3, sizeof *c->p);
			memcpy(c->p, pv, 3 * sizeof *pv);
			c->n = 1;
			while (ed >= 0 && !done[ed]) {
				done[ed] = 1;
				int end = vid[2 * ed] == v ? 1 : 0;
				v = vid[2 * ed + end];
				if (pass == 1 && v == v0) {
					c->closed = 1;
					break;
				}
				xgrow(&c->p, &pc, 3 * ((size_t)c->n + 1), sizeof *c->p);
				memcpy(c->p + 3 * c->n++, end ? e[ed].q : e[ed].p, 3 * sizeof *c->p);
				int nx = adj[2 * v] == ed ? adj[2 * v + 1] : adj[2 * v];
				ed = nx;
			}
		}
	free(done);
	free(adj);
	free(vid);
	free(r);
	*out = ch;
	return nch;
}

static void free_chains(struct chain *c, int n)
{
	for (int i = 0; i < n; i++)
		free(c[i].p);
	free(c);
}

static double dist(const double *a, const double *b)
{
	double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
	return sqrt(dx * dx + dy * dy + dz * dz);
}

static void reverse(struct chain *c)
{
	for (int i = 0, j = c->n - 1; i < j; i++, j--)
		for (int k = 0; k < 3; k++) {
			double t = c->p[3 * i + k];
			c->p[3 * i + k] = c->p[3 * j + k];
			c->p[3 * j + k] = t;
		}
}

/* ---- the strips ---- */

struct welder {
	struct stitch *st;
	stitch_emit_fn *emit;
	void *ctx;
	size_t ntri;
	double *ends;       /* strip end edges for the corners, 6 numbers each */
	size_t nends, cap;
};

static void tri(struct welder *w, const double *a, const double *b, const double *c)
{
	if (same(a, b) || same(b, c) || same(a, c))
		return;
	double t[9];
	memcpy(t, a, 3 * sizeof *t);
	memcpy(t + 3, b, 3 * sizeof *t);
	memcpy(t + 6, c, 3 * sizeof *t);
	w->emit(w->ctx, t);
	w->ntri++;
}

static int on_face(const double *box, const double *p, const double *q)
{
	for (int k = 0; k < 3; k++)
		for (int s = 0; s < 2; s++)
			if (p[k] == box[2 * k + s] && q[k] == box[2 * k + s])
				return 1;
	return 0;
}

static void end_edge(struct welder *w, const double *p, const double *q)
{
	if (same(p, q) || on_face(w->st->box, p, q))
		return;
	xgrow(&w->ends, &w->cap, 6 * (w->nends + 1), sizeof *w->ends);
	memcpy(w->ends + 6 * w->nends, p, 3 * sizeof *p);
	memcpy(w->ends + 6 * w->nends + 3, q, 3 * sizeof *q);
	w->nends++;
}

/* Arc-length fractions of the n points of p. */
static double *fractions(const double *p, int n)
{
	double *s = xreallocarray(NULL, (size_t)n, sizeof *s);
	s[0] = 0;
	for (int i = 1; i < n; i++)
		s[i] = s[i - 1] + dist(p + 3 * (i - 1), p + 3 * i);
	double len = s[n - 1];
	for (int i = 0; i < n; i++)
		s[i] = len > 0 ? s[i] / len : (n > 1 ? (double)i / (n - 1) : 0);
	return s;
}

/* The strip between polylines a (na points) and b (nb), a[0] facing b[0]. */
static void zip(struct welder *w, const double *a, int na, const double *b, int nb)
{
	double *sa = fractions(a, na), *sb = fractions(b, nb);
	int i = 0, j = 0;
	while (i < na - 1 || j < nb - 1) {
		if (j == nb - 1 || (i < na - 1 && sa[i + 1] <= sb[j + 1])) {
			tri(w, a + 3 * i, a + 3 * (i + 1), b + 3 * j);
			i++;
		} else {
			tri(w, a + 3 * i, b + 3 * j, b + 3 * (j + 1));
			j++;
		}
	}
	free(sa);
	free(sb);
}

/* A loop as a polyline from its point k round to k again. */
static double *loop_from(const struct chain *c, int k)
{
	double *p = xreallocarray(NULL, 3 * ((size_t)c->n + 1), sizeof *p);
	for (int i = 0; i <= c->n; i++)
		memcpy(p + 3 * i, c->p + 3 * ((k + i) % c->n), 3 * sizeof *p);
	return p;
}

static void zip_loops(struct welder *w, struct chain *a, struct chain *b)
{
	int k = 0;
	for (int i = 1; i < b->n; i++)
		if (dist(a->p, b->p + 3 * i) < dist(a->p, b->p + 3 * k))
			k = i;
	double *pa = loop_from(a, 0), *pb = loop_from(b, k);
	/* the same way round: b's next point nearer a's next than b's last */
	if (b->n > 2 && dist(pa + 3, pb + 3 * (b->n - 1)) < dist(pa + 3, pb + 3)) {
		struct chain t = {pb, b->n + 1, 0, 0};
		reverse(&t);
	}
	zip(w, pa, a->n + 1, pb, b->n + 1);
	free(pa);
	free(pb);
}

/* Pairs the chains below the plane with those above, nearest ends first. */
static void pair_chains(struct welder *w, struct chain *lo, int nlo, struct chain *hi, int nhi)
{
	for (;;) {
		double best = STITCH_MATCH_UM;
		int bi = -1, bj = -1, flip = 0;
		for (int i = 0; i < nlo; i++)
			for (int j = 0; j < nhi && !lo[i].used; j++) {
				if (hi[j].used || lo[i].closed != hi[j].closed)
					continue;
				const struct chain *a = &lo[i], *b = &hi[j];
				const double *a0 = a->p, *a1 = a->p + 3 * (a->n - 1);
				const double *b0 = b->p, *b1 = b->p + 3 * (b->n - 1);
				double d, df = 0;
				if (a->closed) {
					double ca[3] = {0}, cb[3] = {0};
					for (int k = 0; k < 3; k++) {
						for (int m = 0; m < a->n; m++)
							ca[k] += a->p[3 * m + k] / a->n;
						for (int m = 0; m < b->n; m++)
							cb[k] += b->p[3 * m + k] / b->n;
					}
					d = dist(ca, cb);
				} else {
					d = fmax(dist(a0, b0), dist(a1, b1));
					df = fmax(dist(a0, b1), dist(a1, b0));
				}
				if (d < best)
					best = d, bi = i, bj = j, flip = 0;
				if (!a->closed && df < best)
					best = df, bi = i, bj = j, flip = 1;
			}
		if (bi < 0)
			break;
		struct chain *a = &lo[bi], *b = &hi[bj];
		a->used = b->used = 1;
		if (a->closed) {
			zip_loops(w, a, b);
			continue;
		}
		if (flip)
			reverse(b);
		zip(w, a->p, a->n, b->p, b->n);
		end_edge(w, a->p, b->p);
		end_edge(w, a->p + 3 * (a->n - 1), b->p + 3 * (b->n - 1));
	}
	for (int i = 0; i < nlo; i++)
		w->st->unmatched += !lo[i].used;
	for (int j = 0; j < nhi; j++)
		w->st->unmatched += !hi[j].used;
}

static int cmp_edge(const void *pa, const void *pb)
{
	const struct stitch_edge *a = pa, *b = pb;
	if (a->axis != b->axis)
		return a->axis - b->axis;
	if (a->c != b->c)
		return a->c < b->c ? -1 : 1;
	if (a->side != b->side)
		return a->side - b->side;
	return a->tile - b->tile;
}

/* Welds the seam plane of edges e[0..n-1] (one axis and c). */
static void weld_plane(struct welder *w, const struct stitch_edge *e, size_t n)
{
	struct chain *side[2] = {NULL, NULL};
	int ns[2] = {0, 0};
	size_t cap[2] = {0, 0};
	for (size_t i = 0; i < n;) {
		size_t j = i;
		while (j < n && e[j].side == e[i].side && e[j].tile == e[i].tile)
			j++;
		struct chain *c;
		int nc = build_chains(e + i, (int)(j - i), &c);
		int s = e[i].side;
		xgrow(&side[s], &cap[s], (size_t)ns[s] + (size_t)nc, sizeof *side[s]);
		if (nc > 0)
			memcpy(side[s] + ns[s], c, (size_t)nc * sizeof *c);
		ns[s] += nc;
		free(c);
		i = j;
	}
	pair_chains(w, side[0], ns[0], side[1], ns[1]);
	free_chains(side[0], ns[0]);
	free_chains(side[1], ns[1]);
}

static int cmp_end(const void *pa, const void *pb)
{
	const double *a = pa, *b = pb;
	for (int k = 0; k < 2; k++)
		if (a[k] != b[k])
			return a[k] < b[k] ? -1 : 1;
	return 0;
}

/* The strip ends at the corners: cycles of edges on one vertical line,
 * each closed by a fan. */
static void close_corners(struct welder *w)
{
	double *e = w->ends;
	size_t n = w->nends;
	if (n > 1)	/* qsort takes no null array, even empty */
		qsort(e, n, 6 * sizeof *e, cmp_end);
	char *used = xcalloc(n ? n : 1, 1);
	double *path = NULL;
	size_t pcap = 0;
	for (size_t g = 0; g < n;) {
		size_t h = g;
		while (h < n && cmp_end(e + 6 * h, e + 6 * g) == 0)
			h++;
		for (size_t s = g; s < h; s++) {
			if (used[s])
				continue;
			const double *p = e + 6 * s, *q = p + 3;
			if (p[0] != q[0] || p[1] != q[1]) {
				used[s] = 1;
				w->st->corners_open++;
				continue;
			}
			used[s] = 1;
			size_t np = 2;
			xgrow(&path, &pcap, 6, sizeof *path);
			memcpy(path, p, 6 * sizeof *p);
			int closed = 0;
			for (;;) {
				const double *cur = path + 3 * (np - 1);
				size_t k = g;
				for (; k < h; k++)
					if (!used[k] && (same(e + 6 * k, cur) || same(e + 6 * k + 3, cur)))
						break;
				if (k == h)
					break;
				used[k] = 1;
				const double *nx = same(e + 6 * k, cur) ? e + 6 * k + 3 : e + 6 * k;
				if (same(nx, path)) {
					closed = 1;
					break;
				}
				xgrow(&path, &pcap, 3 * (np + 1), sizeof *path);
				memcpy(path + 3 * np++, nx, 3 * sizeof *path);
			}
			if (!closed) {
				w->st->corners_open++;
				continue;
			}
			for (size_t i = 1; i + 1 < np; i++)
				tri(w, path, path + 3 * i, path + 3 * (i + 1));
		}
		g = h;
	}
	free(path);
	free(used);
}

size_t stitch_weld(struct stitch *st, stitch_emit_fn *emit, void *ctx)
{
	struct welder w = {st, emit, ctx, 0, NULL, 0, 0};
	st->unmatched = st->corners_open = 0;
	if (st->n > 1)
		qsort(st->e, st->n, sizeof *st->e, cmp_edge);
	for (size_t i = 0; i < st->n;) {
		size_t j = i;
		while (j < st->n && st->e[j].axis == st->e[i].axis && st->e[j].c == st->e[i].c)
			j++;
		weld_plane(&w, st->e + i, j - i);
		i = j;
	}
	close_corners(&w);
	free(w.ends);
	return w.ntri;
}
