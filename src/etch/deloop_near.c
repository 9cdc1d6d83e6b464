/*
 * deloop_near.c - the searches for self-intersections after the first
 * pass of a deloop run: only near what the last pass changed (a pass
 * changes a small part of the mesh, and the full search costs the whole
 * of it), and the reference search that -check compares both with.
 */
#include "deloop_grid.h"

#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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
	double (*Pw)[3] = dl_node_positions(m);
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
			if (!dl_seg_pierce(m, P, (int)s, xb[k].t, &x))
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

/* Dirty elements above this fraction of the alive ones: the full search. */
#define NEAR_MAX_DIRTY 0.125

void dl_snap_take(struct deloop_snap *sn, const struct mesh *m, const struct deloop_pierce *pc,
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

void dl_snap_free(struct deloop_snap *sn)
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

/* The state of one search near the changes: the dirty segments and
 * triangles, the grid of cells their boxes touch (a set of cell keys) and
 * the alive triangles listed in those cells. */
struct near {
	const struct mesh *m;
	const struct box_cache *bc;
	unsigned char *ds, *dt;         /* dirty segments, triangles */
	size_t nds, ndt;
	struct grid g;                  /* the cells (g.item: the triangles) */
	long long *key;                 /* the set of dirty cells */
	size_t mask, nkey;
	size_t *start;                  /* per slot: its triangles are
					 * g.item[start[q] .. start[q + 1]) */
	double ulo[3], uhi[3];          /* the box of every dirty box */
};

/* Marks the dirty segments and triangles of nr->m since sn (new,
 * renumbered, re-noded or with a node moved), and brings the node
 * positions of bc up to date. */
static void near_mark(struct near *nr, const struct deloop_snap *sn, struct box_cache *bc)
{
	const struct mesh *m = nr->m;
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
	nr->ds = ds, nr->dt = dt, nr->nds = nds, nr->ndt = ndt;
}

/* Calls fn(ctx, lo, hi) on the box of every dirty segment, then of every
 * dirty triangle (the boxes of nr->bc). */
static void near_each_dirty(const struct near *nr,
			    void (*fn)(void *ctx, const double *lo, const double *hi), void *ctx)
{
	const struct mesh *m = nr->m;
	const struct box_cache *bc = nr->bc;
	for (size_t s = 0; s < m->nseg; s++)
		if (nr->ds[s])
			fn(ctx, bc->sb[s], bc->sb[s] + 3);
	for (size_t t = 0; t < m->ntri; t++)
		if (nr->dt[t])
			fn(ctx, bc->tb[t], bc->tb[t] + 3);
}

/* near_coarsen's count: the cells of grid g a box touches, summed */
struct cell_count {
	const struct grid *g;
	double cells;
};

static void count_cells(void *ctx, const double *lo, const double *hi)
{
	struct cell_count *cc = ctx;
	cc->cells += box_cells(cc->g, lo, hi);
}

/* Coarsens nr->g until the dirty boxes fit in GRID_ENTRIES_PER_TRI cells
 * each on average (coarser, every triangle's box still does). */
static void near_coarsen(struct near *nr)
{
	struct grid *g = &nr->g;
	for (;;) {
		struct cell_count cc = {g, 0};
		near_each_dirty(nr, count_cells, &cc);
		if (cc.cells <= GRID_ENTRIES_PER_TRI * (double)(nr->nds + nr->ndt) + 64)
			break;
		/* same origin, cells twice as large */
		g->h *= 2;
		for (int d = 0; d < 3; d++)
			g->n[d] = (g->n[d] + 1) / 2;
	}
}

/* Adds the cells the box [lo, hi] touches to the set of the struct near
 * ctx, and the box to the union's. */
static void near_add_box(void *ctx, const double *lo, const double *hi)
{
	struct near *nr = ctx;
	set_add_box(&nr->g, lo, hi, &nr->key, &nr->mask, &nr->nkey);
	for (int d = 0; d < 3; d++) {
		nr->ulo[d] = fmin(nr->ulo[d], lo[d]);
		nr->uhi[d] = fmax(nr->uhi[d], hi[d]);
	}
}

/* The cells the dirty boxes touch, and their union's box: an element
 * outside it meets no dirty one. */
static void near_cells(struct near *nr)
{
	nr->mask = 1023, nr->nkey = 0;
	nr->key = xreallocarray(NULL, nr->mask + 1, sizeof *nr->key);
	for (size_t q = 0; q <= nr->mask; q++)
		nr->key[q] = -1;
	for (int d = 0; d < 3; d++)
		nr->ulo[d] = INFINITY, nr->uhi[d] = -INFINITY;
	near_each_dirty(nr, near_add_box, nr);
}

/* Whether box [blo, bhi] lies outside the union of the dirty boxes. */
static int near_outside(const struct near *nr, const double *blo, const double *bhi)
{
	return bhi[0] < nr->ulo[0] || bhi[1] < nr->ulo[1] || bhi[2] < nr->ulo[2] ||
	       blo[0] > nr->uhi[0] || blo[1] > nr->uhi[1] || blo[2] > nr->uhi[2];
}

/* Every alive triangle in the dirty cells, in increasing order per cell:
 * counted, then placed. */
static void near_fill(struct near *nr)
{
	const struct mesh *m = nr->m;
	const struct box_cache *bc = nr->bc;
	struct grid *g = &nr->g;
	size_t mask = nr->mask;
	size_t *start = nr->start = xcalloc(mask + 2, sizeof *start);
	for (int fill = 0; fill < 2; fill++) {
		struct gitem *item = fill ? g->item : NULL;
		for (size_t t = 0; t < m->ntri; t++) {
			if (!m->tri[t].alive)
				continue;
			double blo[3], bhi[3];
			long c0[3], c1[3];
			memcpy(blo, bc->tb[t], sizeof blo);
			memcpy(bhi, bc->tb[t] + 3, sizeof bhi);
			if (near_outside(nr, blo, bhi))
				continue;
			cell_range(g, blo, bhi, c0, c1);
			struct gitem it = {{0}, {0}, 0, {0}};
			if (fill)
				it = dl_item_of(m, (int)t, blo, bhi);
			for (long k = c0[2]; k <= c1[2]; k++)
				for (long j = c0[1]; j <= c1[1]; j++)
					for (long i = c0[0]; i <= c1[0]; i++) {
						size_t q = set_slot(nr->key, mask, cell_key(g, i, j, k));
						if (nr->key[q] == -1)
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
			g->item = xreallocarray(NULL, start[mask + 1] + 1, sizeof *g->item);
		} else {
			/* start[q] is now the end of slot q's run: shift back */
			for (size_t q = mask + 1; q > 0; q--)
				start[q] = start[q - 1];
			start[0] = 0;
		}
	}
}

/* The pierces of the pairs with a dirty member, appended to *list. */
static void near_pairs(const struct near *nr, const double (*P)[3], struct deloop_pierce **list,
		       size_t *n, size_t *cap)
{
	const struct mesh *m = nr->m;
	const struct box_cache *bc = nr->bc;
	const struct grid *g = &nr->g;
	int *stamp = xcalloc(m->ntri + 1, sizeof *stamp);
	for (size_t s = 0; s < m->nseg; s++) {
		const struct segment *sg = &m->seg[s];
		if (!sg->alive)
			continue;
		double blo[3], bhi[3];
		long c0[3], c1[3];
		memcpy(blo, bc->sb[s], sizeof blo);
		memcpy(bhi, bc->sb[s] + 3, sizeof bhi);
		if (near_outside(nr, blo, bhi))
			continue;
		cell_range(g, blo, bhi, c0, c1);
		for (long k = c0[2]; k <= c1[2]; k++)
			for (long jj = c0[1]; jj <= c1[1]; jj++)
				for (long i = c0[0]; i <= c1[0]; i++) {
					size_t c = set_slot(nr->key, nr->mask, cell_key(g, i, jj, k));
					if (nr->key[c] == -1)
						continue;
					for (size_t e = nr->start[c]; e < nr->start[c + 1]; e++) {
						const struct gitem *b = &g->item[e];
						if (item_apart(blo, bhi, b) || item_touches(b, sg->n[0], sg->n[1]))
							continue;
						int t = b->t;
						if ((!nr->ds[s] && !nr->dt[t]) || stamp[t] == (int)s + 1)
							continue;
						stamp[t] = (int)s + 1;
						struct deloop_pierce x;
						if (!dl_seg_pierce(m, P, (int)s, t, &x))
							continue;
						xgrow(list, cap, *n + 1, sizeof **list);
						(*list)[(*n)++] = x;
					}
				}
	}
	free(stamp);
}

/* the pierces of m, searched near what changed since sn (whose geometry
 * *geo, sn->geo or another, becomes that of the search if it is a full one) */
static size_t deloop_pierces_near(const struct mesh *m, const struct deloop_snap *sn,
				  struct deloop_pierce **out, struct grid *geo, struct box_cache *bc)
{
	struct near nr = {.m = m, .bc = bc};
	near_mark(&nr, sn, bc);
	/* the cells of the last full search (a node since moved out of its
	 * box is in a border cell: cell_range clamps, alike for every box),
	 * coarsened to the dirty boxes */
	nr.g = sn->geo;
	if ((double)(nr.nds + nr.ndt) > NEAR_MAX_DIRTY * (double)(m->live_seg + m->live_tri) ||
	    !(nr.g.h > 0)) {
		free(nr.ds);
		free(nr.dt);
		return dl_pierces_geo(m, out, geo, bc);
	}
	const double (*P)[3] = (const double (*)[3])bc->P;
	box_cache_update(bc, m, P, nr.ds, nr.dt);
	near_coarsen(&nr);
	near_cells(&nr);
	near_fill(&nr);
	struct deloop_pierce *list = NULL;
	size_t n = 0, cap = 0;
	near_pairs(&nr, P, &list, &n, &cap);
	free(nr.start);
	free(nr.key);
	free(nr.g.item);
	/* and the previous ones between clean elements */
	for (size_t k = 0; k < sn->np; k++) {
		size_t s = (size_t)sn->pc[k].s, t = (size_t)sn->pc[k].t;
		if (s < m->nseg && m->seg[s].alive && !nr.ds[s] && t < m->ntri && m->tri[t].alive &&
		    !nr.dt[t]) {
			xgrow(&list, &cap, n + 1, sizeof *list);
			list[n++] = sn->pc[k];
		}
	}
	free(nr.ds);
	free(nr.dt);
	if (n > 1)
		qsort(list, n, sizeof *list, cmp_pierce);
	*out = list;
	return n;
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
size_t dl_pierces_near_checked(const struct mesh *m, const struct deloop_snap *sn,
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

/* Whether pierce p has a triangle, or a segment of a triangle, from
 * ntri0 on. */
static int fresh_member(const struct mesh *m, size_t ntri0, const struct deloop_pierce *p)
{
	const struct segment *sg = &m->seg[p->s];
	return (size_t)p->t >= ntri0 || (sg->t[0] >= 0 && (size_t)sg->t[0] >= ntri0) ||
	       (sg->t[1] >= 0 && (size_t)sg->t[1] >= ntri0);
}

/* dl_pierces_fresh, and under -check its comparison with the full
 * search: every pierce of it with a new member must be in the list, bit
 * for bit */
size_t dl_pierces_fresh_checked(const struct mesh *m, size_t ntri0, struct deloop_pierce **out)
{
	size_t n = dl_pierces_fresh(m, ntri0, out);
	if (check_near) {
		struct deloop_pierce *full;
		size_t nf = deloop_pierces(m, &full);
		for (size_t i = 0; i < nf; i++) {
			if (!fresh_member(m, ntri0, &full[i]))
				continue;
			const struct deloop_pierce *f =
				n ? bsearch(&full[i], *out, n, sizeof **out, cmp_pierce) : NULL;
			if (!f || memcmp(f, &full[i], sizeof *f) != 0)
				die("deloop: -check: the search of a closing's crossings missed "
				    "segment %d through triangle %d", full[i].s, full[i].t);
		}
		free(full);
	}
	return n;
}
