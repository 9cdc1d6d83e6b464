/*
 * deloop_grid.c - the full search for the self-intersections of the
 * ray-string mesh (deloop.h, stage 1): every segment that pierces a
 * triangle it does not touch, by the exact segment/triangle test, through
 * a hashed grid of the triangles searched by the threads (par.h).
 */
#include "deloop_grid.h"

#include "par.h"
#include "util.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Grid cell edge in mean edge lengths: a triangle's box then spans one
 * or two cells per axis, and a segment's box as many, so each query looks
 * at a handful of triangles.  2 rather than 1.5: each triangle is listed
 * in fewer cells (3.4 M entries for 1.4 M triangles against 4.4 M), and
 * the search, which reads the boxes of a cell without branches, gains
 * more from that than it loses to fuller cells (0.3 s at 1.4 M
 * triangles). */
#define GRID_CELL_SEGS 2.0
/* Barycentric slack of the crossing test: rounding of the determinants
 * of nodes of order 1 um apart is ~1e-16 relative; this is far above it
 * and far below any real distance from a triangle's edge. */
#define BARY_EPS 1e-9
/* Sine of the angle under which a segment counts as lying in a
 * triangle's plane: rounding is ~1e-16, real crossings are steeper than
 * 1e-9 by far. */
#define PLANE_EPS 1e-9

/* Whether segment pq meets triangle abc, boundaries included (two
 * sheets mirror images of each other, as two seeds grow, cross exactly
 * on each other's segments: a strict test would miss every crossing),
 * but not lying in its plane; *u the fraction from p. */
static int pierce(const double *p, const double *q, const double *a, const double *b,
		  const double *c, double *u)
{
	double sp = orient(a, b, c, p), sq = orient(a, b, c, q);
	if (!((sp >= 0 && sq <= 0) || (sp <= 0 && sq >= 0)))
		return 0;
	/* a segment in the triangle's plane (rows of nodes along a straight
	 * front, a wall) only touches it: sp - sq = n . (p - q) must be more
	 * than rounding of the angle between them */
	double u1[3], v1[3], w1[3], n[3];
	vec3_sub(b, a, u1);
	vec3_sub(c, a, v1);
	vec3_sub(q, p, w1);
	vec3_cross(u1, v1, n);
	double scale = sqrt(vec3_dot(n, n) * vec3_dot(w1, w1));
	if (!(fabs(sp - sq) > PLANE_EPS * scale))
		return 0;
	/* the e's over their sum are the barycentric coordinates of the
	 * crossing point: a point on an edge is in both triangles on it even
	 * when rounding puts it a hair outside each */
	double e1 = orient(p, q, a, b), e2 = orient(p, q, b, c), e3 = orient(p, q, c, a);
	double sum = e1 + e2 + e3;
	if (!(fabs(sum) > 0))
		return 0;
	if (e1 / sum < -BARY_EPS || e2 / sum < -BARY_EPS || e3 / sum < -BARY_EPS)
		return 0;
	*u = sp / (sp - sq);
	return 1;
}

/* The node positions of m, copied into one array: the searches read
 * them in a scattered order, and the nodes' own records are three times
 * their size.  Free it. */
double (*dl_node_positions(const struct mesh *m))[3]
{
	double (*P)[3] = xreallocarray(NULL, m->nnode + 1, sizeof *P);
	for (size_t i = 0; i < m->nnode; i++)
		memcpy(P[i], m->node[i].p, sizeof P[i]);
	return P;
}


/* Whether segment s crosses triangle t of m (pierce), the two sharing no
 * node; if so, the crossing in *x.  P: the node positions. */
static int seg_pierce_nodes(const double (*P)[3], int s, const int *sn, int t, const int *tn,
			    struct deloop_pierce *x)
{
	for (int a = 0; a < 3; a++)
		if (tn[a] == sn[0] || tn[a] == sn[1])
			return 0;
	const double *p = P[sn[0]], *q = P[sn[1]];
	double u;
	if (!pierce(p, q, P[tn[0]], P[tn[1]], P[tn[2]], &u))
		return 0;
	x->s = s;
	x->t = t;
	x->u = u;
	for (int d = 0; d < 3; d++)
		x->x[d] = p[d] + u * (q[d] - p[d]);
	return 1;
}

