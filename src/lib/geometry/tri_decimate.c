/*
 * tri_decimate.c - half-edge collapse decimation under a quadric error
 * bound (tri_decimate.h).
 *
 * Files: the mesh is tri_decimate_mesh.h, the checks against the input
 * and the collapse itself tri_decimate_input.c, the welding tri_weld.c.
 *
 * Shape: the soup is welded, then each vertex keeps the list of its
 * corners (triangle, slot) as a linked list; a collapse u -> v rewrites u's live
 * corners to v and splices them into v's list, dead corners are skipped
 * where the lists are read and unlinked where a vertex's neighbours are
 * listed (a vertex opposite a collapsed edge would otherwise carry its
 * dead corners to the end, two for each live one).  Every vertex has at most one entry in a
 * binary heap, updated in place: its cheapest collapse by the cost and
 * the box and boundary rules, keyed (cost, vertex); after a collapse
 * u -> v, v and its neighbours are re-evaluated (their triangles or
 * their targets' quadrics changed).  A popped collapse is checked in full
 * before it is made (one that fails re-ranks its vertex by every check),
 * so the order can only miss a collapse that became valid late, never
 * make an invalid one.  On the fast-marching walls about five popped
 * collapses fail (mostly the shape check) for each one made, and each
 * failure re-weighs all of u's candidates: they share one gathering of
 * u's star (star_prep), and the link condition is read off v's
 * triangles against u's marked ring.
 *
 * Vertices whose edges are not all two-sided and consistently oriented,
 * or one-sided off the box (a crack where iso.h dropped a degenerate
 * triangle), never move and never absorb.  A one-sided (boundary) vertex
 * on the box moves only along a boundary edge.
 */
#include "tri_decimate.h"
#include "tri_decimate_mesh.h"
#include "tri_weld.h"
#include "surf.h"
#include "util.h"
#include "vec3.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- geometry ---- */

/* twice the area vector of a b c */
static void normal(const double *a, const double *b, const double *c, double *n)
{
	double u[3], w[3];
	vec3_sub(b, a, u);
	vec3_sub(c, a, w);
	vec3_cross(u, w, n);
}

/* the quality 4 sqrt(3) area / (sum of squared edge lengths) of a b c,
 * whose normal(a, b, c) is n */
static double quality_n(const double *a, const double *b, const double *c, const double *n)
{
	double u[3], w[3], x[3];
	vec3_sub(b, a, u);
	vec3_sub(c, b, w);
	vec3_sub(a, c, x);
	double s = vec3_dot(u, u) + vec3_dot(w, w) + vec3_dot(x, x);
	return s > 0 ? 2 * sqrt(3.0) * sqrt(vec3_dot(n, n)) / s : 0;
}

/* adds the plane through p with unit normal n */
static void q_add_plane(double *q, const double *n, const double *p)
{
	double d = -vec3_dot(n, p);
	double e[4] = {n[0], n[1], n[2], d};
	int k = 0;
	for (int i = 0; i < 4; i++)
		for (int j = i; j < 4; j++)
			q[k++] += e[i] * e[j];
}

/* (qa + qb)(p): the sum of squared distances of p to their planes, the
 * terms of e^T Q e (e = p, 1) in the order aa ab ac ad bb bc bd cc cd dd,
 * written out (the hot loop of consider: a neighbour's cost) */
static double q_eval(const double *qa, const double *qb, const double *p)
{
	double x = p[0], y = p[1], z = p[2], s = 0;
	s += (qa[0] + qb[0]) * x * x;
	s += 2 * (qa[1] + qb[1]) * x * y;
	s += 2 * (qa[2] + qb[2]) * x * z;
	s += 2 * (qa[3] + qb[3]) * x;
	s += (qa[4] + qb[4]) * y * y;
	s += 2 * (qa[5] + qb[5]) * y * z;
	s += 2 * (qa[6] + qb[6]) * y;
	s += (qa[7] + qb[7]) * z * z;
	s += 2 * (qa[8] + qb[8]) * z;
	s += qa[9] + qb[9];
	return s > 0 ? s : 0;
}

/* ---- topology ---- */

/* the distinct neighbours of x into *r, marked with the current stamp;
 * with count, also the triangles x shares with each neighbour w in
 * m->cnt[w] (ring_cnt) */
