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
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Grid cell edge in mean edge lengths: a triangle's box then spans one
 * or two cells per axis, and a segment's box as many, so each query looks
 * at a handful of triangles.  (1.5 before: 2 lists each triangle in fewer
 * cells, 3.4 M entries for 1.4 M triangles instead of 4.4 M, and the
 * search, which reads the boxes of a cell without branches, gained more
 * from that than it lost to fuller cells: 0.3 s less at 1.4 M
 * triangles.) */
#define GRID_CELL_SEGS 2.0
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

/* The node positions of m, copied into one array: the searches read
 * them in a scattered order, and the nodes' own records are three times
 * their size.  Free it. */
static double (*node_positions(const struct mesh *m))[3]
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
static int seg_pierce(const struct mesh *m, const double (*P)[3], int s, int t,
		      struct deloop_pierce *x)
{
	return seg_pierce_nodes(P, s, m->seg[s].n, t, m->tri[t].n, x);
}

/* A hashed grid of the alive triangles: cells about GRID_CELL_SEGS mean
 * edges across, fixed by the mesh alone, only the occupied ones stored
 * (a surface fills a vanishing part of its box, so a dense array of cells
 * this small would not fit, and a coarser one - as before issue 15 - puts
 * ever more triangles in a cell as the mesh grows: n^1.5).  Cell keys
 * (cell_key, Morton order) hash into an open-addressed table of 2^k
 * slots, each with the cell's rank in key order; the triangles of the
 * cell of rank r are box/ref[start[r] .. start[r + 1]).  Which cells a
 * triangle is listed in does not change the pierces found (every pair
 * with overlapping boxes meets in some cell, and the list is sorted at
 * the end), only the time.
 *
 * Where the time goes (1.4 M triangles, 2.1 M segments, before the
 * rework of this grid): not in the pierce tests (8 M) but in reading
 * memory in a scattered order - the nodes of each segment and triangle,
 * the hash table, the cells - and in the 170 M boxes scanned.  Hence the
 * node positions copied into one array (node_positions), the segments
 * visited in cell order with their boxes at hand (struct qrec), the
 * cells in Morton order with a small cache of their ranks, the boxes of
 * a cell apart from the rest and tested without branches, and each pair
 * tested once by rule rather than through a per-triangle stamp. */
/* A triangle in a cell: its box, rounded outwards to floats, and its
 * nodes, read with it so that most of the triangles a query meets (boxes
 * apart, or the segment's own neighbours, about two thirds of those whose
 * boxes meet) are rejected without touching the mesh. */
struct gitem {
	float lo[3], hi[3];
	int t;
	int n[3];
};

/* Whether box [lo, hi] and item b's box have no common point (cheaper
 * than the orientations of a pierce). */
static int item_apart(const double *lo, const double *hi, const struct gitem *b)
{
	return hi[0] < b->lo[0] || hi[1] < b->lo[1] || hi[2] < b->lo[2] ||
	       lo[0] > b->hi[0] || lo[1] > b->hi[1] || lo[2] > b->hi[2];
}

/* Whether item b's triangle has node a or node c (then the segment ac
 * cannot pierce it: seg_pierce) */
static int item_touches(const struct gitem *b, int a, int c)
{
	return b->n[0] == a || b->n[1] == a || b->n[2] == a || b->n[0] == c || b->n[1] == c ||
	       b->n[2] == c;
}

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
static struct gitem item_of(const struct mesh *m, int t, const double *lo, const double *hi)
{
	struct gitem it = item_of_box(lo, hi);
	it.t = t;
	for (int a = 0; a < 3; a++)
		it.n[a] = m->tri[t].n[a];
	return it;
}

struct grid {
	double lo[3], h;
	long n[3];              /* cells per axis (the mesh's box over h) */
	size_t mask;            /* slots - 1 */
	struct gslot {
		long long key;  /* the cell's index, or -1: empty slot */
		size_t rank;    /* the cell's place in the order of the indices */
	} *slot;
	size_t nocc;            /* occupied cells */
	size_t *start;          /* per rank: cell r's triangles are
				 * item[start[r] .. start[r + 1]) */
	struct gitem *item;     /* (the near search's grid) */
	/* the full search's grid: the items split in their boxes, read by
	 * every query, and the rest, read for the few whose boxes meet */
	struct gbox {
		float lo[3], hi[3];
	} *box;
	struct gref {
		int t, n[3];
		int c0[3];      /* the triangle's lowest cell */
	} *ref;
	size_t maxk;            /* the most triangles in a cell */
};

