/*
 * deloop_fresh.c - the crossings a closing may have made (deloop_close.c):
 * every pierce of a triangle added since the mesh had ntri0 triangles,
 * and of a segment of one, without searching the rest of the mesh.
 *
 * The closing of the open border adds a few triangles, and only the
 * loops whose new triangles take part in a crossing are opened again;
 * the full search (dl_pierces_geo) found those and every other crossing
 * of the whole mesh, at each of the closing's rounds and ways (on
 * examples/defect two thirds of the searches a run made).  Here the new
 * triangles (kind 0) and their segments (kind 1) are listed in the
 * cells of a grid over them alone, and every alive segment, then every
 * older triangle, looks only in the cells its box touches.  A pair is
 * tested, by the same exact test (dl_seg_pierce), when the full search
 * tests it: the segment's box against the triangle's box rounded
 * outwards to floats (item_apart), so the pierces with a new member are
 * the full search's, and so are the loops opened again.
 */
#include "deloop_grid.h"

#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Grid cell edge in mean edges of the new triangles, and the most cell
 * entries per new element before the cells are made coarser. */
#define FRESH_CELL_SEGS 2.0
#define FRESH_ENTRIES 64.0

struct fentry {
	long long key;
	int kind, i;            /* 0: triangle i, 1: segment i */
};

static int cmp_fentry(const void *a, const void *b)
{
	const struct fentry *p = a, *q = b;
	if (p->key != q->key)
		return p->key < q->key ? -1 : 1;
	if (p->kind != q->kind)
		return p->kind - q->kind;
	return (p->i > q->i) - (p->i < q->i);
}