static size_t ring(struct dmesh *m, int x, int **r, size_t *cap, int count)
{
	m->stamp++;
	size_t k = 0;
	for (int *pc = &m->head[x]; *pc >= 0;) {
		long c = *pc, t = c / 3;
		if (m->tv[3 * t] < 0) {
			*pc = m->next[c];       /* a dead corner: unlinked for good */
			continue;
		}
		pc = &m->next[c];
		for (int s = 0; s < 3; s++) {
			int w = m->tv[3 * t + s];
			if (w == x)
				continue;
			if (m->mark[w] != m->stamp) {
				m->mark[w] = m->stamp;
				if (count)
					m->cnt[w] = 0;
				if (k + 1 > *cap)
					xgrow(r, cap, k + 1, sizeof **r);
				(*r)[k++] = w;
			}
			if (count)
				m->cnt[w]++;
		}
	}
	return k;
}

static size_t ring_of(struct dmesh *m, int x, int **r, size_t *cap)
{
	return ring(m, x, r, cap, 0);
}

static size_t ring_cnt(struct dmesh *m, int x, int **r, size_t *cap)
{
	return ring(m, x, r, cap, 1);
}

/* the checks of the heap's order: the box, the boundary (ns: the
 * triangles holding u and v) and the cost */
static int valid_cheap(const struct dmesh *m, int u, int v, int ns, double *cost)
{
	if ((m->face[u] & ~m->face[v]) || (m->flag[v] & F_LOCKED))
		return 0;
	if (m->flag[u] & F_BOUNDARY) {
		if (ns != 1)    /* a boundary vertex moves along the boundary only */
			return 0;
	} else if (ns != 2)
		return 0;
	double c = q_eval(m->q + 10 * (size_t)u, m->q + 10 * (size_t)v, m->p + 3 * (size_t)v);
	if (!(c <= m->tol2))
		return 0;
	*cost = c;
	return 1;
}

/* u's star as valid_star reads it, computed once for all the collapses
 * of u weighed together: u's live triangles in corner-list order (their
 * vertices, twice the area vector and the quality as they are now), and
 * (when valid first needs them) u's distinct neighbours marked in m->umark */
static void star_prep(struct dmesh *m, int u)
{
	m->su = u;
	m->sring = 0;
	size_t n = 0;
	for (long c = m->head[u]; c >= 0; c = m->next[c]) {
		const int *tv = m->tv + 3 * (c / 3);
		if (tv[0] < 0)
			continue;
		if (n + 1 > m->cstri)
			xgrow(&m->stri, &m->cstri, n + 1, sizeof *m->stri);
		struct star_tri *st = &m->stri[n++];
		memcpy(st->tv, tv, sizeof st->tv);
		const double *a0 = m->p + 3 * (size_t)tv[0], *a1 = m->p + 3 * (size_t)tv[1],
			     *a2 = m->p + 3 * (size_t)tv[2];
		normal(a0, a1, a2, st->n);
		st->q = -1;     /* not yet computed */
	}
	m->nstri = n;
}

/* u's distinct neighbours into m->nbr from the star of star_prep(m, u),
 * with the triangles each shares with u in m->cnt (as ring_cnt) */
static size_t star_ring(struct dmesh *m, int u)
{
	m->stamp++;
	size_t k = 0;
	for (size_t i = 0; i < m->nstri; i++)
		for (int s = 0; s < 3; s++) {
			int w = m->stri[i].tv[s];
			if (w == u)
				continue;
			if (m->mark[w] != m->stamp) {
				m->mark[w] = m->stamp;
				m->cnt[w] = 0;
				if (k + 1 > m->cnbr)
					xgrow(&m->nbr, &m->cnbr, k + 1, sizeof *m->nbr);
				m->nbr[k++] = w;
			}
			m->cnt[w]++;
		}
	return k;
}

/* whether moving u onto v flips none of u's other triangles and makes
 * none thinner than TRI_DECIMATE_QMIN that was not thinner already
 * (after star_prep(m, u)) */
static int shape_ok(struct dmesh *m, int u, int v)
{
	const double *pv = m->p + 3 * (size_t)v;
	for (size_t k = 0; k < m->nstri; k++) {
		struct star_tri *st = &m->stri[k];
		const int *tv = st->tv;
		if (tv[0] == v || tv[1] == v || tv[2] == v)
			continue;
		const double *b[3];
		for (int s = 0; s < 3; s++)
			b[s] = tv[s] == u ? pv : m->p + 3 * (size_t)tv[s];
		double n1[3];
		normal(b[0], b[1], b[2], n1);
		if (!(vec3_dot(st->n, n1) > 0))
			return 0;
		double q1 = quality_n(b[0], b[1], b[2], n1);
		if (q1 >= TRI_DECIMATE_QMIN)
			continue;
		if (st->q < 0)
			st->q = quality_n(m->p + 3 * (size_t)tv[0], m->p + 3 * (size_t)tv[1],
					  m->p + 3 * (size_t)tv[2], st->n);
		if (q1 < st->q)
			return 0;
	}
	return 1;
}