/* the same, s and t given by their index in m */
int dl_seg_pierce(const struct mesh *m, const double (*P)[3], int s, int t,
		      struct deloop_pierce *x)
{
	return seg_pierce_nodes(P, s, m->seg[s].n, t, m->tri[t].n, x);
}

/* A hashed grid of the alive triangles: cells about GRID_CELL_SEGS mean
 * edges across, fixed by the mesh alone, only the occupied ones stored
 * (a surface fills a vanishing part of its box, so a dense array of cells
 * this small would not fit, and a coarser one puts ever more triangles in
 * a cell as the mesh grows: n^1.5).  Cell keys
 * (cell_key, Morton order) hash into an open-addressed table of 2^k
 * slots, each with the cell's rank in key order; the triangles of the
 * cell of rank r are box/ref[start[r] .. start[r + 1]).  Which cells a
 * triangle is listed in does not change the pierces found (every pair
 * with overlapping boxes meets in some cell, and the list is sorted at
 * the end), only the time.
 *
 * Where the time of a search goes (1.4 M triangles, 2.1 M segments, with
 * a plainer grid): less into the pierce tests (8 M) than into reading
 * memory in a scattered order - the nodes of each segment and triangle,
 * the hash table, the cells - and in the 170 M boxes scanned.  Hence the
 * node positions copied into one array (dl_node_positions), the segments
 * visited in cell order with their boxes at hand (struct qrec), the
 * cells in Morton order with a small cache of their ranks, the boxes of
 * a cell apart from the rest and tested without branches, and each pair
 * tested once by rule rather than through a per-triangle stamp. */

/* The float box of [lo, hi], rounded outward so that it still contains
 * it. */
/* nextafterf(f, -INFINITY) and nextafterf(f, INFINITY) for f not NaN,
 * through the bits (a call to libm per box end was 2 % of an etch run) */
static float float_down(float f)
{
	uint32_t u;
	memcpy(&u, &f, sizeof u);
	u = f > 0 ? u - 1 : f < 0 ? u + 1 : 0x80000001u;       /* 0: -denormal */
	memcpy(&f, &u, sizeof f);
	return f;
}

static float float_up(float f)
{
	uint32_t u;
	memcpy(&u, &f, sizeof u);
	u = f < 0 ? u - 1 : f > 0 ? u + 1 : 0x00000001u;
	memcpy(&f, &u, sizeof f);
	return f;
}

static struct gitem item_of_box(const double *lo, const double *hi)
{
	struct gitem it = {{0}, {0}, -1, {-1, -1, -1}};
	for (int d = 0; d < 3; d++) {
		it.lo[d] = (float)lo[d];
		if ((double)it.lo[d] > lo[d])
			it.lo[d] = float_down(it.lo[d]);
		it.hi[d] = (float)hi[d];
		if ((double)it.hi[d] < hi[d])
			it.hi[d] = float_up(it.hi[d]);
	}
	return it;
}


/* The grid item of triangle t of m with box [lo, hi], rounded outward to
 * float so that it still contains the box. */
struct gitem dl_item_of(const struct mesh *m, int t, const double *lo, const double *hi)
{
	struct gitem it = item_of_box(lo, hi);
	it.t = t;
	for (int a = 0; a < 3; a++)
		it.n[a] = m->tri[t].n[a];
	return it;
}

static size_t cell_hash(const struct grid *g, long long key)
{
	unsigned long long x = (unsigned long long)key * 0x9E3779B97F4A7C15ull;
	return (size_t)(x ^ (x >> 29)) & g->mask;
}

/* the slot of key, or of the empty slot where it would go */
static size_t cell_slot(const struct grid *g, long long key)
{
	size_t q = cell_hash(g, key);
	while (g->slot[q].key != key && g->slot[q].key != -1)
		q = (q + 1) & g->mask;
	return q;
}

