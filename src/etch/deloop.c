/*
 * deloop.c - mesh delooping (thesis 7.5.3, 8.4.3): find the
 * self-intersections through a hashed grid, split the mesh into patches
 * along the intersection curves, classify each patch by the arrival time
 * of the fast-marching engine, cut the crossing segments on the curves and
 * delete the loop patches.  See deloop.h for the design.
 *
 * The thesis' pass tested all pairs of triangles (O(N^2)), decided which
 * side of an intersection to delete from the motion of the two triangles,
 * and so broke on pinwheeling triangles and on three or more triangles
 * crossing at one place, and on a real contact deleted most of the mesh
 * (Figure 8.19).  Here the only per-crossing geometry is the exact
 * segment/triangle crossing; what to delete is a volumetric verdict per
 * patch.
 */
#include "deloop.h"

#include "etch.h"
#include "fmm.h"
#include "par.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Grid cell edge in mean segment lengths: a triangle's box then spans one
 * or two cells per axis, and a segment's box as many, so each query looks
 * at a handful of triangles. */
#define GRID_CELL_SEGS 1.5
/* A patch is a loop when the median of its nodes' signed distances to the
 * fast-marching front is below minus a margin: DELOOP_TOL_SPREAD times the
 * median |distance| over all the mesh's nodes (most of them are on the
 * true front, so that is the two engines' typical disagreement on this
 * mesh, and a true front patch's median is of that size), but at least
 * DELOOP_TOL_MIN and at most DELOOP_TOL_MAX cells of the classifier's grid
 * (the engines agree to half a cell in median at the cross-check
 * level, fmm_auto_refine). */
#define DELOOP_TOL_SPREAD 4.0
#define DELOOP_TOL_MIN 0.05
#define DELOOP_TOL_MAX 1.0
/* A cut node the joining (deloop_zip.c) leaves open is moved this
 * fraction of the way back from the crossing towards the kept node: the
 * kept sheets end on chords of the curved intersection curve, and two
 * chords of the same curve, one in each sheet, would otherwise cross each
 * other by a rounding-sized or curvature-sized margin.  A tenth of a
 * segment leaves a gap under 0.1 S_max between the sheets (well inside
 * the 2-segment and 1% checks). */
#define DELOOP_PULLBACK 0.1
/* The classifier's cells may be this many ideal segments across before
 * its grid is refined laterally: the margin follows the engines' actual
 * disagreement (DELOOP_TOL_SPREAD), which on the rate grids of bleach is
 * a small fraction of a cell, so a cell of two segments still resolves
 * loops a segment deep. */
#define DELOOP_CELL_SEGS 2.0
/* ... but by at most this factor per axis for that reason (memory and
 * time grow with its cube; z refinement for standing waves is separate,
 * fmm_auto_refine). */
#define DELOOP_MAX_REFINE 4
/* Largest classifier grid (nodes): 8 bytes each, and fast marching at a
 * few million nodes a second. */
#define DELOOP_MAX_FMM_NODES 4.0e7
/* Arrival times beyond this are the engine's "never reached". */
#define UNREACHED_T (0.5 * FMM_UNREACHED)
/* Passes: the patch pass, then local passes for folds shallower than the
 * margin, each on the crossings the previous left; two or three suffice
 * in every case tested, the cap bounds the work. */
#define DELOOP_PASSES 12

/* Local passes that first try to merge the chosen nodes away
 * (merge_away); the later ones delete them, which always progresses. */
#define DELOOP_MERGE_PASSES 6
/* ... and only nodes on or next to a seam joined in the same run, and
 * this many segment lengths or less past the other sheet: the folds a
 * join leaves at its seam are that shallow (a few hundredths of a
 * segment on the two seeds), while other folds, left by the classifier's
 * margin on rough fronts, have layers that merging one node would leave
 * in place (merged rather than deleted, they add 2-3% to the contact's
 * developed volume). */
#define DELOOP_MERGE_DEPTH 0.05

/* Barycentric slack of the crossing test: rounding of the determinants
 * of nodes of order 1 um apart is ~1e-16 relative; this is far above it
 * and far below any real distance from a triangle's edge. */
#define BARY_EPS 1e-9
/* Sine of the angle under which a segment counts as lying in a
 * triangle's plane: rounding is ~1e-16, real crossings are steeper than
 * 1e-9 by far. */
#define PLANE_EPS 1e-9
/* Cuts nearer than this fraction of the segment to the kept node are not
 * made (a near zero-length segment would come of it). */
#define MIN_CUT 1e-3

static double orient(const double *a, const double *b, const double *c, const double *d)
{
	double u[3], v[3], w[3];
	for (int i = 0; i < 3; i++) {
		u[i] = b[i] - a[i];
		v[i] = c[i] - a[i];
		w[i] = d[i] - a[i];
	}
	return (u[1] * v[2] - u[2] * v[1]) * w[0] + (u[2] * v[0] - u[0] * v[2]) * w[1] +
	       (u[0] * v[1] - u[1] * v[0]) * w[2];
}

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
	for (int i = 0; i < 3; i++) {
		u1[i] = b[i] - a[i];
		v1[i] = c[i] - a[i];
		w1[i] = q[i] - p[i];
	}
	n[0] = u1[1] * v1[2] - u1[2] * v1[1];
	n[1] = u1[2] * v1[0] - u1[0] * v1[2];
	n[2] = u1[0] * v1[1] - u1[1] * v1[0];
	double scale = sqrt((n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) *
			    (w1[0] * w1[0] + w1[1] * w1[1] + w1[2] * w1[2]));
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

/* Whether segment s crosses triangle t of m (pierce), the two sharing no
 * node; if so, the crossing in *x. */
static int seg_pierce(const struct mesh *m, int s, int t, struct deloop_pierce *x)
{
	const struct segment *sg = &m->seg[s];
	const struct triangle *tr = &m->tri[t];
	for (int a = 0; a < 3; a++)
		if (tr->n[a] == sg->n[0] || tr->n[a] == sg->n[1])
			return 0;
	const double *p = m->node[sg->n[0]].p, *q = m->node[sg->n[1]].p;
	double u;
	if (!pierce(p, q, m->node[tr->n[0]].p, m->node[tr->n[1]].p, m->node[tr->n[2]].p, &u))
		return 0;
	x->s = s;
	x->t = t;
	x->u = u;
	for (int d = 0; d < 3; d++)
		x->x[d] = p[d] + u * (q[d] - p[d]);
	return 1;
}

/* A hashed grid of the alive triangles: cells about GRID_CELL_SEGS mean
 * segments across, fixed by the mesh alone, only the occupied ones
 * stored (a surface fills a vanishing part of its box, so a dense array
 * of cells this small would not fit, and a coarser one - as before issue
 * 15 - puts ever more triangles in a cell as the mesh grows: n^1.5).
 * Cell keys hash into an open-addressed table of 2^k slots; the
 * triangles of slot q's cell are item[start[q] .. start[q + 1]).  Which
 * cells a triangle is listed in does not change the pierces found (every
 * pair with overlapping boxes meets in some cell, and the list is sorted
 * at the end), only the time. */
/* A triangle in a cell: its box, rounded outwards to floats, read with
 * it so that most of the triangles a query meets are rejected without
 * touching the mesh. */