/* whether collapsing u onto v is allowed (after star_prep(m, u)), its
 * cost in *cost: the box, the boundary and the cost (the heap's order;
 * with cheap, already found to pass by consider, at cost *cost), then
 * the orientation, shape and topology (the input vertices and samples
 * are points_ok's) */
static int valid(struct dmesh *m, int u, int v, double *cost, int cheap)
{
	/* the triangles holding u and v, and their third vertices */
	int opp[2], ns = 0;
	for (size_t k = 0; k < m->nstri; k++) {
		const int *tv = m->stri[k].tv;
		if (tv[0] != v && tv[1] != v && tv[2] != v)
			continue;
		if (ns < 2)
			opp[ns] = tv[0] + tv[1] + tv[2] - u - v;
		ns++;
	}
	if (!cheap && !valid_cheap(m, u, v, ns, cost))
		return 0;
	/* the shape first: it fails most often (on the thin triangles of
	 * marching tetrahedra) and needs no ring */
	if (!shape_ok(m, u, v))
		return 0;
	/* link condition: the common neighbours are the opposite vertices */
	if (!m->sring) {        /* u's ring, once per star_prep */
		m->sring = 1;
		m->snu = ring_of(m, u, &m->ring, &m->cring);
		m->ustamp++;
		for (size_t k = 0; k < m->snu; k++)
			m->umark[m->ring[k]] = m->ustamp;
	}
	/* read off v's live triangles (no ring needed): every vertex near
	 * both is an opposite one, and each opposite one is met */
	unsigned met = 0;
	for (long c = m->head[v]; c >= 0; c = m->next[c]) {
		const int *tv = m->tv + 3 * (c / 3);
		if (tv[0] < 0)
			continue;
		for (int s = 0; s < 3; s++) {
			int w = tv[s];
			if (w == v || m->umark[w] != m->ustamp)
				continue;
			if (w == opp[0])
				met |= 1;
			else if (ns == 2 && w == opp[1])
				met |= 2;
			else
				return 0;
		}
	}
	if ((int)((met & 1) + (met >> 1)) != ns)
		return 0;
	if (ns == 2 && m->snu == 3 && ring_of(m, v, &m->ring2, &m->cring2) == 3)
		return 0;       /* a tetrahedron would fold flat */
	return 1;
}

/* ---- heap of (cost, vertex): one entry per vertex, updated in place
 * (a heap of stale entries grows to ten per collapse, and its pops miss
 * the cache on a million-vertex tile) ---- */

struct entry {
	double cost;
	int u, v;
};

struct heap {
	struct entry *e;
	size_t n, cap;
	long *pos;              /* per vertex: its entry's index, -1: none */
};

static int before(const struct entry *a, const struct entry *b)
{
	return a->cost < b->cost || (a->cost == b->cost && a->u < b->u);
}

static void heap_place(struct heap *h, size_t i, struct entry x)
{
	h->e[i] = x;
	h->pos[x.u] = (long)i;
}

static void sift_up(struct heap *h, size_t i, struct entry x)
{
	while (i > 0 && before(&x, &h->e[(i - 1) / 2])) {
		heap_place(h, i, h->e[(i - 1) / 2]);
		i = (i - 1) / 2;
	}
	heap_place(h, i, x);
}

static void sift_down(struct heap *h, size_t i, struct entry x)
{
	for (;;) {
		size_t c = 2 * i + 1;
		if (c >= h->n)
			break;
		if (c + 1 < h->n && before(&h->e[c + 1], &h->e[c]))
			c++;
		if (!before(&h->e[c], &x))
			break;
		heap_place(h, i, h->e[c]);
		i = c;
	}
	heap_place(h, i, x);
}

/* u's entry set to x (x.u == u), added if it had none */
static void heap_set(struct heap *h, struct entry x)
{
	long p = h->pos[x.u];
	if (p < 0) {
		xgrow(&h->e, &h->cap, h->n + 1, sizeof *h->e);
		sift_up(h, h->n++, x);
	} else if (before(&x, &h->e[p]))
		sift_up(h, (size_t)p, x);
	else
		sift_down(h, (size_t)p, x);
}