/* the grid's construction, by the threads over ranges of triangles */
struct grid_job {
	struct grid *g;
	const struct mesh *m;
	const double (*P)[3];
	struct gitem *tit;      /* per triangle: its item (t -1: dead) */
	double (*tb)[6];        /* per triangle: its box, or NULL */
	double (*wbox)[6];      /* per worker: the box of its triangles */
	double *cnt;            /* per triangle: its cell entries */
	int (*c0)[3];           /* per triangle: its lowest cell */
	const size_t *off;      /* per triangle: its first entry */
	struct ekey {
		unsigned long long key;
		int t;
	} *ek;
};

/* the items, and in cnt the triangles' perimeters */
static void item_range(void *ctx, size_t lo, size_t hi, int w)
{
	struct grid_job *j = ctx;
	double *wb = j->wbox[w];
	for (int d = 0; d < 3; d++) {
		wb[d] = INFINITY;
		wb[3 + d] = -INFINITY;
	}
	for (size_t t = lo; t < hi; t++) {
		j->cnt[t] = 0;
		if (!j->m->tri[t].alive) {
			j->tit[t].t = -1;
			continue;
		}
		double blo[3], bhi[3];
		tri_box(j->m, j->P, (int)t, blo, bhi);
		j->tit[t] = dl_item_of(j->m, (int)t, blo, bhi);
		if (j->tb) {
			memcpy(j->tb[t], blo, sizeof blo);
			memcpy(j->tb[t] + 3, bhi, sizeof bhi);
		}
		for (int d = 0; d < 3; d++) {
			wb[d] = blo[d] < wb[d] ? blo[d] : wb[d];
			wb[3 + d] = bhi[d] > wb[3 + d] ? bhi[d] : wb[3 + d];
		}
		const int *n = j->m->tri[t].n;
		for (int a = 0; a < 3; a++) {
			const double *p = j->P[n[a]], *q = j->P[n[(a + 1) % 3]];
			double dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2];
			j->cnt[t] += sqrt(dx * dx + dy * dy + dz * dz);
		}
	}
}

/* the cells of item b (its float box, which holds the triangle's) */
static void item_cells(const struct grid *g, const struct gitem *b, long c0[3], long c1[3])
{
	double blo[3] = {b->lo[0], b->lo[1], b->lo[2]}, bhi[3] = {b->hi[0], b->hi[1], b->hi[2]};
	cell_range(g, blo, bhi, c0, c1);
}

static void count_range(void *ctx, size_t lo, size_t hi, int w)
{
	(void)w;
	struct grid_job *j = ctx;
	for (size_t t = lo; t < hi; t++) {
		j->cnt[t] = 0;
		if (j->tit[t].t < 0)
			continue;
		long c0[3], c1[3];
		item_cells(j->g, &j->tit[t], c0, c1);
		for (int d = 0; d < 3; d++)
			j->c0[t][d] = (int)c0[d];
		j->cnt[t] = (double)(c1[0] - c0[0] + 1) * (double)(c1[1] - c0[1] + 1) *
			    (double)(c1[2] - c0[2] + 1);
	}
}

static void fill_range(void *ctx, size_t lo, size_t hi, int w)
{
	(void)w;
	struct grid_job *j = ctx;
	for (size_t t = lo; t < hi; t++) {
		if (j->tit[t].t < 0)
			continue;
		long c0[3], c1[3];
		item_cells(j->g, &j->tit[t], c0, c1);
		size_t e = j->off[t];
		for (long k = c0[2]; k <= c1[2]; k++)
			for (long jj = c0[1]; jj <= c1[1]; jj++)
				for (long i = c0[0]; i <= c1[0]; i++) {
					j->ek[e].key = (unsigned long long)cell_key(j->g, i, jj, k);
					j->ek[e++].t = (int)t;
				}
	}
}