/* At most this many cell entries per triangle: the grid is coarsened
 * (h doubled) until the triangles' boxes fit (a mesh of a few huge
 * triangles among small ones). */
#define GRID_ENTRIES_PER_TRI 64.0

static void cell_range(const struct grid *g, const double *lo, const double *hi,
		       long c0[3], long c1[3])
{
	/* (long) truncates as floor does for the non-negative values it
	 * gets; a multiplication, not divisions: the cells move by rounding,
	 * which is monotone (the lowest common cell of two boxes is still
	 * the one of the larger lower end), and do not change the pierces */
	double ih = 1 / g->h;
	for (int d = 0; d < 3; d++) {
		double a = (lo[d] - g->lo[d]) * ih, b = (hi[d] - g->lo[d]) * ih;
		c0[d] = a < 0 ? 0 : a >= (double)g->n[d] ? g->n[d] - 1 : (long)a;
		c1[d] = b < 0 ? 0 : b >= (double)g->n[d] ? g->n[d] - 1 : (long)b;
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

/* i's low 21 bits spread to every third bit */
static unsigned long long spread3(unsigned long long i)
{
	i &= 0x1fffff;
	i = (i | i << 32) & 0x1f00000000ffffull;
	i = (i | i << 16) & 0x1f0000ff0000ffull;
	i = (i | i << 8) & 0x100f00f00f00f00full;
	i = (i | i << 4) & 0x10c30c30c30c30c3ull;
	i = (i | i << 2) & 0x1249249249249249ull;
	return i;
}

/* The index of cell (i, j, k): its bits interleaved (Morton order, at
 * most GRID_AXIS_BITS a coordinate), so that the cells in the order of
 * their index, the order the search visits them in, go through space in
 * blocks: consecutive ones are near each other, and so are the triangles
 * and cells they read. */
#define GRID_AXIS_BITS 21
static long long cell_key(const struct grid *g, long i, long j, long k)
{
	(void)g;
	return (long long)(spread3((unsigned long long)i) | spread3((unsigned long long)j) << 1 |
			   spread3((unsigned long long)k) << 2);
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

static void tri_box(const struct mesh *m, const double (*P)[3], int t, double lo[3], double hi[3])
{
	const struct triangle *tr = &m->tri[t];
	for (int d = 0; d < 3; d++) {
		lo[d] = hi[d] = P[tr->n[0]][d];
		for (int j = 1; j < 3; j++) {
			double v = P[tr->n[j]][d];
			lo[d] = v < lo[d] ? v : lo[d];     /* fmin, fmax: calls */
			hi[d] = v > hi[d] ? v : hi[d];
		}
	}
}

/* The boxes of the alive triangles and segments at the last search (the
 * next search near the changes reads the ones since unchanged from here,
 * in order, rather than from their nodes, scattered).  nt = ns = 0:
 * none. */
struct box_cache {
	double (*tb)[6], (*sb)[6];      /* lo[3], hi[3] */
	size_t nt, ns;
	double (*P)[3];                 /* the node positions (node_positions) */
	size_t np;
};

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
		j->tit[t] = item_of(j->m, (int)t, blo, bhi);
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

static int cmp_pierce(const void *a, const void *b)
{
	const struct deloop_pierce *p = a, *q = b;
	if (p->s != q->s)
		return p->s < q->s ? -1 : 1;
	return (p->t > q->t) - (p->t < q->t);
}

static void seg_box(const struct mesh *m, const double (*P)[3], int s, double lo[3], double hi[3])
{
	const double *p = P[m->seg[s].n[0]], *q = P[m->seg[s].n[1]];
	for (int d = 0; d < 3; d++) {
		lo[d] = q[d] < p[d] ? q[d] : p[d];
		hi[d] = q[d] > p[d] ? q[d] : p[d];
	}
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
static size_t pierces_geo(const struct mesh *m, struct deloop_pierce **out, struct grid *geo,
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
	double (*P)[3] = node_positions(m);
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
	return pierces_geo(m, out, NULL, NULL);
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
	double (*Pw)[3] = node_positions(m);
	const double (*P)[3] = (const double (*)[3])Pw;
	struct xbox *xb = xreallocarray(NULL, m->ntri + 1, sizeof *xb);
	size_t nb = 0;
	for (size_t t = 0; t < m->ntri; t++) {
		if (!m->tri[t].alive)
			continue;
		double lo[3], hi[3];
		tri_box(m, P, (int)t, lo, hi);
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
			if (!seg_pierce(m, P, (int)s, xb[k].t, &x))
				continue;
			xgrow(&list, &cap, n + 1, sizeof *list);
			list[n++] = x;
		}
	}
	free(xb);
	free(Pw);
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


/* bc brought up to date: the boxes of the triangles and segments marked
 * in dt and ds (changed since the last search) or not yet in it */
static void box_cache_update(struct box_cache *bc, const struct mesh *m, const double (*P)[3],
			     const unsigned char *ds, const unsigned char *dt)
{
	bc->tb = xreallocarray(bc->tb, m->ntri + 1, sizeof *bc->tb);
	bc->sb = xreallocarray(bc->sb, m->nseg + 1, sizeof *bc->sb);
	for (size_t t = 0; t < m->ntri; t++)
		if (m->tri[t].alive && (t >= bc->nt || dt[t]))
			tri_box(m, P, (int)t, bc->tb[t], bc->tb[t] + 3);
	for (size_t s = 0; s < m->nseg; s++)
		if (m->seg[s].alive && (s >= bc->ns || ds[s]))
			seg_box(m, P, (int)s, bc->sb[s], bc->sb[s] + 3);
	bc->nt = m->ntri;
	bc->ns = m->nseg;
}

/* the pierces of m, searched near what changed since sn (whose geometry
 * *geo, sn->geo or another, becomes that of the search if it is a full one) */
static size_t deloop_pierces_near(const struct mesh *m, const struct deloop_snap *sn,
				  struct deloop_pierce **out, struct grid *geo, struct box_cache *bc)
{
	/* the dirty nodes, segments and triangles */
	unsigned char *dn = xcalloc(m->nnode + 1, 1), *ds = xcalloc(m->nseg + 1, 1),
		      *dt = xcalloc(m->ntri + 1, 1);
	/* and the node positions brought up to date (the others are as at
	 * the last search, whose mesh sn is) */
	bc->P = xreallocarray(bc->P, m->nnode + 1, sizeof *bc->P);
	for (size_t i = 0; i < m->nnode; i++) {
		dn[i] = i >= sn->nnode || !sn->node[i].alive ||
			memcmp(sn->node[i].p, m->node[i].p, sizeof sn->node[i].p) != 0;
		if (dn[i] || i >= bc->np)
			memcpy(bc->P[i], m->node[i].p, sizeof bc->P[i]);
	}
	bc->np = m->nnode;
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
		return pierces_geo(m, out, geo, bc);
	}
	/* the cells of the last full search (a node since moved out of its
	 * box is in a border cell: cell_range clamps, alike for every box),
	 * coarsened until the dirty boxes fit in GRID_ENTRIES_PER_TRI cells
	 * each on average (coarser, every triangle's box still does) */
	struct grid g = sn->geo;
	if (!(g.h > 0)) {
		free(ds);
		free(dt);
		return pierces_geo(m, out, geo, bc);
	}
	const double (*P)[3] = (const double (*)[3])bc->P;
	box_cache_update(bc, m, P, ds, dt);
	for (;;) {
		double de = 0;
		for (size_t t = 0; t < m->ntri; t++) {
			if (!dt[t])
				continue;
			double blo[3], bhi[3];
			memcpy(blo, bc->tb[t], sizeof blo);
			memcpy(bhi, bc->tb[t] + 3, sizeof bhi);
			de += box_cells(&g, blo, bhi);
		}
		for (size_t s = 0; s < m->nseg; s++) {
			if (!ds[s])
				continue;
			double blo[3], bhi[3];
			memcpy(blo, bc->sb[s], sizeof blo);
			memcpy(bhi, bc->sb[s] + 3, sizeof bhi);
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
			memcpy(blo, bc->sb[s], sizeof blo);
			memcpy(bhi, bc->sb[s] + 3, sizeof bhi);
			set_add_box(&g, blo, bhi, &key, &mask, &nkey);
			for (int d = 0; d < 3; d++) {
				ulo[d] = fmin(ulo[d], blo[d]);
				uhi[d] = fmax(uhi[d], bhi[d]);
			}
		}
	for (size_t t = 0; t < m->ntri; t++)
		if (dt[t]) {
			double blo[3], bhi[3];
			memcpy(blo, bc->tb[t], sizeof blo);
			memcpy(bhi, bc->tb[t] + 3, sizeof bhi);
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
			memcpy(blo, bc->tb[t], sizeof blo);
			memcpy(bhi, bc->tb[t] + 3, sizeof bhi);
			if (bhi[0] < ulo[0] || bhi[1] < ulo[1] || bhi[2] < ulo[2] || blo[0] > uhi[0] ||
			    blo[1] > uhi[1] || blo[2] > uhi[2])
				continue;
			cell_range(&g, blo, bhi, c0, c1);
			struct gitem it = {{0}, {0}, 0, {0}};
			if (fill)
				it = item_of(m, (int)t, blo, bhi);
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
		memcpy(blo, bc->sb[s], sizeof blo);
			memcpy(bhi, bc->sb[s] + 3, sizeof bhi);
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
						if (item_apart(blo, bhi, b) || item_touches(b, sg->n[0], sg->n[1]))
							continue;
						int t = b->t;
						if ((!ds[s] && !dt[t]) || stamp[t] == (int)s + 1)
							continue;
						stamp[t] = (int)s + 1;
						struct deloop_pierce x;
						if (!seg_pierce(m, P, (int)s, t, &x))
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

/* The k-th smallest of v[0 .. n) (k < n), v partly reordered so that
 * v[0 .. k) are the smaller ones (quickselect: the median of a patch
 * without sorting it, the same value). */
static double kth_smallest(double *v, size_t n, size_t k)
{
	long lo = 0, hi = (long)n - 1, kk = (long)k;
	while (hi > lo) {
		long mid = lo + (hi - lo) / 2;
		double a = v[lo], b = v[mid], c = v[hi];
		double piv = a < b ? (b < c ? b : (a < c ? c : a)) : (a < c ? a : (b < c ? c : b));
		long i = lo, j = hi;
		while (i <= j) {
			while (v[i] < piv)
				i++;
			while (v[j] > piv)
				j--;
			if (i <= j) {
				double x = v[i];
				v[i++] = v[j];
				v[j--] = x;
			}
		}
		if (kk <= j)
			hi = j;
		else if (kk >= i)
			lo = i;
		else
			break;
	}
	return v[k];
}

/* The median of v[0 .. k) (k > 0), v reordered. */
static double median(double *v, size_t k)
{
	double b = kth_smallest(v, k, k / 2);
	if (k & 1)
		return b;
	double a = v[0];
	for (size_t i = 1; i < k / 2; i++)
		a = fmax(a, v[i]);
	return 0.5 * (a + b);
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
	if (nv > 0)
		spread = kth_smallest(sorted + nv, nv, nv / 2);
	double tol = fmin(fmax(DELOOP_TOL_SPREAD * spread, DELOOP_TOL_MIN * cell),
			  DELOOP_TOL_MAX * cell);
	unsigned char *loop = xcalloc(nn, 1);   /* per patch root */
	for (size_t r = 0; r < nn; r++) {
		size_t k = first[r + 1] - first[r];
		if (k == 0)
			continue;
		double med = median(sorted + first[r], k);
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
				   struct deloop_pierce **out, struct grid *geo, struct box_cache *bc)
{
	size_t n = deloop_pierces_near(m, sn, out, geo, bc);
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
	struct box_cache bc = {0};
	for (int pass = 0; pass < DELOOP_PASSES; pass++) {
		struct deloop_pierce *pc;
		size_t np = pass == 0 ? pierces_geo(m, &pc, &sn.geo, &bc)
			: pierces_near_checked(m, &sn, &pc, &sn.geo, &bc);
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
			rep->left = (long)pierces_near_checked(m, &sn, &pc, &sn.geo, &bc);
			free(pc);
		}
	}
	snap_free(&sn);
	free(bc.tb);
	free(bc.sb);
	free(bc.P);
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