static void heap_remove(struct heap *h, int u)
{
	long p = h->pos[u];
	if (p < 0)
		return;
	h->pos[u] = -1;
	struct entry x = h->e[--h->n];
	if ((size_t)p == h->n)
		return;
	if (before(&x, &h->e[p]))
		sift_up(h, (size_t)p, x);
	else
		sift_down(h, (size_t)p, x);
}

static struct entry heap_pop(struct heap *h)
{
	struct entry top = h->e[0];
	heap_remove(h, top.u);
	return top;
}

struct cand {
	double cost;
	int v;
};

static int cand_cmp(const void *a, const void *b)
{
	const struct cand *p = a, *q = b;
	if (p->cost != q->cost)
		return p->cost < q->cost ? -1 : 1;
	return (p->v > q->v) - (p->v < q->v);
}

/* pushes u's cheapest collapse: with full 0 the cheapest by the cost
 * alone (checked in full when popped), 1 the cheapest that passes the
 * topology and shape checks (valid), 2 the cheapest that passes every
 * check (valid and points_ok).  failed >= 0: the collapse of u onto
 * failed has just failed those checks on u's star as star_prep(m, u)
 * left it, unchanged since: the star is not gathered again and that
 * candidate is not weighed again (it would fail the same way) */
static void consider_but(struct dmesh *m, struct heap *h, int u, int full, int failed, int prepped)
{
	m->checked[u] = 0;
	m->exact[u] = full == 0;
	if (m->flag[u] & (F_LOCKED | F_DEAD)) {
		heap_remove(h, u);
		return;
	}
	size_t k, nc = 0;
	if (full) {
		/* the star valid needs anyway gives the neighbours too (their
		 * order does not matter: the candidates are sorted) */
		if (!prepped)
			star_prep(m, u);
		k = star_ring(m, u);
	} else
		k = ring_cnt(m, u, &m->nbr, &m->cnbr);
	xgrow(&m->cands, &m->ccands, k + 1, sizeof *m->cands);
	for (size_t i = 0; i < k; i++) {
		double c;
		int w = m->nbr[i];
		if (valid_cheap(m, u, w, m->cnt[w], &c))
			m->cands[nc++] = (struct cand){c, w};
	}
	if (nc == 0) {
		heap_remove(h, u);
		return;
	}
	if (!full) {
		struct cand b = m->cands[0];
		for (size_t i = 1; i < nc; i++)
			if (cand_cmp(&m->cands[i], &b) < 0)
				b = m->cands[i];
		heap_set(h, (struct entry){b.cost, u, b.v});
		return;
	}
	/* a handful of candidates: an insertion sort (cand_cmp is a total
	 * order, so any sort gives this order) */
	for (size_t i = 1; i < nc; i++) {
		struct cand x = m->cands[i];
		size_t j = i;
		for (; j > 0 && cand_cmp(&x, &m->cands[j - 1]) < 0; j--)
			m->cands[j] = m->cands[j - 1];
		m->cands[j] = x;
	}
	for (size_t i = 0; i < nc; i++) {
		double c = m->cands[i].cost;
		if (m->cands[i].v == failed)
			continue;
		if (valid(m, u, m->cands[i].v, &c, 1) && (full < 2 || dm_points_ok(m, u, m->cands[i].v))) {
			heap_set(h, (struct entry){c, u, m->cands[i].v});
			m->checked[u] = 1;
			m->vu[u] = m->ver[u];
			m->vv[u] = m->ver[m->cands[i].v];
			return;
		}
	}
	heap_remove(h, u);
}

static void consider(struct dmesh *m, struct heap *h, int u, int full)
{
	consider_but(m, h, u, full, -1, 0);
}

/* ---- edges at setup ---- */

struct hedge {
	int a, b;               /* a < b */
	int dir;                /* +1: a -> b in its triangle, -1: b -> a */
	long t;
};

static int hedge_cmp(const void *x, const void *y)
{
	const struct hedge *p = x, *q = y;
	if (p->a != q->a)
		return p->a < q->a ? -1 : 1;
	if (p->b != q->b)
		return p->b < q->b ? -1 : 1;
	return (p->t > q->t) - (p->t < q->t);
}