/* The largest cell index of g (cell_key). */
static unsigned long long grid_kmax(const struct grid *g)
{
	int bits = 0;
	while (bits < GRID_AXIS_BITS && ((1L << bits) < g->n[0] || (1L << bits) < g->n[1] ||
					 (1L << bits) < g->n[2]))
		bits++;
	return (1ull << 3 * bits) - 1;
}

/* ek[0 .. n) sorted by key (at most kmax), stably: LSD radix, 16 bits a
 * pass, through tmp (n long).  Returns the sorted array, ek or tmp; frees
 * the other. */
static struct ekey *ekey_sort(struct ekey *ek, struct ekey *tmp, size_t n, unsigned long long kmax)
{
	size_t *bucket = xreallocarray(NULL, 65536 + 1, sizeof *bucket);
	for (int shift = 0; shift < 64 && (kmax >> shift) > 0; shift += 16) {
		memset(bucket, 0, (65536 + 1) * sizeof *bucket);
		for (size_t x = 0; x < n; x++)
			bucket[((ek[x].key >> shift) & 0xffff) + 1]++;
		for (size_t q = 0; q < 65536; q++)
			bucket[q + 1] += bucket[q];
		for (size_t x = 0; x < n; x++)
			tmp[bucket[(ek[x].key >> shift) & 0xffff]++] = ek[x];
		struct ekey *sw = ek;
		ek = tmp;
		tmp = sw;
	}
	free(bucket);
	free(tmp);
	return ek;
}

/* Triangles per thread at least, building the grid. */
#define GRID_MIN_TRIS 4096

/* the cell entries of the alive triangles at the grid's cell size, per
 * triangle in j->cnt, and their total */
static double grid_entries(struct grid_job *j)
{
	par_for(j->m->ntri, GRID_MIN_TRIS, count_range, j);
	double total = 0;
	for (size_t t = 0; t < j->m->ntri; t++)
		total += j->cnt[t];
	return total;
}