/* the first entry of e[0 .. n) with key k or more */
static size_t first_of(const struct fentry *e, size_t n, long long k)
{
	size_t lo = 0, hi = n;
	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;
		if (e[mid].key < k)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

/* the float box of triangle t (the full search's) as doubles */
static void tri_fbox(const struct mesh *m, const double (*P)[3], int t, struct gitem *it,
		     double lo[3], double hi[3])
{
	double a[3], b[3];
	tri_box(m, P, t, a, b);
	*it = dl_item_of(m, t, a, b);
	for (int d = 0; d < 3; d++) {
		lo[d] = it->lo[d];
		hi[d] = it->hi[d];
	}
}

static int boxes_apart(const double *alo, const double *ahi, const double *blo, const double *bhi)
{
	return ahi[0] < blo[0] || ahi[1] < blo[1] || ahi[2] < blo[2] || alo[0] > bhi[0] ||
	       alo[1] > bhi[1] || alo[2] > bhi[2];
}

struct fresh {
	const struct mesh *m;
	const double (*P)[3];
	struct grid g;          /* lo, h, n only */
	double ulo[3], uhi[3];  /* the box of the new elements */
	struct fentry *e;
	size_t ne;
	struct deloop_pierce *list;
	size_t n, cap;
};

/* the entries of kind in the cells of box [lo, hi], each tested by test */
static void look(struct fresh *fr, const double *lo, const double *hi, int kind, int self,
		 int self_is_seg)
{
	if (boxes_apart(lo, hi, fr->ulo, fr->uhi))
		return;
	long c0[3], c1[3];
	cell_range(&fr->g, lo, hi, c0, c1);
	for (long k = c0[2]; k <= c1[2]; k++)
		for (long j = c0[1]; j <= c1[1]; j++)
			for (long i = c0[0]; i <= c1[0]; i++) {
				long long key = cell_key(&fr->g, i, j, k);
				for (size_t x = first_of(fr->e, fr->ne, key);
				     x < fr->ne && fr->e[x].key == key; x++) {
					if (fr->e[x].kind != kind)
						continue;
					int s = self_is_seg ? self : fr->e[x].i;
					int t = self_is_seg ? fr->e[x].i : self;
					double slo[3], shi[3];
					seg_box(fr->m, fr->P, s, slo, shi);
					struct gitem it;
					double tlo[3], thi[3];
					tri_fbox(fr->m, fr->P, t, &it, tlo, thi);
					if (item_apart(slo, shi, &it))
						continue;
					struct deloop_pierce p;
					if (!dl_seg_pierce(fr->m, fr->P, s, t, &p))
						continue;
					xgrow(&fr->list, &fr->cap, fr->n + 1, sizeof *fr->list);
					fr->list[fr->n++] = p;
				}
			}
}

/* the box of new element q: triangle nt[q] below na, else segment
 * ns[q - na] */
static void elem_box(const struct fresh *fr, const int *nt, size_t na, const int *ns, size_t q,
		     double lo[3], double hi[3])
{
	if (q < na) {
		struct gitem it;
		tri_fbox(fr->m, fr->P, nt[q], &it, lo, hi);
	} else {
		seg_box(fr->m, fr->P, ns[q - na], lo, hi);
	}
}

/* the cells of the new elements, at a cell size that keeps the entries
 * within FRESH_ENTRIES per element */
static void fresh_cells(struct fresh *fr, const int *nt, size_t na, const int *ns, size_t nsn)
{
	const struct mesh *m = fr->m;
	double len = 0;
	for (int d = 0; d < 3; d++) {
		fr->ulo[d] = INFINITY;
		fr->uhi[d] = -INFINITY;
	}
	for (size_t q = 0; q < na + nsn; q++) {
		double lo[3], hi[3];
		elem_box(fr, nt, na, ns, q, lo, hi);
		if (q >= na)
			len += mesh_seg_length(m, ns[q - na]);
		for (int d = 0; d < 3; d++) {
			fr->ulo[d] = fmin(fr->ulo[d], lo[d]);
			fr->uhi[d] = fmax(fr->uhi[d], hi[d]);
		}
	}
	double h = nsn ? FRESH_CELL_SEGS * len / (double)nsn : 1;
	if (!(h > 0))
		h = 1;
	memcpy(fr->g.lo, fr->ulo, sizeof fr->g.lo);
	for (;;) {
		double cells = 0;
		int fits = 1;
		fr->g.h = h;
		for (int d = 0; d < 3; d++) {
			double nd = floor((fr->uhi[d] - fr->ulo[d]) / h) + 1;
			fits &= nd < (double)(1L << GRID_AXIS_BITS);
			fr->g.n[d] = fits ? (long)nd : 1;
		}
		for (size_t q = 0; fits && q < na + nsn; q++) {
			double lo[3], hi[3];
			elem_box(fr, nt, na, ns, q, lo, hi);
			cells += box_cells(&fr->g, lo, hi);
		}
		if (fits && cells <= FRESH_ENTRIES * (double)(na + nsn) + 64) {
			fr->e = xreallocarray(NULL, (size_t)cells + 1, sizeof *fr->e);
			break;
		}
		h *= 2;
	}
	fr->ne = 0;
	for (size_t q = 0; q < na + nsn; q++) {
		double lo[3], hi[3];
		elem_box(fr, nt, na, ns, q, lo, hi);
		long c0[3], c1[3];
		cell_range(&fr->g, lo, hi, c0, c1);
		for (long k = c0[2]; k <= c1[2]; k++)
			for (long j = c0[1]; j <= c1[1]; j++)
				for (long i = c0[0]; i <= c1[0]; i++)
					fr->e[fr->ne++] = (struct fentry){cell_key(&fr->g, i, j, k),
									  q < na ? 0 : 1,
									  q < na ? nt[q] : ns[q - na]};
	}
	qsort(fr->e, fr->ne, sizeof *fr->e, cmp_fentry);
}

size_t dl_pierces_fresh(const struct mesh *m, size_t ntri0, struct deloop_pierce **out)
{
	*out = NULL;
	/* the new triangles and their segments (each once) */
	int *nt = NULL, *ns = NULL;
	size_t na = 0, nsn = 0, capt = 0, caps = 0;
	for (size_t t = ntri0; t < m->ntri; t++) {
		if (!m->tri[t].alive)
			continue;
		xgrow(&nt, &capt, na + 1, sizeof *nt);
		nt[na++] = (int)t;
		for (int a = 0; a < 3; a++) {
			int s = m->tri[t].s[a];
			const struct segment *sg = &m->seg[s];
			/* listed by its first new triangle */
			int first = sg->t[0] >= (int)ntri0 && m->tri[sg->t[0]].alive ? sg->t[0] : sg->t[1];
			if (first != (int)t)
				continue;
			xgrow(&ns, &caps, nsn + 1, sizeof *ns);
			ns[nsn++] = s;
		}
	}
	if (na == 0) {
		free(nt);
		free(ns);
		return 0;
	}
	double (*Pw)[3] = dl_node_positions(m);
	struct fresh fr = {0};
	fr.m = m;
	fr.P = (const double (*)[3])Pw;
	fresh_cells(&fr, nt, na, ns, nsn);
	/* every alive segment against the new triangles */
	for (size_t s = 0; s < m->nseg; s++) {
		if (!m->seg[s].alive)
			continue;
		double lo[3], hi[3];
		seg_box(m, fr.P, (int)s, lo, hi);
		look(&fr, lo, hi, 0, (int)s, 1);
	}
	/* every older alive triangle against the new segments */
	for (size_t t = 0; t < ntri0 && t < m->ntri; t++) {
		if (!m->tri[t].alive)
			continue;
		struct gitem it;
		double lo[3], hi[3];
		tri_fbox(m, fr.P, (int)t, &it, lo, hi);
		look(&fr, lo, hi, 1, (int)t, 0);
	}
	free(fr.e);
	free(Pw);
	free(nt);
	free(ns);
	/* a pair met in several cells is listed once */
	size_t n = 0;
	if (fr.n > 1) {
		qsort(fr.list, fr.n, sizeof *fr.list, cmp_pierce);
		for (size_t i = 0; i < fr.n; i++)
			if (n == 0 || fr.list[i].s != fr.list[n - 1].s || fr.list[i].t != fr.list[n - 1].t)
				fr.list[n++] = fr.list[i];
	} else {
		n = fr.n;
	}
	*out = fr.list;
	return n;
}