static void classify(struct dmesh *m, struct tri_decimate_stats *st)
{
	/* the edges sorted by (a, b, t) (the boundary planes are summed in
	 * that order): bucketed by a, then each bucket (a vertex's few
	 * edges) by insertion; the keys are distinct, so this is qsort's
	 * order */
	size_t ne = 3 * m->nt;
	struct hedge *e = xreallocarray(NULL, ne + 1, sizeof *e);
	size_t *first = xcalloc(m->nv + 2, sizeof *first);
	for (size_t c = 0; c < ne; c++) {
		int a = m->tv[c], b = m->tv[c - c % 3 + (c % 3 + 1) % 3];
		first[(a < b ? a : b) + 2]++;
	}
	for (size_t i = 0; i < m->nv; i++)
		first[i + 2] += first[i + 1];
	for (size_t t = 0; t < m->nt; t++)
		for (int s = 0; s < 3; s++) {
			int a = m->tv[3 * t + s], b = m->tv[3 * t + (s + 1) % 3];
			e[first[(a < b ? a : b) + 1]++] = a < b ? (struct hedge){a, b, 1, (long)t}
								: (struct hedge){b, a, -1, (long)t};
		}
	for (size_t i = 0; i < m->nv; i++)
		for (size_t k = first[i] + 1; k < first[i + 1]; k++) {
			struct hedge x = e[k];
			size_t j = k;
			for (; j > first[i] && hedge_cmp(&x, &e[j - 1]) < 0; j--)
				e[j] = e[j - 1];
			e[j] = x;
		}
	free(first);
	int *nb = xcalloc(m->nv + 1, sizeof *nb);
	for (size_t i = 0; i < ne;) {
		size_t j = i;
		while (j < ne && e[j].a == e[i].a && e[j].b == e[i].b)
			j++;
		int a = e[i].a, b = e[i].b;
		if (j - i == 1) {
			st->boundary_edges++;
			nb[a]++;
			nb[b]++;
			m->flag[a] |= F_BOUNDARY;
			m->flag[b] |= F_BOUNDARY;
			if (!(m->face[a] & m->face[b])) {
				/* a crack off the box, or a boundary leaving a face */
				m->flag[a] |= F_LOCKED;
				m->flag[b] |= F_LOCKED;
			}
			/* the plane through the edge normal to its triangle */
			const int *tv = m->tv + 3 * e[i].t;
			double n[3], d[3], w[3];
			normal(m->p + 3 * (size_t)tv[0], m->p + 3 * (size_t)tv[1], m->p + 3 * (size_t)tv[2], n);
			vec3_sub(m->p + 3 * (size_t)b, m->p + 3 * (size_t)a, d);
			vec3_cross(n, d, w);
			double l = sqrt(vec3_dot(w, w));
			if (l > 0) {
				for (int k = 0; k < 3; k++)
					w[k] /= l;
				q_add_plane(m->q + 10 * (size_t)a, w, m->p + 3 * (size_t)a);
				q_add_plane(m->q + 10 * (size_t)b, w, m->p + 3 * (size_t)a);
			}
		} else if (j - i > 2 || e[i].dir == e[i + 1].dir) {
			m->flag[a] |= F_LOCKED;
			m->flag[b] |= F_LOCKED;
		}
		i = j;
	}
	free(e);
	/* a boundary vertex needs exactly two boundary edges to slide on */
	for (size_t i = 0; i < m->nv; i++)
		if (nb[i] != 0 && nb[i] != 2)
			m->flag[i] |= F_LOCKED;
	free(nb);
}

/* The decimator's arrays for the welded mesh m of nt triangles: the
 * input triangles' bounding spheres and CSR lists (the sample check),
 * the box faces and locked sides of each vertex, the vertex-to-corner
 * lists and each vertex's quadric (the sum of its triangles' planes). */