static void grid_build(struct grid *g, const struct mesh *m, const double (*P)[3],
		       double (*tb)[6])
{
	memset(g, 0, sizeof *g);
	int nw = par_threads();
	struct grid_job job = {g, m, P, xreallocarray(NULL, m->ntri + 1, sizeof *job.tit), tb,
			       xcalloc((size_t)nw, sizeof *job.wbox),
			       xreallocarray(NULL, m->ntri + 1, sizeof *job.cnt),
			       xreallocarray(NULL, m->ntri + 1, sizeof *job.c0), NULL, NULL};
	for (int w = 0; w < nw; w++)
		for (int d = 0; d < 3; d++) {
			job.wbox[w][d] = INFINITY;
			job.wbox[w][3 + d] = -INFINITY;
		}
	par_for(m->ntri, GRID_MIN_TRIS, item_range, &job);
	/* the triangles' box, and their mean edge (the mean segment length
	 * but for the border segments, counted once) */
	double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
	for (int w = 0; w < nw; w++)
		for (int d = 0; d < 3; d++) {
			lo[d] = fmin(lo[d], job.wbox[w][d]);
			hi[d] = fmax(hi[d], job.wbox[w][3 + d]);
		}
	free(job.wbox);
	double len = 0;
	size_t ntri = 0;
	for (size_t t = 0; t < m->ntri; t++) {
		len += job.cnt[t];
		ntri += m->tri[t].alive != 0;
	}
	double h = ntri ? GRID_CELL_SEGS * len / (3.0 * (double)ntri) : 1;
	double ext[3];
	for (int d = 0; d < 3; d++) {
		ext[d] = hi[d] > lo[d] ? hi[d] - lo[d] : 0;
		g->lo[d] = lo[d] > -INFINITY && lo[d] < INFINITY ? lo[d] : 0;
	}
	if (!(h > 0))
		h = 1;
	/* cell indices stay far inside a long long, and the triangles'
	 * boxes within GRID_ENTRIES_PER_TRI cells each on average */
	for (;;) {
		double cells = 1;
		for (int d = 0; d < 3; d++)
			cells *= floor(ext[d] / h) + 1;
		if (cells < 1e15 && floor(ext[0] / h) < (1L << GRID_AXIS_BITS) &&
		    floor(ext[1] / h) < (1L << GRID_AXIS_BITS) &&
		    floor(ext[2] / h) < (1L << GRID_AXIS_BITS)) {
			g->h = h;
			for (int d = 0; d < 3; d++)
				g->n[d] = (long)floor(ext[d] / h) + 1;
			if (grid_entries(&job) <= GRID_ENTRIES_PER_TRI * (double)ntri + 64)
				break;
		}
		h *= 2;
	}
	/* the entries (cell index, triangle) in the triangles' order, sorted
	 * by cell index (LSD radix, 16 bits a pass: stable, so a cell's
	 * triangles stay in increasing order), then the occupied cells
	 * hashed once each */
	size_t *off = xreallocarray(NULL, m->ntri + 1, sizeof *off), ne = 0;
	for (size_t t = 0; t < m->ntri; t++) {
		off[t] = ne;
		ne += (size_t)job.cnt[t];
	}
	free(job.cnt);
	struct ekey *ek = xreallocarray(NULL, ne + 1, sizeof *ek),
		    *tmp = xreallocarray(NULL, ne + 1, sizeof *tmp);
	job.off = off;
	job.ek = ek;
	par_for(m->ntri, GRID_MIN_TRIS, fill_range, &job);
	free(off);
	ek = ekey_sort(ek, tmp, ne, grid_kmax(g));
	g->box = xreallocarray(NULL, ne + 1, sizeof *g->box);
	g->ref = xreallocarray(NULL, ne + 1, sizeof *g->ref);
	size_t nocc = 0;
	for (size_t x = 0; x < ne; x++) {
		const struct gitem *it = &job.tit[ek[x].t];
		memcpy(g->box[x].lo, it->lo, sizeof it->lo);
		memcpy(g->box[x].hi, it->hi, sizeof it->hi);
		const int *c0 = job.c0[ek[x].t];
		g->ref[x] = (struct gref){it->t, {it->n[0], it->n[1], it->n[2]}, {c0[0], c0[1], c0[2]}};
		nocc += x == 0 || ek[x].key != ek[x - 1].key;
	}
	free(job.tit);
	free(job.c0);
	size_t slots = 1024;
	while (slots < 2 * nocc)
		slots *= 2;
	g->mask = slots - 1;
	g->nocc = nocc;
	g->slot = xreallocarray(NULL, slots, sizeof *g->slot);
	g->start = xreallocarray(NULL, nocc + 1, sizeof *g->start);
	for (size_t q = 0; q < slots; q++)
		g->slot[q].key = -1;
	size_t r = 0;
	for (size_t x = 0; x < ne; x++)
		if (x == 0 || ek[x].key != ek[x - 1].key) {
			size_t q = cell_slot(g, (long long)ek[x].key);
			g->slot[q].key = (long long)ek[x].key;
			g->slot[q].rank = r;
			g->start[r++] = x;
		}
	g->start[nocc] = ne;
	free(ek);
	g->maxk = 0;
	for (r = 0; r < nocc; r++)
		if (g->start[r + 1] - g->start[r] > g->maxk)
			g->maxk = g->start[r + 1] - g->start[r];
}

static void grid_free(struct grid *g)
{
	free(g->slot);
	free(g->start);
	free(g->box);
	free(g->ref);

	free(g->item);
}

/* the search, shared by the threads: each takes a range of the segments
 * (in cell order) with its own list */
struct pierce_job {
	const struct mesh *m;
	const double (*P)[3];
	const struct grid *g;
	const struct qrec {
		double lo[3], hi[3];    /* the segment's box */
		int s, n[2];
	} *order;
	size_t **buf;           /* per worker: a cell's items whose boxes meet the query's */
	struct deloop_pierce **list;
	size_t *n, *cap;
};

/* Cells whose rank a query thread keeps at hand (a power of 2). */
#define RANK_CACHE 512

