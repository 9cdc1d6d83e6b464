/*
 * deloop_grid.h - the search for the self-intersections of the mesh,
 * shared by the files of delooping only: deloop_grid.c (the exact
 * segment/triangle test, the hashed grid of triangles and the full
 * search), deloop_near.c (the search near what the last pass changed,
 * and the reference search of -check), used by deloop.c's passes.
 */
#ifndef ETCH_DELOOP_GRID_H
#define ETCH_DELOOP_GRID_H

#include "deloop.h"
#include "vec3.h"

#include <stddef.h>

/* The orientation of d against the plane abc: (b - a) x (c - a) . (d - a),
 * six times the signed volume of the tetrahedron. */
static inline double orient(const double *a, const double *b, const double *c, const double *d)
{
	double u[3], v[3], w[3], n[3];
	vec3_sub(b, a, u);
	vec3_sub(c, a, v);
	vec3_sub(d, a, w);
	vec3_cross(u, v, n);
	return vec3_dot(n, w);
}

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
static inline int item_apart(const double *lo, const double *hi, const struct gitem *b)
{
	return hi[0] < b->lo[0] || hi[1] < b->lo[1] || hi[2] < b->lo[2] ||
	       lo[0] > b->hi[0] || lo[1] > b->hi[1] || lo[2] > b->hi[2];
}

/* Whether item b's triangle has node a or node c (then the segment ac
 * cannot pierce it: dl_seg_pierce) */
static inline int item_touches(const struct gitem *b, int a, int c)
{
	return b->n[0] == a || b->n[1] == a || b->n[2] == a || b->n[0] == c || b->n[1] == c ||
	       b->n[2] == c;
}

/* At most this many cell entries per triangle: the grid is coarsened
 * (h doubled) until the triangles' boxes fit (a mesh of a few huge
 * triangles among small ones). */
#define GRID_ENTRIES_PER_TRI 64.0

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

static inline void cell_range(const struct grid *g, const double *lo, const double *hi,
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
static inline double box_cells(const struct grid *g, const double *lo, const double *hi)
{
	long c0[3], c1[3];
	cell_range(g, lo, hi, c0, c1);
	return (double)(c1[0] - c0[0] + 1) * (double)(c1[1] - c0[1] + 1) *
	       (double)(c1[2] - c0[2] + 1);
}

/* i's low 21 bits spread to every third bit */
static inline unsigned long long spread3(unsigned long long i)
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
static inline long long cell_key(const struct grid *g, long i, long j, long k)
{
	(void)g;
	return (long long)(spread3((unsigned long long)i) | spread3((unsigned long long)j) << 1 |
			   spread3((unsigned long long)k) << 2);
}

static inline void tri_box(const struct mesh *m, const double (*P)[3], int t, double lo[3], double hi[3])
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

static inline void seg_box(const struct mesh *m, const double (*P)[3], int s, double lo[3], double hi[3])
{
	const double *p = P[m->seg[s].n[0]], *q = P[m->seg[s].n[1]];
	for (int d = 0; d < 3; d++) {
		lo[d] = q[d] < p[d] ? q[d] : p[d];
		hi[d] = q[d] > p[d] ? q[d] : p[d];
	}
}

static inline int cmp_pierce(const void *a, const void *b)
{
	const struct deloop_pierce *p = a, *q = b;
	if (p->s != q->s)
		return p->s < q->s ? -1 : 1;
	return (p->t > q->t) - (p->t < q->t);
}

/* The boxes of the alive triangles and segments at the last search (the
 * next search near the changes reads the ones since unchanged from here,
 * in order, rather than from their nodes, scattered).  nt = ns = 0:
 * none. */
struct box_cache {
	double (*tb)[6], (*sb)[6];      /* lo[3], hi[3] */
	size_t nt, ns;
	double (*P)[3];                 /* the node positions (dl_node_positions) */
	size_t np;
};

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

/* deloop_grid.c: the grid item of triangle t of m with box [lo, hi] */
struct gitem dl_item_of(const struct mesh *m, int t, const double *lo, const double *hi);
/* Whether segment s crosses triangle t of m, the two sharing no node; if
 * so, the crossing in *x.  P: the node positions. */
int dl_seg_pierce(const struct mesh *m, const double (*P)[3], int s, int t,
		  struct deloop_pierce *x);
/* The node positions of m, copied into one array (free it). */
double (*dl_node_positions(const struct mesh *m))[3];
/* The full search: the pierces of m, sorted, in *out (free it); the
 * grid's geometry in *geo and the boxes in *bc for the next search near
 * the changes (either NULL: not kept).  Returns the count. */
size_t dl_pierces_geo(const struct mesh *m, struct deloop_pierce **out, struct grid *geo,
		      struct box_cache *bc);

/* deloop_fresh.c: the pierces of m whose triangle, or a triangle of
 * whose segment, was added since m had ntri0 triangles (at least: a
 * pierce of two older elements may be among them), sorted, each once;
 * every such pierce of the full search is there. */
size_t dl_pierces_fresh(const struct mesh *m, size_t ntri0, struct deloop_pierce **out);
/* deloop_near.c: the same, under -check compared with the full search */
size_t dl_pierces_fresh_checked(const struct mesh *m, size_t ntri0, struct deloop_pierce **out);

/* deloop_near.c: sn becomes m and its pierces pc (np); dl_snap_free
 * releases it. */
void dl_snap_take(struct deloop_snap *sn, const struct mesh *m, const struct deloop_pierce *pc,
		  size_t np);
void dl_snap_free(struct deloop_snap *sn);
/* The pierces of m, searched near what changed since sn (the full search
 * when much did), the same list as dl_pierces_geo's; under -check
 * (deloop_set_check) compared with a full search. */
size_t dl_pierces_near_checked(const struct mesh *m, const struct deloop_snap *sn,
			       struct deloop_pierce **out, struct grid *geo, struct box_cache *bc);

#endif