static void setup(struct dmesh *mp, size_t nt, double tol, const double box[6],
		  double box_eps, const double keep[4])
{
	struct dmesh m = *mp;
	m.q = xcalloc(10 * m.nv + 1, sizeof *m.q);
	m.face = xcalloc(m.nv + 1, 1);
	m.flag = xcalloc(m.nv + 1, 1);
	m.mark = xcalloc(m.nv + 1, sizeof *m.mark);
	m.umark = xcalloc(m.nv + 1, sizeof *m.umark);
	m.tmark = xcalloc(nt + 1, sizeof *m.tmark);
	m.cnt = xcalloc(m.nv + 1, sizeof *m.cnt);
	m.exact = xcalloc(m.nv + 1, 1);
	m.ver = xcalloc(m.nv + 1, sizeof *m.ver);
	m.checked = xcalloc(m.nv + 1, 1);
	m.vu = xcalloc(m.nv + 1, sizeof *m.vu);
	m.vv = xcalloc(m.nv + 1, sizeof *m.vv);
	m.head = xreallocarray(NULL, m.nv + 1, sizeof *m.head);
	m.next = xreallocarray(NULL, 3 * nt + 1, sizeof *m.next);
	m.tol = tol;
	m.otv = xreallocarray(NULL, 3 * nt + 1, sizeof *m.otv);
	memcpy(m.otv, m.tv, 3 * nt * sizeof *m.otv);
	m.ostart = xcalloc(m.nv + 2, sizeof *m.ostart);
	m.otri = xreallocarray(NULL, 3 * nt + 1, sizeof *m.otri);
	m.osph = xreallocarray(NULL, 4 * nt + 1, sizeof *m.osph);
	for (size_t t = 0; t < nt; t++) {
		const int *a = m.tv + 3 * t;
		float *b = m.osph + 4 * t;
		double r = 0;
		for (int d = 0; d < 3; d++)
			b[d] = (float)((m.p[3 * (size_t)a[0] + d] + m.p[3 * (size_t)a[1] + d] +
					m.p[3 * (size_t)a[2] + d]) / 3);
		for (int s2 = 0; s2 < 3; s2++) {
			const double *x = m.p + 3 * (size_t)a[s2];
			double e[3] = {x[0] - b[0], x[1] - b[1], x[2] - b[2]};
			r = fmax(r, sqrt(vec3_dot(e, e)));
		}
		/* float rounding of the centre and radius: a relative 1e-6 of
		 * the coordinates more keeps the sphere around the triangle */
		double mag = fabs(b[0]) + fabs(b[1]) + fabs(b[2]) + r;
		b[3] = (float)(r + 1e-6 * mag);
	}
	for (size_t c = 0; c < 3 * nt; c++)
		m.ostart[m.tv[c] + 2]++;
	for (size_t i = 0; i < m.nv; i++)
		m.ostart[i + 2] += m.ostart[i + 1];
	for (size_t c = 0; c < 3 * nt; c++)
		m.otri[m.ostart[m.tv[c] + 1]++] = (int)(c / 3);
	m.tol2 = 0.5 * tol * tol;
	m.thead = xreallocarray(NULL, nt + 1, sizeof *m.thead);
	m.pnext = xreallocarray(NULL, m.nv + 1, sizeof *m.pnext);
	for (size_t t = 0; t < nt; t++)
		m.thead[t] = -1;
	if (box)
		for (size_t i = 0; i < m.nv; i++)
			for (int f = 0; f < 6; f++)
				if (fabs(m.p[3 * i + f / 2] - box[f]) <= box_eps)
					m.face[i] |= (unsigned char)(1u << f);
	if (keep)
		for (size_t i = 0; i < m.nv; i++)
			for (int f = 0; f < 4; f++)
				if (fabs(m.p[3 * i + f / 2] - keep[f]) <= box_eps)
					m.flag[i] |= F_LOCKED;
	for (size_t i = 0; i < m.nv; i++)
		m.head[i] = -1;
	for (size_t c = 3 * nt; c-- > 0;) {
		int w = m.tv[c];
		m.next[c] = m.head[w];
		m.head[w] = (int)c;
	}
	for (size_t t = 0; t < nt; t++) {
		const int *a = m.tv + 3 * t;
		double nn[3];
		normal(m.p + 3 * (size_t)a[0], m.p + 3 * (size_t)a[1], m.p + 3 * (size_t)a[2], nn);
		double l = sqrt(vec3_dot(nn, nn));
		if (!(l > 0))
			continue;
		for (int k = 0; k < 3; k++)
			nn[k] /= l;
		for (int s = 0; s < 3; s++)
			q_add_plane(m.q + 10 * (size_t)a[s], nn, m.p + 3 * (size_t)a[0]);
	}
	*mp = m;
}

/* Collapses the cheapest valid edge of m until none is left within tol
 * (Garland-Heckbert order, every collapse checked against the input
 * triangles). */