/* Segments per thread at least. */
#define PIERCE_MIN_SEGS 4096

static void pierce_range(void *ctx, size_t lo0, size_t hi0, int w)
{
	struct pierce_job *j = ctx;
	const double (*P)[3] = j->P;
	const struct grid *g = j->g;
	if (!j->buf[w])
		j->buf[w] = xreallocarray(NULL, g->maxk + 1, sizeof *j->buf[w]);
	size_t *buf = j->buf[w];
	struct gslot cache[RANK_CACHE];
	for (int c = 0; c < RANK_CACHE; c++)
		cache[c].key = -1;
	for (size_t o = lo0; o < hi0; o++) {
		const struct qrec *qr = &j->order[o];
		size_t s = (size_t)qr->s;
		const double *lo = qr->lo, *hi = qr->hi;
		long c0[3], c1[3];
		/* the segment's box as an item (rounded outwards): the
		 * float test then passes every pair whose boxes meet */
		struct gitem qb = item_of_box(lo, hi);
		cell_range(g, lo, hi, c0, c1);
		for (long k = c0[2]; k <= c1[2]; k++)
			for (long jj = c0[1]; jj <= c1[1]; jj++)
				for (long i = c0[0]; i <= c1[0]; i++) {
					/* consecutive queries look up the same
					 * few cells: a small cache before the
					 * table */
					long long key = cell_key(g, i, jj, k);
					struct gslot *cs = &cache[(size_t)key & (RANK_CACHE - 1)];
					if (cs->key != key) {
						size_t c = cell_slot(g, key);
						cs->key = key;
						cs->rank = g->slot[c].key == -1 ? (size_t)-1 : g->slot[c].rank;
					}
					if (cs->rank == (size_t)-1)
						continue;
					size_t r = cs->rank, e1 = g->start[r + 1], nb = 0;
					/* the boxes first, without branches (most
					 * are apart, in an unpredictable axis) */
					for (size_t e = g->start[r]; e < e1; e++) {
						const struct gbox *b = &g->box[e];
						buf[nb] = e;
						nb += !((qb.hi[0] < b->lo[0]) | (qb.hi[1] < b->lo[1]) |
							(qb.hi[2] < b->lo[2]) | (qb.lo[0] > b->hi[0]) |
							(qb.lo[1] > b->hi[1]) | (qb.lo[2] > b->hi[2]));
					}
					for (size_t y = 0; y < nb; y++) {
						const struct gref *b = &g->ref[buf[y]];
						if (b->n[0] == qr->n[0] || b->n[1] == qr->n[0] ||
						    b->n[2] == qr->n[0] || b->n[0] == qr->n[1] ||
						    b->n[1] == qr->n[1] || b->n[2] == qr->n[1])
							continue;
						/* the test of the near search (the
						 * segment's box unrounded) */
						const struct gbox *bb = &g->box[buf[y]];
						if (hi[0] < bb->lo[0] || hi[1] < bb->lo[1] ||
						    hi[2] < bb->lo[2] || lo[0] > bb->hi[0] ||
						    lo[1] > bb->hi[1] || lo[2] > bb->hi[2])
							continue;
						/* the pair is tested in the lowest
						 * cell both boxes touch, once */
						if (i != (b->c0[0] > c0[0] ? b->c0[0] : c0[0]) ||
						    jj != (b->c0[1] > c0[1] ? b->c0[1] : c0[1]) ||
						    k != (b->c0[2] > c0[2] ? b->c0[2] : c0[2]))
							continue;
						struct deloop_pierce x;
						if (!seg_pierce_nodes(P, (int)s, qr->n, b->t, b->n, &x))
							continue;
						xgrow(&j->list[w], &j->cap[w], j->n[w] + 1, sizeof *j->list[w]);
						j->list[w][j->n[w]++] = x;
					}
				}
	}
}