struct gitem {
	float lo[3], hi[3];
	int t;
};

/* Whether box [lo, hi] and item b's box have no common point (cheaper
 * than the orientations of a pierce). */
static int item_apart(const double *lo, const double *hi, const struct gitem *b)
{
	return hi[0] < b->lo[0] || hi[1] < b->lo[1] || hi[2] < b->lo[2] ||
	       lo[0] > b->hi[0] || lo[1] > b->hi[1] || lo[2] > b->hi[2];
}

/* The grid item of triangle t with box [lo, hi], rounded outward to
 * float so that it still contains the box. */
static struct gitem item_of(int t, const double *lo, const double *hi)
{
	struct gitem it = {{0}, {0}, t};
	for (int d = 0; d < 3; d++) {
		it.lo[d] = (float)lo[d];
		if ((double)it.lo[d] > lo[d])
			it.lo[d] = nextafterf(it.lo[d], -INFINITY);
		it.hi[d] = (float)hi[d];
		if ((double)it.hi[d] < hi[d])
			it.hi[d] = nextafterf(it.hi[d], INFINITY);
	}
	return it;
}

struct grid {
	double lo[3], h;
	long n[3];              /* cells per axis (the mesh's box over h) */
	size_t mask;            /* slots - 1 */
	long long *key;         /* the cell's index, or -1: empty slot */
	size_t *rank;           /* the slot's cell in the order of the indices */
	size_t nocc;            /* occupied cells */
	size_t *start;          /* per rank: cell r's triangles are
				 * item[start[r] .. start[r + 1]) */
	struct gitem *item;
};

/* At most this many cell entries per triangle: the grid is coarsened
 * (h doubled) until the triangles' boxes fit (a mesh of a few huge
 * triangles among small ones). */
#define GRID_ENTRIES_PER_TRI 64.0

static void cell_range(const struct grid *g, const double *lo, const double *hi,
		       long c0[3], long c1[3])
{
	for (int d = 0; d < 3; d++) {
		double a = floor((lo[d] - g->lo[d]) / g->h), b = floor((hi[d] - g->lo[d]) / g->h);
		c0[d] = a < 0 ? 0 : a >= g->n[d] ? g->n[d] - 1 : (long)a;
		c1[d] = b < 0 ? 0 : b >= g->n[d] ? g->n[d] - 1 : (long)b;
	}
}

/* The number of cells the box [lo, hi] touches. */
static double box_cells(const struct grid *g, const double *lo, const double *hi)
{
	long c0[3], c1[3];
	cell_range(g, lo, hi, c0, c1);
	return (double)(c1[0] - c0[0] + 1) * (double)(c1[1] - c0[1] + 1) *
	       (double)(c1[2] - c0[2] + 1);
}

static long long cell_key(const struct grid *g, long i, long j, long k)
{
	return ((long long)k * g->n[1] + j) * g->n[0] + i;
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
	while (g->key[q] != key && g->key[q] != -1)
		q = (q + 1) & g->mask;
	return q;
}

static void tri_box(const struct mesh *m, int t, double lo[3], double hi[3])
{
	const struct triangle *tr = &m->tri[t];
	for (int d = 0; d < 3; d++) {
		lo[d] = hi[d] = m->node[tr->n[0]].p[d];
		for (int j = 1; j < 3; j++) {
			double v = m->node[tr->n[j]].p[d];
			lo[d] = fmin(lo[d], v);
			hi[d] = fmax(hi[d], v);
		}
	}
}

/* the grid's construction, by the threads over ranges of triangles */
struct grid_job {
	struct grid *g;
	const struct mesh *m;
	double *cnt;            /* per triangle: its cell entries */
	const size_t *off;      /* per triangle: its first entry */
	struct ekey {
		unsigned long long key;
		size_t i;
	} *ek;
	struct gitem *raw;
};

static void count_range(void *ctx, size_t lo, size_t hi, int w)
{
	(void)w;
	struct grid_job *j = ctx;
	for (size_t t = lo; t < hi; t++) {
		j->cnt[t] = 0;
		if (!j->m->tri[t].alive)
			continue;
		double blo[3], bhi[3];
		tri_box(j->m, (int)t, blo, bhi);
		j->cnt[t] = box_cells(j->g, blo, bhi);
	}
}