static void collapse_all(struct dmesh *mp)
{
	struct dmesh m = *mp;
	struct heap h = {NULL, 0, 0, xreallocarray(NULL, m.nv + 1, sizeof *h.pos)};
	for (size_t i = 0; i < m.nv; i++)
		h.pos[i] = -1;
	for (size_t i = 0; i < m.nv; i++)
		consider(&m, &h, (int)i, 0);
	int *nb = NULL, *nbc = NULL;
	size_t cnb = 0, cnbc = 0;
	while (h.n) {
		struct entry e = heap_pop(&h);
		m.exact[e.u] = 0;
		double c;
		/* a failed collapse re-ranks u by the checks it failed:
		 * the topology and shape alone (the input checks, which
		 * rarely fail, run when the new entry is popped), or
		 * those and the input checks */
		/* an entry that passed valid with u's and v's stars as they
		 * are now (their versions) passes it again */
		int prepped = !(m.checked[e.u] && m.vu[e.u] == m.ver[e.u] && m.vv[e.u] == m.ver[e.v]);
		if (prepped) {
			star_prep(&m, e.u);
			if (!valid(&m, e.u, e.v, &c, 0)) {
				consider_but(&m, &h, e.u, 1, e.v, 1);
				continue;
			}
		}
		if (!dm_points_ok(&m, e.u, e.v)) {
			consider_but(&m, &h, e.u, 2, e.v, prepped);
			continue;
		}
		dm_collapse(&m, e.u, e.v);
		consider(&m, &h, e.v, 0);
		/* v's neighbours: only their collapses onto v (v's
		 * quadric and the triangles they share with it changed)
		 * or onto u (gone) are not as they were, so one whose
		 * entry is consider(, 0)'s and aims at neither needs
		 * only its collapse onto v weighed against it (the
		 * same entry as a full consider) */
		size_t k = ring_cnt(&m, e.v, &nb, &cnb);
		xgrow(&nbc, &cnbc, k + 1, sizeof *nbc);
		/* the stars that changed: v's and its neighbours' (every
		 * triangle rewritten or dropped holds v now, or held u and v) */
		m.ver[e.v]++;
		for (size_t i = 0; i < k; i++) {
			nbc[i] = m.cnt[nb[i]];  /* consider changes m.cnt */
			m.ver[nb[i]]++;
		}
		for (size_t i = 0; i < k; i++) {
			int w = nb[i];
			long p = h.pos[w];
			if (!m.exact[w] || (p >= 0 && (h.e[p].v == e.u || h.e[p].v == e.v))) {
				consider(&m, &h, w, 0);
				continue;
			}
			if (m.flag[w] & (F_LOCKED | F_DEAD))
				continue;
			if (!valid_cheap(&m, w, e.v, nbc[i], &c))
				continue;
			struct cand a = {c, e.v};
			if (p < 0 || cand_cmp(&a, &(struct cand){h.e[p].cost, h.e[p].v}) < 0) {
				heap_set(&h, (struct entry){c, w, e.v});
				m.checked[w] = 0;
			}
		}
	}
	free(nb);
	free(nbc);
	free(h.e);
	free(h.pos);
	*mp = m;
}

/* the live triangles of m into v, 9 doubles each, in order */
static size_t write_soup(const struct dmesh *m, double *v)
{
	size_t o = 0;
	for (size_t t = 0; t < m->nt; t++) {
		const int *a = m->tv + 3 * t;
		if (a[0] < 0)
			continue;
		for (int s = 0; s < 3; s++)
			memcpy(v + 9 * o + 3 * s, m->p + 3 * (size_t)a[s], 3 * sizeof *v);
		o++;
	}
	return o;
}

/* the live triangles of m, in order, as a tri_mesh of the vertices they
 * use (renumbered in the order of first use; m->mark is reused) */
static size_t write_mesh(struct dmesh *m, struct tri_mesh *out)
{
	size_t nt = 0, nv = 0;
	for (size_t t = 0; t < m->nt; t++)
		nt += m->tv[3 * t] >= 0;
	int *num = (int *)m->mark;      /* unsigned per vertex: the new numbers */
	for (size_t i = 0; i < m->nv; i++)
		num[i] = -1;
	out->tv = xreallocarray(NULL, 3 * nt + 1, sizeof *out->tv);
	size_t o = 0;
	for (size_t t = 0; t < m->nt; t++) {
		const int *a = m->tv + 3 * t;
		if (a[0] < 0)
			continue;
		for (int s = 0; s < 3; s++) {
			if (num[a[s]] < 0)
				num[a[s]] = (int)nv++;
			out->tv[3 * o + (size_t)s] = num[a[s]];
		}
		o++;
	}
	out->p = xreallocarray(NULL, 3 * nv + 1, sizeof *out->p);
	for (size_t i = 0; i < m->nv; i++)
		if (num[i] >= 0)
			memcpy(out->p + 3 * (size_t)num[i], m->p + 3 * i, 3 * sizeof *out->p);
	out->nv = nv;
	out->nt = nt;
	return nt;
}