/* deloop_pierces, and the grid's geometry (lo, h, n) in *geo if not NULL */
size_t dl_pierces_geo(const struct mesh *m, struct deloop_pierce **out, struct grid *geo,
			  struct box_cache *bc)
{
	*out = NULL;
	if (geo)
		memset(geo, 0, sizeof *geo);
	if (bc)
		bc->nt = bc->ns = bc->np = 0;
	if (m->ntri == 0)
		return 0;
	struct grid g;
	double (*P)[3] = dl_node_positions(m);
	if (bc) {
		bc->tb = xreallocarray(bc->tb, m->ntri + 1, sizeof *bc->tb);
		bc->sb = xreallocarray(bc->sb, m->nseg + 1, sizeof *bc->sb);
		bc->nt = m->ntri;
		bc->ns = m->nseg;
	}
	grid_build(&g, m, (const double (*)[3])P, bc ? bc->tb : NULL);
	if (geo) {
		memcpy(geo->lo, g.lo, sizeof g.lo);
		geo->h = g.h;
		memcpy(geo->n, g.n, sizeof g.n);
	}
	/* segments visited cell by cell, the cells in the order of their
	 * index (cell_key: through space in blocks; a radix sort on the cell
	 * of their first node): consecutive queries then read the same
	 * triangles, which stay in cache, where the mesh's own order, after
	 * many splits and merges, is scattered over the surface */
	struct ekey *sk = xreallocarray(NULL, m->nseg + 1, sizeof *sk);
	size_t nlive = 0;
	for (size_t s = 0; s < m->nseg; s++) {
		if (!m->seg[s].alive)
			continue;
		const double *p = P[m->seg[s].n[0]];
		long c[3], c1[3];
		cell_range(&g, p, p, c, c1);
		sk[nlive].key = (unsigned long long)cell_key(&g, c[0], c[1], c[2]);
		sk[nlive++].t = (int)s;
	}
	sk = ekey_sort(sk, xreallocarray(NULL, nlive + 1, sizeof *sk), nlive, grid_kmax(&g));
	/* with what the query needs */
	struct qrec *order = xreallocarray(NULL, nlive + 1, sizeof *order);
	for (size_t o = 0; o < nlive; o++) {
		int s = sk[o].t;
		struct qrec *qr = &order[o];
		qr->s = s;
		qr->n[0] = m->seg[s].n[0];
		qr->n[1] = m->seg[s].n[1];
		seg_box(m, P, s, qr->lo, qr->hi);
		if (bc) {
			memcpy(bc->sb[s], qr->lo, sizeof qr->lo);
			memcpy(bc->sb[s] + 3, qr->hi, sizeof qr->hi);
		}
	}
	free(sk);
	int nw = par_threads();
	struct pierce_job j = {m, (const double (*)[3])P, &g, order,
			       xcalloc((size_t)nw, sizeof *j.buf), xcalloc((size_t)nw, sizeof *j.list),
			       xcalloc((size_t)nw, sizeof *j.n), xcalloc((size_t)nw, sizeof *j.cap)};
	par_for(nlive, PIERCE_MIN_SEGS, pierce_range, &j);
	size_t n = 0;
	for (int w = 0; w < nw; w++)
		n += j.n[w];
	struct deloop_pierce *list = n ? xreallocarray(NULL, n, sizeof *list) : NULL;
	n = 0;
	for (int w = 0; w < nw; w++) {
		if (j.n[w])
			memcpy(list + n, j.list[w], j.n[w] * sizeof *list);
		n += j.n[w];
		free(j.list[w]);
		free(j.buf[w]);
	}
	free(j.buf);
	free(j.list);
	free(j.n);
	free(j.cap);
	/* the visiting order depends on the grid and the threads; the
	 * list's does not */
	if (n > 1)
		qsort(list, n, sizeof *list, cmp_pierce);
	free(order);
	if (bc) {
		free(bc->P);
		bc->P = P;
		bc->np = m->nnode;
	} else {
		free(P);
	}
	grid_free(&g);
	*out = list;
	return n;
}

size_t deloop_pierces(const struct mesh *m, struct deloop_pierce **out)
{
	return dl_pierces_geo(m, out, NULL, NULL);
}