static void fill_range(void *ctx, size_t lo, size_t hi, int w)
{
	(void)w;
	struct grid_job *j = ctx;
	for (size_t t = lo; t < hi; t++) {
		if (!j->m->tri[t].alive)
			continue;
		double blo[3], bhi[3];
		long c0[3], c1[3];
		tri_box(j->m, (int)t, blo, bhi);
		struct gitem it = item_of((int)t, blo, bhi);
		cell_range(j->g, blo, bhi, c0, c1);
		size_t e = j->off[t];
		for (long k = c0[2]; k <= c1[2]; k++)
			for (long jj = c0[1]; jj <= c1[1]; jj++)
				for (long i = c0[0]; i <= c1[0]; i++) {
					j->ek[e].key = (unsigned long long)cell_key(j->g, i, jj, k);
					j->ek[e].i = e;
					j->raw[e++] = it;
				}
	}
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

static void grid_build(struct grid *g, const struct mesh *m)
{
	double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
	double len = 0;
	size_t nseg = 0, ntri = 0;
	for (size_t i = 0; i < m->nnode; i++)
		if (m->node[i].alive)
			for (int d = 0; d < 3; d++) {
				lo[d] = fmin(lo[d], m->node[i].p[d]);
				hi[d] = fmax(hi[d], m->node[i].p[d]);
			}
	for (size_t s = 0; s < m->nseg; s++)
		if (m->seg[s].alive) {
			len += mesh_seg_length(m, (int)s);
			nseg++;
		}
	for (size_t t = 0; t < m->ntri; t++)
		ntri += m->tri[t].alive != 0;
	memset(g, 0, sizeof *g);
	double h = nseg ? GRID_CELL_SEGS * len / (double)nseg : 1;
	double ext[3];
	for (int d = 0; d < 3; d++) {
		ext[d] = hi[d] > lo[d] ? hi[d] - lo[d] : 0;
		g->lo[d] = lo[d] > -INFINITY && lo[d] < INFINITY ? lo[d] : 0;
	}
	if (!(h > 0))
		h = 1;
	struct grid_job job = {g, m, xreallocarray(NULL, m->ntri + 1, sizeof *job.cnt), NULL, NULL,
			       NULL};
	/* cell indices stay far inside a long long, and the triangles'
	 * boxes within GRID_ENTRIES_PER_TRI cells each on average */
	for (;;) {
		double cells = 1;
		for (int d = 0; d < 3; d++)
			cells *= floor(ext[d] / h) + 1;
		if (cells < 1e15) {
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
	struct ekey *ek = xreallocarray(NULL, ne + 1, sizeof *ek), *tmp = xreallocarray(NULL, ne + 1, sizeof *tmp);
	struct gitem *raw = xreallocarray(NULL, ne + 1, sizeof *raw);
	job.off = off;
	job.ek = ek;
	job.raw = raw;
	par_for(m->ntri, GRID_MIN_TRIS, fill_range, &job);
	free(off);
	unsigned long long kmax = (unsigned long long)cell_key(g, g->n[0] - 1, g->n[1] - 1, g->n[2] - 1);
	size_t *bucket = xreallocarray(NULL, 65536 + 1, sizeof *bucket);
	for (int shift = 0; shift < 64 && (kmax >> shift) > 0; shift += 16) {
		memset(bucket, 0, (65536 + 1) * sizeof *bucket);
		for (size_t x = 0; x < ne; x++)
			bucket[((ek[x].key >> shift) & 0xffff) + 1]++;
		for (size_t q = 0; q < 65536; q++)
			bucket[q + 1] += bucket[q];
		for (size_t x = 0; x < ne; x++)
			tmp[bucket[(ek[x].key >> shift) & 0xffff]++] = ek[x];
		struct ekey *sw = ek;
		ek = tmp;
		tmp = sw;
	}
	free(bucket);
	free(tmp);
	g->item = xreallocarray(NULL, ne + 1, sizeof *g->item);
	size_t nocc = 0;
	for (size_t x = 0; x < ne; x++) {
		g->item[x] = raw[ek[x].i];
		nocc += x == 0 || ek[x].key != ek[x - 1].key;
	}
	free(raw);
	size_t slots = 1024;
	while (slots < 2 * nocc)
		slots *= 2;
	g->mask = slots - 1;
	g->nocc = nocc;
	g->key = xreallocarray(NULL, slots, sizeof *g->key);
	g->rank = xreallocarray(NULL, slots, sizeof *g->rank);
	g->start = xreallocarray(NULL, nocc + 1, sizeof *g->start);
	for (size_t q = 0; q < slots; q++)
		g->key[q] = -1;
	size_t r = 0;
	for (size_t x = 0; x < ne; x++)
		if (x == 0 || ek[x].key != ek[x - 1].key) {
			size_t q = cell_slot(g, (long long)ek[x].key);
			g->key[q] = (long long)ek[x].key;
			g->rank[q] = r;
			g->start[r++] = x;
		}
	g->start[nocc] = ne;
	free(ek);
}

static void grid_free(struct grid *g)
{
	free(g->key);
	free(g->rank);
	free(g->start);
	free(g->item);
}

static int cmp_pierce(const void *a, const void *b)
{
	const struct deloop_pierce *p = a, *q = b;
	if (p->s != q->s)
		return p->s < q->s ? -1 : 1;
	return (p->t > q->t) - (p->t < q->t);
}

/* the search, shared by the threads: each takes a range of the segments
 * (in cell order) with its own stamps and list */
struct pierce_job {
	const struct mesh *m;
	const struct grid *g;
	const int *order;
	int **stamp;            /* per worker: stamp[t] = s + 1 once s tested t */
	struct deloop_pierce **list;
	size_t *n, *cap;
};

/* Segments per thread at least. */
#define PIERCE_MIN_SEGS 4096

static void pierce_range(void *ctx, size_t lo0, size_t hi0, int w)
{
	struct pierce_job *j = ctx;
	const struct mesh *m = j->m;
	const struct grid *g = j->g;
	if (!j->stamp[w])
		j->stamp[w] = xcalloc(m->ntri, sizeof *j->stamp[w]);
	int *stamp = j->stamp[w];
	for (size_t o = lo0; o < hi0; o++) {
		size_t s = (size_t)j->order[o];
		const struct segment *sg = &m->seg[s];
		const double *p = m->node[sg->n[0]].p, *q = m->node[sg->n[1]].p;
		double lo[3], hi[3];
		long c0[3], c1[3];
		for (int d = 0; d < 3; d++) {
			lo[d] = fmin(p[d], q[d]);
			hi[d] = fmax(p[d], q[d]);
		}
		cell_range(g, lo, hi, c0, c1);
		for (long k = c0[2]; k <= c1[2]; k++)
			for (long jj = c0[1]; jj <= c1[1]; jj++)
				for (long i = c0[0]; i <= c1[0]; i++) {
					size_t c = cell_slot(g, cell_key(g, i, jj, k));
					if (g->key[c] == -1)
						continue;
					size_t r = g->rank[c];
					for (size_t e = g->start[r]; e < g->start[r + 1]; e++) {
						const struct gitem *b = &g->item[e];
						if (item_apart(lo, hi, b))
							continue;
						int t = b->t;
						if (stamp[t] == (int)s + 1)
							continue;
						stamp[t] = (int)s + 1;
						struct deloop_pierce x;
						if (!seg_pierce(m, (int)s, t, &x))
							continue;
						xgrow(&j->list[w], &j->cap[w], j->n[w] + 1, sizeof *j->list[w]);
						j->list[w][j->n[w]++] = x;
					}
				}
	}
}

/* deloop_pierces, and the grid's geometry (lo, h, n) in *geo if not NULL */
static size_t pierces_geo(const struct mesh *m, struct deloop_pierce **out, struct grid *geo)
{
	*out = NULL;
	if (geo)
		memset(geo, 0, sizeof *geo);
	if (m->ntri == 0)
		return 0;
	struct grid g;
	grid_build(&g, m);
	if (geo) {
		memcpy(geo->lo, g.lo, sizeof g.lo);
		geo->h = g.h;
		memcpy(geo->n, g.n, sizeof g.n);
	}
	/* segments visited cell by cell, the cells in the order of their
	 * index (x fastest, then y, z; a counting sort on the rank of the
	 * cell of their first node): consecutive queries then read the same
	 * triangles, which stay in cache, where the mesh's own order, after
	 * many splits and merges, is scattered over the surface */
	size_t nocc = g.nocc;
	size_t *at = xcalloc(nocc + 2, sizeof *at);
	int *order = xreallocarray(NULL, m->nseg + 1, sizeof *order);
	size_t *cellof = xreallocarray(NULL, m->nseg + 1, sizeof *cellof);
	for (size_t s = 0; s < m->nseg; s++) {
		if (!m->seg[s].alive)
			continue;
		const double *p = m->node[m->seg[s].n[0]].p;
		long c[3], c1[3];
		cell_range(&g, p, p, c, c1);
		size_t q = cell_slot(&g, cell_key(&g, c[0], c[1], c[2]));
		cellof[s] = g.key[q] == -1 ? nocc : g.rank[q];     /* an empty cell: last */
		at[cellof[s] + 1]++;
	}
	for (size_t c = 0; c <= nocc; c++)
		at[c + 1] += at[c];
	size_t nlive = at[nocc + 1];
	for (size_t s = 0; s < m->nseg; s++)
		if (m->seg[s].alive)
			order[at[cellof[s]]++] = (int)s;
	free(at);
	free(cellof);
	int nw = par_threads();
	struct pierce_job j = {m, &g, order, xcalloc((size_t)nw, sizeof *j.stamp),
			       xcalloc((size_t)nw, sizeof *j.list), xcalloc((size_t)nw, sizeof *j.n),
			       xcalloc((size_t)nw, sizeof *j.cap)};
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
		free(j.stamp[w]);
	}
	free(j.list);
	free(j.stamp);
	free(j.n);
	free(j.cap);
	/* the visiting order depends on the grid and the threads; the
	 * list's does not */
	if (n > 1)
		qsort(list, n, sizeof *list, cmp_pierce);
	free(order);
	grid_free(&g);
	*out = list;
	return n;
}

size_t deloop_pierces(const struct mesh *m, struct deloop_pierce **out)
{
	return pierces_geo(m, out, NULL);
}

/* the reference search: every alive segment against every alive
 * triangle whose x range meets its own (a sweep over the triangles
 * sorted by their x minimum), no grid */
struct xbox {
	double lo, hi;
	int t;
};

static int cmp_xbox(const void *a, const void *b)
{
	const struct xbox *p = a, *q = b;
	if (p->lo != q->lo)
		return p->lo < q->lo ? -1 : 1;
	return (p->t > q->t) - (p->t < q->t);
}

size_t deloop_pierces_all(const struct mesh *m, struct deloop_pierce **out)
{
	*out = NULL;
	struct xbox *xb = xreallocarray(NULL, m->ntri + 1, sizeof *xb);
	size_t nb = 0;
	for (size_t t = 0; t < m->ntri; t++) {
		if (!m->tri[t].alive)
			continue;
		double lo[3], hi[3];
		tri_box(m, (int)t, lo, hi);
		xb[nb++] = (struct xbox){lo[0], hi[0], (int)t};
	}
	qsort(xb, nb, sizeof *xb, cmp_xbox);
	struct deloop_pierce *list = NULL;
	size_t n = 0, cap = 0;
	for (size_t s = 0; s < m->nseg; s++) {
		const struct segment *sg = &m->seg[s];
		if (!sg->alive)
			continue;
		const double *p = m->node[sg->n[0]].p, *q = m->node[sg->n[1]].p;
		double lo = fmin(p[0], q[0]), hi = fmax(p[0], q[0]);
		for (size_t k = 0; k < nb && xb[k].lo <= hi; k++) {
			if (xb[k].hi < lo)
				continue;
			struct deloop_pierce x;
			if (!seg_pierce(m, (int)s, xb[k].t, &x))
				continue;
			xgrow(&list, &cap, n + 1, sizeof *list);
			list[n++] = x;
		}
	}
	free(xb);
	if (n > 1)
		qsort(list, n, sizeof *list, cmp_pierce);
	*out = list;
	return n;
}

/* The passes after the first search only near what changed.  A pierce
 * depends on nothing but its segment's and triangle's nodes (indices and
 * positions), so the list of a mesh equals the previous search's pierces
 * whose segment and triangle are unchanged, plus the pierces of a changed
 * ("dirty": new, renumbered, re-noded or with a node moved) segment or
 * triangle.  Those meet in a cell that a dirty element's box touches:
 * the search lists triangles only in those cells and tests only the pairs
 * with a dirty member.  Sorted as deloop_pierces, the list is the same,
 * bit for bit (no test calls it alone: etch's outputs with it, on every
 * example with -deloop and tests/bench/etchfast.sh's spheres, were
 * compared with cmp to those of the full search every pass). */
struct deloop_snap {
	size_t nnode, nseg, ntri;
	struct snode {
		double p[3];
		int alive;
	} *node;
	struct sseg {
		int n[2], alive;
	} *seg;
	struct stri {
		int n[3], alive;
	} *tri;
	struct deloop_pierce *pc;    /* the pierces of that mesh */
	size_t np;
	struct grid geo;        /* the last full search's cells (lo, h, n) */
};

/* Dirty elements above this fraction of the alive ones: the full search. */
#define NEAR_MAX_DIRTY 0.125

static void snap_take(struct deloop_snap *sn, const struct mesh *m, const struct deloop_pierce *pc,
		      size_t np)
{
	sn->nnode = m->nnode;
	sn->nseg = m->nseg;
	sn->ntri = m->ntri;
	sn->node = xreallocarray(sn->node, m->nnode + 1, sizeof *sn->node);
	sn->seg = xreallocarray(sn->seg, m->nseg + 1, sizeof *sn->seg);
	sn->tri = xreallocarray(sn->tri, m->ntri + 1, sizeof *sn->tri);
	for (size_t i = 0; i < m->nnode; i++) {
		memcpy(sn->node[i].p, m->node[i].p, sizeof sn->node[i].p);
		sn->node[i].alive = m->node[i].alive != 0;
	}
	for (size_t s = 0; s < m->nseg; s++)
		sn->seg[s] = (struct sseg){{m->seg[s].n[0], m->seg[s].n[1]}, m->seg[s].alive != 0};
	for (size_t t = 0; t < m->ntri; t++)
		sn->tri[t] = (struct stri){{m->tri[t].n[0], m->tri[t].n[1], m->tri[t].n[2]},
					   m->tri[t].alive != 0};
	sn->pc = xreallocarray(sn->pc, np + 1, sizeof *sn->pc);
	if (np)
		memcpy(sn->pc, pc, np * sizeof *pc);
	sn->np = np;
}

static void snap_free(struct deloop_snap *sn)
{
	/* sn->geo holds no arrays */
	free(sn->node);
	free(sn->seg);
	free(sn->tri);
	free(sn->pc);
	memset(sn, 0, sizeof *sn);
}

/* the slot of key in a set of 2^k slots (mask), or the empty one (-1) where it would go */
static size_t set_slot(const long long *key, size_t mask, long long k)
{
	unsigned long long x = (unsigned long long)k * 0x9E3779B97F4A7C15ull;
	size_t q = (size_t)(x ^ (x >> 29)) & mask;
	while (key[q] != k && key[q] != -1)
		q = (q + 1) & mask;
	return q;
}

/* the cells of box lo..hi (via g's geometry) into the set, growing it */
static void set_add_box(const struct grid *g, const double *lo, const double *hi, long long **key,
			size_t *mask, size_t *nkey)
{
	long c0[3], c1[3];
	cell_range(g, lo, hi, c0, c1);
	for (long k = c0[2]; k <= c1[2]; k++)
		for (long j = c0[1]; j <= c1[1]; j++)
			for (long i = c0[0]; i <= c1[0]; i++) {
				if (2 * (*nkey + 1) > *mask + 1) {
					size_t nm = 2 * (*mask + 1) - 1;
					long long *nk = xreallocarray(NULL, nm + 1, sizeof *nk);
					for (size_t q = 0; q <= nm; q++)
						nk[q] = -1;
					for (size_t q = 0; q <= *mask; q++)
						if ((*key)[q] != -1)
							nk[set_slot(nk, nm, (*key)[q])] = (*key)[q];
					free(*key);
					*key = nk;
					*mask = nm;
				}
				long long c = cell_key(g, i, j, k);
				size_t q = set_slot(*key, *mask, c);
				if ((*key)[q] == -1) {
					(*key)[q] = c;
					(*nkey)++;
				}
			}
}

static void seg_box(const struct mesh *m, int s, double lo[3], double hi[3])
{
	const double *p = m->node[m->seg[s].n[0]].p, *q = m->node[m->seg[s].n[1]].p;
	for (int d = 0; d < 3; d++) {
		lo[d] = fmin(p[d], q[d]);
		hi[d] = fmax(p[d], q[d]);
	}
}

/* the pierces of m, searched near what changed since sn (whose geometry
 * *geo, sn->geo or another, becomes that of the search if it is a full one) */
static size_t deloop_pierces_near(const struct mesh *m, const struct deloop_snap *sn,
				  struct deloop_pierce **out, struct grid *geo)
{
	/* the dirty nodes, segments and triangles */
	unsigned char *dn = xcalloc(m->nnode + 1, 1), *ds = xcalloc(m->nseg + 1, 1),
		      *dt = xcalloc(m->ntri + 1, 1);
	for (size_t i = 0; i < m->nnode; i++)
		dn[i] = i >= sn->nnode || !sn->node[i].alive ||
			memcmp(sn->node[i].p, m->node[i].p, sizeof sn->node[i].p) != 0;
	size_t nds = 0, ndt = 0;
	for (size_t s = 0; s < m->nseg; s++) {
		const struct segment *sg = &m->seg[s];
		if (!sg->alive)
			continue;
		ds[s] = s >= sn->nseg || !sn->seg[s].alive || sn->seg[s].n[0] != sg->n[0] ||
			sn->seg[s].n[1] != sg->n[1] || dn[sg->n[0]] || dn[sg->n[1]];
		nds += ds[s];
	}
	for (size_t t = 0; t < m->ntri; t++) {
		const struct triangle *tr = &m->tri[t];
		if (!tr->alive)
			continue;
		int d = t >= sn->ntri || !sn->tri[t].alive;
		for (int a = 0; a < 3 && !d; a++)
			d = sn->tri[t].n[a] != tr->n[a] || dn[tr->n[a]];
		dt[t] = (unsigned char)d;
		ndt += dt[t];
	}
	free(dn);
	if ((double)(nds + ndt) > NEAR_MAX_DIRTY * (double)(m->live_seg + m->live_tri)) {
		free(ds);
		free(dt);
		return pierces_geo(m, out, geo);
	}
	/* the cells of the last full search (a node since moved out of its
	 * box is in a border cell: cell_range clamps, alike for every box),
	 * coarsened until the dirty boxes fit in GRID_ENTRIES_PER_TRI cells
	 * each on average (coarser, every triangle's box still does) */
	struct grid g = sn->geo;
	if (!(g.h > 0)) {
		free(ds);
		free(dt);
		return pierces_geo(m, out, geo);
	}
	for (;;) {
		double de = 0;
		for (size_t t = 0; t < m->ntri; t++) {
			if (!dt[t])
				continue;
			double blo[3], bhi[3];
			tri_box(m, (int)t, blo, bhi);
			de += box_cells(&g, blo, bhi);
		}
		for (size_t s = 0; s < m->nseg; s++) {
			if (!ds[s])
				continue;
			double blo[3], bhi[3];
			seg_box(m, (int)s, blo, bhi);
			de += box_cells(&g, blo, bhi);
		}
		if (de <= GRID_ENTRIES_PER_TRI * (double)(nds + ndt) + 64)
			break;
		/* same origin, cells twice as large */
		g.h *= 2;
		for (int d = 0; d < 3; d++)
			g.n[d] = (g.n[d] + 1) / 2;
	}
	/* the cells the dirty boxes touch */
	size_t mask = 1023, nkey = 0;
	long long *key = xreallocarray(NULL, mask + 1, sizeof *key);
	for (size_t q = 0; q <= mask; q++)
		key[q] = -1;
	/* and their union's box: an element outside it meets no dirty one */
	double ulo[3] = {INFINITY, INFINITY, INFINITY}, uhi[3] = {-INFINITY, -INFINITY, -INFINITY};
	for (size_t s = 0; s < m->nseg; s++)
		if (ds[s]) {
			double blo[3], bhi[3];
			seg_box(m, (int)s, blo, bhi);
			set_add_box(&g, blo, bhi, &key, &mask, &nkey);
			for (int d = 0; d < 3; d++) {
				ulo[d] = fmin(ulo[d], blo[d]);
				uhi[d] = fmax(uhi[d], bhi[d]);
			}
		}
	for (size_t t = 0; t < m->ntri; t++)
		if (dt[t]) {
			double blo[3], bhi[3];
			tri_box(m, (int)t, blo, bhi);
			set_add_box(&g, blo, bhi, &key, &mask, &nkey);
			for (int d = 0; d < 3; d++) {
				ulo[d] = fmin(ulo[d], blo[d]);
				uhi[d] = fmax(uhi[d], bhi[d]);
			}
		}
	/* every alive triangle in those cells, in increasing order per cell:
	 * counted, then placed */
	size_t *start = xcalloc(mask + 2, sizeof *start);
	for (int fill = 0; fill < 2; fill++) {
		struct gitem *item = fill ? g.item : NULL;
		for (size_t t = 0; t < m->ntri; t++) {
			if (!m->tri[t].alive)
				continue;
			double blo[3], bhi[3];
			long c0[3], c1[3];
			tri_box(m, (int)t, blo, bhi);
			if (bhi[0] < ulo[0] || bhi[1] < ulo[1] || bhi[2] < ulo[2] || blo[0] > uhi[0] ||
			    blo[1] > uhi[1] || blo[2] > uhi[2])
				continue;
			cell_range(&g, blo, bhi, c0, c1);
			struct gitem it = item_of((int)t, blo, bhi);
			for (long k = c0[2]; k <= c1[2]; k++)
				for (long j = c0[1]; j <= c1[1]; j++)
					for (long i = c0[0]; i <= c1[0]; i++) {
						size_t q = set_slot(key, mask, cell_key(&g, i, j, k));
						if (key[q] == -1)
							continue;
						if (fill)
							item[start[q]++] = it;
						else
							start[q + 1]++;
					}
		}
		if (!fill) {
			for (size_t q = 0; q <= mask; q++)
				start[q + 1] += start[q];
			g.item = xreallocarray(NULL, start[mask + 1] + 1, sizeof *g.item);
		} else {
			/* start[q] is now the end of slot q's run: shift back */
			for (size_t q = mask + 1; q > 0; q--)
				start[q] = start[q - 1];
			start[0] = 0;
		}
	}
	/* the pairs with a dirty member */
	int *stamp = xcalloc(m->ntri + 1, sizeof *stamp);
	struct deloop_pierce *list = NULL;
	size_t n = 0, cap = 0;
	for (size_t s = 0; s < m->nseg; s++) {
		const struct segment *sg = &m->seg[s];
		if (!sg->alive)
			continue;
		double blo[3], bhi[3];
		long c0[3], c1[3];
		seg_box(m, (int)s, blo, bhi);
		if (bhi[0] < ulo[0] || bhi[1] < ulo[1] || bhi[2] < ulo[2] || blo[0] > uhi[0] ||
		    blo[1] > uhi[1] || blo[2] > uhi[2])
			continue;
		cell_range(&g, blo, bhi, c0, c1);
		for (long k = c0[2]; k <= c1[2]; k++)
			for (long jj = c0[1]; jj <= c1[1]; jj++)
				for (long i = c0[0]; i <= c1[0]; i++) {
					size_t c = set_slot(key, mask, cell_key(&g, i, jj, k));
					if (key[c] == -1)
						continue;
					for (size_t e = start[c]; e < start[c + 1]; e++) {
						const struct gitem *b = &g.item[e];
						if (item_apart(blo, bhi, b))
							continue;
						int t = b->t;
						if ((!ds[s] && !dt[t]) || stamp[t] == (int)s + 1)
							continue;
						stamp[t] = (int)s + 1;
						struct deloop_pierce x;
						if (!seg_pierce(m, (int)s, t, &x))
							continue;
						xgrow(&list, &cap, n + 1, sizeof *list);
						list[n++] = x;
					}
				}
	}
	free(stamp);
	free(start);
	free(key);
	free(g.item);
	/* and the previous ones between clean elements */
	for (size_t k = 0; k < sn->np; k++) {
		size_t s = (size_t)sn->pc[k].s, t = (size_t)sn->pc[k].t;
		if (s < m->nseg && m->seg[s].alive && !ds[s] && t < m->ntri && m->tri[t].alive &&
		    !dt[t]) {
			xgrow(&list, &cap, n + 1, sizeof *list);
			list[n++] = sn->pc[k];
		}
	}
	free(ds);
	free(dt);
	if (n > 1)
		qsort(list, n, sizeof *list, cmp_pierce);
	*out = list;
	return n;
}

/* Union-find with path halving. */
static int find(int *up, int x)
{
	while (up[x] != x) {
		up[x] = up[up[x]];
		x = up[x];
	}
	return x;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* Signed distance (um) of node i to the fast-marching front at time t:
 * negative inside developed resist.  *vote 0 for nodes on the top or the
 * substrate: those are developed surface wherever a node lies on them
 * (T < t there), so they cast no vote. */
static double node_dist(const struct mesh *m, int i, const struct fmm *fm,
			const struct rfield *f, double t, int *vote)
{
	const struct node *nd = &m->node[i];
	*vote = nd->alive && !(nd->flags & (ON_TOP | ON_SUB));
	if (!*vote)
		return 0;
	double tp = fmm_time_at(fm, nd->p);
	if (tp >= UNREACHED_T)
		return HUGE_VAL;
	return (tp - t) * rfield_eval(f, nd->p, NULL);
}

/* The patch verdict (deloop.h, stage 2): which nodes are in loops. */
static unsigned char *classify_patches(const struct mesh *m, const struct deloop_pierce *pc,
				       size_t np, const struct fmm *fm, const struct rfield *f,
				       double t, struct deloop_report *rep)
{
	size_t nn = m->nnode;
	/* patches: nodes joined by segments no other sheet crosses */
	unsigned char *cut = xcalloc(m->nseg, 1);
	for (size_t i = 0; i < np; i++)
		cut[pc[i].s] = 1;
	int *up = xreallocarray(NULL, nn, sizeof *up);
	for (size_t i = 0; i < nn; i++)
		up[i] = (int)i;
	for (size_t s = 0; s < m->nseg; s++)
		if (m->seg[s].alive && !cut[s]) {
			int a = find(up, m->seg[s].n[0]), b = find(up, m->seg[s].n[1]);
			if (a != b)
				up[a > b ? a : b] = a < b ? a : b;
		}
	free(cut);
	/* each patch's signed distances, grouped by a counting sort */
	size_t *first = xcalloc(nn + 1, sizeof *first);
	double *dist = xreallocarray(NULL, nn + 1, sizeof *dist);
	int *root = xreallocarray(NULL, nn + 1, sizeof *root);
	for (size_t i = 0; i < nn; i++) {
		int vote;
		dist[i] = node_dist(m, (int)i, fm, f, t, &vote);
		root[i] = vote ? find(up, (int)i) : -1;
		if (vote)
			first[root[i] + 1]++;
	}
	for (size_t i = 0; i < nn; i++)
		first[i + 1] += first[i];
	size_t *fill = xreallocarray(NULL, nn + 1, sizeof *fill);
	double *sorted = xreallocarray(NULL, 2 * nn + 1, sizeof *sorted);
	memcpy(fill, first, (nn + 1) * sizeof *fill);
	for (size_t i = 0; i < nn; i++)
		if (root[i] >= 0)
			sorted[fill[root[i]]++] = dist[i];
	free(fill);
	double cell = fmax(fm->h[0], fmax(fm->h[1], fm->h[2]));
	size_t nv = first[nn];
	for (size_t i = 0; i < nv; i++)
		sorted[nv + i] = fabs(sorted[i]);
	double spread = 0;
	if (nv > 0) {
		qsort(sorted + nv, nv, sizeof *sorted, cmp_double);
		spread = sorted[nv + nv / 2];
	}
	double tol = fmin(fmax(DELOOP_TOL_SPREAD * spread, DELOOP_TOL_MIN * cell),
			  DELOOP_TOL_MAX * cell);
	unsigned char *loop = xcalloc(nn, 1);   /* per patch root */
	for (size_t r = 0; r < nn; r++) {
		size_t k = first[r + 1] - first[r];
		if (k == 0)
			continue;
		double *v = sorted + first[r];
		qsort(v, k, sizeof *v, cmp_double);
		double med = k & 1 ? v[k / 2] : 0.5 * (v[k / 2 - 1] + v[k / 2]);
		if (med < -tol) {
			loop[r] = 1;
			rep->loops++;
		}
		rep->margin = tol;
	}
	free(first);
	free(dist);
	free(sorted);
	free(root);
	unsigned char *gone = xcalloc(nn, 1);  /* per node */
	for (size_t i = 0; i < nn; i++)
		if (m->node[i].alive)
			gone[i] = loop[find(up, (int)i)];
	free(loop);
	free(up);
	return gone;
}

/* The fallback for crossings left between two kept patches (a fold no
 * deeper than the margin, so both sides pass as front): of each crossing
 * segment the node deeper in developed resist goes.  Such folds lie
 * within the margin of the true front, so nothing further from it than
 * the margin is deleted. */
static unsigned char *classify_local(const struct mesh *m, const struct deloop_pierce *pc,
				     size_t np, const struct fmm *fm, const struct rfield *f,
				     double t, long *folds)
{
	unsigned char *gone = xcalloc(m->nnode, 1);
	(*folds)++;
	for (size_t i = 0; i < np; i++) {
		if (i > 0 && pc[i].s == pc[i - 1].s)
			continue;
		int a = m->seg[pc[i].s].n[0], b = m->seg[pc[i].s].n[1], va, vb;
		double da = node_dist(m, a, fm, f, t, &va), db = node_dist(m, b, fm, f, t, &vb);
		if (va && (!vb || da < db)) {
			gone[a] = 1;
		} else if (vb) {
			gone[b] = 1;
		} else {
			/* a segment on the substrate (or the top) crossing
			 * another sheet: the crossed triangle's deepest voting
			 * node goes, or if none votes its last node, so that
			 * every pass makes progress */
			const struct triangle *tr = &m->tri[pc[i].t];
			int pick = tr->n[0];
			double dp = HUGE_VAL;
			for (int j = 0; j < 3; j++) {
				int v;
				double d = node_dist(m, tr->n[j], fm, f, t, &v);
				if (v && d < dp) {
					dp = d;
					pick = tr->n[j];
				} else if (dp == HUGE_VAL && tr->n[j] > pick) {
					pick = tr->n[j];
				}
			}
			gone[pick] = 1;
		}
	}
	return gone;
}

/* Stage 3: cut every crossing segment from a kept node to a gone one at
 * the crossing nearest the kept node, delete every triangle with a gone
 * node, join the two sheets along the cuts and pull back the cut nodes
 * left open. */
static void cut_and_remove(struct mesh *m, const struct deloop_pierce *pc, size_t np,
			   const unsigned char *gone, struct deloop_report *rep, int first,
			   int join, unsigned char **seam, size_t *nseam)
{
	size_t nn = m->nnode;
	/* decided before any split, as the splits add segments */
	struct { int s; double u; int kept, node; } *todo =
		xreallocarray(NULL, np + 1, sizeof *todo);
	size_t ntodo = 0;
	/* a loop node on which a crossing from a kept node ends lies on the
	 * other sheet, i.e. on the intersection curve: in the patch pass it
	 * is kept and ends its sheet there, as a kept node on the other
	 * sheet does (below).  Cutting each of its segments there instead
	 * would put several nodes at one place, which no join can pair
	 * (two seeds a radius apart: vertices of the two start meshes meet
	 * on the curve).  The local passes delete what they chose, so that
	 * each pass makes progress. */
	unsigned char *gn = xreallocarray(NULL, nn + 1, 1);
	memcpy(gn, gone, nn);
	for (size_t i = 0; first && i < np; ) {
		size_t j = i;
		while (j < np && pc[j].s == pc[i].s)
			j++;
		const struct segment *sg = &m->seg[pc[i].s];
		int g0 = gone[sg->n[0]], g1 = gone[sg->n[1]];
		if (g0 != g1) {
			double u = g0 ? 0 : 1;
			for (size_t k = i; k < j; k++)
				u = g0 ? fmax(u, pc[k].u) : fmin(u, pc[k].u);
			if ((g0 ? 1 - u : u) >= 1 - MIN_CUT)
				gn[g0 ? sg->n[0] : sg->n[1]] = 0;
		}
		i = j;
	}
	gone = gn;
	for (size_t i = 0; i < np; ) {
		size_t j = i;
		while (j < np && pc[j].s == pc[i].s)
			j++;
		const struct segment *sg = &m->seg[pc[i].s];
		int g0 = gone[sg->n[0]], g1 = gone[sg->n[1]];
		if (g0 != g1) {
			double u = g0 ? 0 : 1;
			for (size_t k = i; k < j; k++)
				u = g0 ? fmax(u, pc[k].u) : fmin(u, pc[k].u);
			/* a crossing at the kept node itself (it lies on the
			 * other sheet) is no place for a new node: the kept
			 * node ends the sheet */
			double from_kept = g0 ? 1 - u : u;
			if (from_kept > MIN_CUT) {
				todo[ntodo].s = pc[i].s;
				todo[ntodo].u = u;
				todo[ntodo].kept = g0 ? sg->n[1] : sg->n[0];
				ntodo++;
			}
		}
		i = j;
	}
	for (size_t i = 0; i < ntodo; i++) {
		int s = todo[i].s;
		double u = todo[i].u;
		const struct node *a = &m->node[m->seg[s].n[0]], *b = &m->node[m->seg[s].n[1]];
		double p[3], r[3];
		for (int d = 0; d < 3; d++) {
			p[d] = a->p[d] + u * (b->p[d] - a->p[d]);
			r[d] = a->s[d] + u * (b->s[d] - a->s[d]);
		}
		double rl = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
		for (int d = 0; d < 3; d++)
			r[d] = rl > 1e-12 ? r[d] / rl : (u < 0.5 ? a->s[d] : b->s[d]);
		unsigned fl = a->flags & b->flags & (ON_WALLS | ON_SUB);
		todo[i].node = mesh_split(m, s, p, r, fl);
		rep->cuts++;
	}
	/* new nodes (index >= nn) are kept; the kept nodes of deleted
	 * triangles and the new nodes are where the sheets now end */
	size_t nf = m->nnode;
	unsigned char *fresh = xcalloc(nf + 1, 1);
	memset(fresh + nn, 1, nf - nn);
	for (size_t tt = 0; tt < m->ntri; tt++) {
		const struct triangle *tr = &m->tri[tt];
		if (!tr->alive)
			continue;
		int any = 0;
		for (int j = 0; j < 3; j++)
			any |= (size_t)tr->n[j] < nn && gone[tr->n[j]];
		if (any) {
			for (int j = 0; j < 3; j++)
				fresh[tr->n[j]] = 1;
			mesh_kill_triangle(m, (int)tt);
			rep->removed_tris++;
		}
	}
	if (first)
		rep->open_cut = deloop_open_length(m);
	unsigned char *welded = xcalloc(nf + 1, 1);
	if (join)
		rep->joined += deloop_zip(m, fresh, nf, welded, nf);
	/* the seam nodes, for merge_away */
	if (*nseam < nf) {
		*seam = xreallocarray(*seam, nf, 1);
		memset(*seam + *nseam, 0, nf - *nseam);
		*nseam = nf;
	}
	for (size_t i = 0; i < nf; i++)
		(*seam)[i] |= welded[i];
	/* the cut nodes left open: pulled back (DELOOP_PULLBACK) */
	for (size_t i = 0; i < ntodo; i++) {
		int c = todo[i].node, k = todo[i].kept;
		struct node *nc = &m->node[c];
		if (!nc->alive || welded[c] || !m->node[k].alive)
			continue;
		for (int d = 0; d < 3; d++)
			nc->p[d] -= DELOOP_PULLBACK * (nc->p[d] - m->node[k].p[d]);
	}
	free(welded);
	free(fresh);
	free(todo);
	free(gn);
}

/* The local passes' first resort at a seam: a node chosen to go, on or
 * next to a seam this run joined (seam, nseam) and barely past the other
 * sheet (DELOOP_MERGE_DEPTH), is merged onto its nearest neighbour not
 * chosen (mesh_merge, thesis 8.4.1.2, with all its checks) instead of
 * being deleted, so that the joined surface stays closed; the merge
 * moves the surface by less than a segment.  Returns the nodes merged;
 * none (every merge refused) leaves the deletion to cut_and_remove. */
static long merge_away(struct mesh *m, const struct deloop_pierce *pc, size_t np,
		       const unsigned char *gone, const unsigned char *seam, size_t nseam,
		       struct deloop_report *rep)
{
	long merged = 0;
	size_t nn = m->nnode;
	/* only nodes just past the other sheet: for every crossing on their
	 * segments, within DELOOP_MERGE_DEPTH segment lengths of the
	 * crossed triangle's plane */
	unsigned char *shallow = xcalloc(nn + 1, 1);
	for (size_t i = 0; i < np; i++)
		for (int e = 0; e < 2; e++) {
			int g = m->seg[pc[i].s].n[e];
			if (!gone[g] || shallow[g] == 2)
				continue;
			const struct triangle *tr = &m->tri[pc[i].t];
			const double *a = m->node[tr->n[0]].p, *b = m->node[tr->n[1]].p,
				*c = m->node[tr->n[2]].p;
			double u[3], v[3];
			for (int d = 0; d < 3; d++) {
				u[d] = b[d] - a[d];
				v[d] = c[d] - a[d];
			}
			double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
				       u[0] * v[1] - u[1] * v[0]};
			double nl = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
			double depth = nl > 0 ? fabs(orient(a, b, c, m->node[g].p)) / nl : HUGE_VAL;
			shallow[g] = depth <= DELOOP_MERGE_DEPTH * mesh_seg_length(m, pc[i].s) ? 1 : 2;
		}
	for (size_t g = 0; g < nn; g++) {
		if (!gone[g] || !m->node[g].alive || shallow[g] != 1)
			continue;
		/* at a seam this run joined: the node or a neighbour on it */
		int near = g < nseam && seam[g];
		for (int k = 0; k < m->node[g].nseg && !near; k++) {
			const struct segment *sg = &m->seg[m->node[g].seg[k]];
			int o = sg->n[0] == (int)g ? sg->n[1] : sg->n[0];
			near = (size_t)o < nseam && seam[o];
		}
		if (!near)
			continue;
		/* the neighbours by distance, nearest first (ties by index) */
		const struct node *nd = &m->node[g];
		int best = -1;
		double bl = HUGE_VAL;
		for (int pick = 0; pick < nd->nseg && best < 0; pick++) {
			double lim = bl;
			int cand = -1;
			bl = HUGE_VAL;
			for (int k = 0; k < nd->nseg; k++) {
				int s = nd->seg[k];
				int o = m->seg[s].n[0] == (int)g ? m->seg[s].n[1] : m->seg[s].n[0];
				double l = mesh_seg_length(m, s);
				if ((size_t)o < nn && gone[o])
					continue;
				if (pick > 0 && !(l > lim))
					continue;
				if (l < bl) {
					bl = l;
					cand = s;
				}
			}
			if (cand < 0)
				break;
			if (mesh_can_merge(m, cand, (int)g))
				best = cand;
		}
		if (best < 0)
			continue;
		mesh_merge(m, best, (int)g);
		merged++;
	}
	free(shallow);
	rep->merged += merged;
	return merged;
}

/* -check: every search near the changes is compared with a full search,
 * which must give the same list bit for bit (set by deloop_set_check). */
static int check_near;

void deloop_set_check(int on)
{
	check_near = on;
}

/* deloop_pierces_near, and under -check its comparison with the full
 * search */
static size_t pierces_near_checked(const struct mesh *m, const struct deloop_snap *sn,
				   struct deloop_pierce **out, struct grid *geo)
{
	size_t n = deloop_pierces_near(m, sn, out, geo);
	if (check_near) {
		struct deloop_pierce *full;
		size_t nf = deloop_pierces(m, &full);
		if (nf != n || (n && memcmp(full, *out, n * sizeof *full) != 0))
			die("deloop: -check: the search near the changes found %zu crossings, "
			    "the full search %zu (or other ones)", n, nf);
		free(full);
	}
	return n;
}

static void deloop_passes(struct mesh *m, const struct fmm *fm, const struct rfield *f, double t,
			  int join, struct deloop_report *rep)
{
	memset(rep, 0, sizeof *rep);
	unsigned char *seam = NULL;     /* nodes joined across a seam this run */
	size_t nseam = 0;
	struct deloop_snap sn = {0};
	for (int pass = 0; pass < DELOOP_PASSES; pass++) {
		struct deloop_pierce *pc;
		size_t np = pass == 0 ? pierces_geo(m, &pc, &sn.geo)
			: pierces_near_checked(m, &sn, &pc, &sn.geo);
		snap_take(&sn, m, pc, np);
		if (pass == 0)
			rep->crossings = (long)np;
		rep->left = (long)np;
		if (np == 0)
			break;
		unsigned char *gone = pass == 0 ? classify_patches(m, pc, np, fm, f, t, rep)
			: classify_local(m, pc, np, fm, f, t, &rep->folds);
		/* the next pass recounts: cutting can leave a crossing that
		 * no pierce of this one showed */
		if (pass == 0 || pass > DELOOP_MERGE_PASSES ||
		    !merge_away(m, pc, np, gone, seam, nseam, rep))
			cut_and_remove(m, pc, np, gone, rep, pass == 0, join, &seam, &nseam);
		free(gone);
		free(pc);
		if (pass + 1 == DELOOP_PASSES) {
			/* the cap: report what the last pass left, not what it
			 * started from */
			rep->left = (long)pierces_near_checked(m, &sn, &pc, &sn.geo);
			free(pc);
		}
	}
	snap_free(&sn);
	free(seam);
	rep->open_left = deloop_open_length(m);
}

/* Joining the sheets along the intersection curve (deloop_zip.c) leaves,
 * on some meshes, crossings no later pass removes (the unbaked contact at
 * 240 mJ/cm2 with 0.1 um segments: 4, however many passes).  A loop-free
 * mesh matters more than a closed seam, so the run is then redone from a
 * copy of the mesh without joining: the sheets end a pull-back apart. */
long deloop_run(struct mesh *m, const struct fmm *fm, const struct rfield *f, double t,
		struct deloop_report *rep)
{
	struct mesh *before = mesh_copy(m);
	deloop_passes(m, fm, f, t, 1, rep);
	if (rep->left > 0) {
		struct mesh joined = *m;
		*m = *before;
		*before = joined;
		deloop_passes(m, fm, f, t, 0, rep);
		rep->unjoined = 1;
	}
	mesh_free(before);
	return rep->loops;
}

struct fmm *deloop_classifier(const struct ratefile *r, double seg,
			      const double *seeds, int nseeds)
{
	int refine[3];
	double h[3] = {
		r->nx > 1 ? (r->xmax - r->xmin) / (r->nx - 1) : 0,
		r->ny > 1 ? (r->ymax - r->ymin) / (r->ny - 1) : 0,
		r->nz > 1 ? (r->zmax - r->zmin) / (r->nz - 1) : 0,
	};
	int nz_auto = fmm_auto_refine(r);
	double nodes = 1;
	int n[3] = {r->nx, r->ny, r->nz};
	for (int d = 0; d < 3; d++) {
		/* a cell no wider than DELOOP_CELL_SEGS segments: a young
		 * loop is about a segment deep, and must be deeper than the
		 * margin */
		double k = seg > 0 && h[d] > DELOOP_CELL_SEGS * seg ?
			fmin(ceil(h[d] / (DELOOP_CELL_SEGS * seg)), DELOOP_MAX_REFINE) : 1;
		if (d == 2 && k < nz_auto)
			k = nz_auto;
		refine[d] = k > FMM_MAX_REFINE ? FMM_MAX_REFINE : (int)k;
	}
	for (;;) {
		nodes = 1;
		for (int d = 0; d < 3; d++)
			nodes *= (double)(n[d] > 1 ? (n[d] - 1) * refine[d] + 1 : 1);
		if (nodes <= DELOOP_MAX_FMM_NODES)
			break;
		int big = 0;
		for (int d = 1; d < 3; d++)
			if (refine[d] > refine[big])
				big = d;
		if (refine[big] == 1)
			break;
		refine[big]--;
	}
	return nseeds > 0 ? fmm_solve_points(r, refine, seeds, nseeds) : fmm_solve(r, refine);
}