static void dmesh_free(struct dmesh *m)
{
	free(m->p);
	free(m->q);
	free(m->face);
	free(m->flag);
	free(m->mark);
	free(m->umark);
	free(m->tmark);
	free(m->tset);
	free(m->stri);
	free(m->cnt);
	free(m->exact);
	free(m->ver);
	free(m->checked);
	free(m->vu);
	free(m->vv);
	free(m->head);
	free(m->next);
	free(m->tv);
	free(m->ring);
	free(m->ring2);
	free(m->thead);
	free(m->nbr);
	free(m->phint);
	free(m->cands);
	free(m->otv);
	free(m->ostart);
	free(m->otri);
	free(m->osph);
	free(m->pnext);
	free(m->star);
	free(m->pts);
}

/* the welded mesh (p, nv, tv, n) decimated, taking over p and tv: its
 * triangles kept go to soup (9 doubles each, at most n) or, with soup
 * NULL, to mesh */
static size_t decimate(double *p, size_t nv, int *tv, size_t n, double tol, const double box[6],
		       double box_eps, const double keep[4], struct tri_decimate_stats *stp,
		       double *soup, struct tri_mesh *mesh)
{
	struct tri_decimate_stats st = {0, 0, 0, 0, 0};
	struct dmesh m = {0};
	if (n > INT_MAX / 3)    /* the corner lists are of int */
		die("tri_decimate: %zu triangles, more than %d", n, INT_MAX / 3);
	m.nv = nv;
	m.p = p;
	m.tv = tv;
	/* drop the triangles welding made degenerate */
	size_t nt = 0;
	for (size_t t = 0; t < n; t++) {
		int *a = m.tv + 3 * t;
		if (a[0] == a[1] || a[1] == a[2] || a[0] == a[2])
			continue;
		memmove(m.tv + 3 * nt, a, 3 * sizeof *a);
		nt++;
	}
	m.nt = nt;
	st.vertices = m.nv;
	st.in = nt;
	setup(&m, nt, tol, box, box_eps, keep);
	classify(&m, &st);
	for (size_t i = 0; i < m.nv; i++)
		if (m.flag[i] & F_LOCKED)
			st.locked++;
	if (tol > 0)
		collapse_all(&m);
	size_t o = soup ? write_soup(&m, soup) : write_mesh(&m, mesh);
	st.out = o;
	if (stp)
		*stp = st;
	dmesh_free(&m);
	return o;
}

size_t tri_decimate(double *v, size_t n, double tol, double weld_eps, const double box[6],
		    double box_eps, const double keep[4], struct tri_decimate_stats *stp)
{
	double *p;
	int *tv;
	size_t nv = tri_weld(v, n, weld_eps, &p, &tv);
	return decimate(p, nv, tv, n, tol, box, box_eps, keep, stp, v, NULL);
}

size_t tri_decimate_welded(struct tri_weld *w, double tol, const double box[6], double box_eps,
			   const double keep[4], struct tri_decimate_stats *st, struct tri_mesh *out)
{
	double *p;
	int *tv;
	size_t n;
	size_t nv = tri_weld_take(w, &p, &tv, &n);
	return decimate(p, nv, tv, n, tol, box, box_eps, keep, st, NULL, out);
}

size_t tri_decimate_mesh(const struct tri_mesh *in, double tol, const double box[6], double box_eps,
			 const double keep[4], struct tri_decimate_stats *st, struct tri_mesh *out)
{
	/* decimate works on (and frees) its own vertices and triangles */
	double *p = xreallocarray(NULL, 3 * in->nv + 1, sizeof *p);
	int *tv = xreallocarray(NULL, 3 * in->nt + 1, sizeof *tv);
	memcpy(p, in->p, 3 * in->nv * sizeof *p);
	memcpy(tv, in->tv, 3 * in->nt * sizeof *tv);
	return decimate(p, in->nv, tv, in->nt, tol, box, box_eps, keep, st, NULL, out);
}

void tri_mesh_free(struct tri_mesh *m)
{
	free(m->p);
	free(m->tv);
	m->p = NULL;
	m->tv = NULL;
	m->nv = m->nt = 0;
}
