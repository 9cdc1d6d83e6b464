/*
 * fmm_out.c - the developed surface of a fast-marching solution as
 * triangles, and its curves.plot / curves.plot.2D output (thesis
 * Appendix B, etch's FILES), laid out exactly as the ray-string method
 * writes them: one set per print time, bounds the rate box, every
 * triangle a closed 4-point curve p1 p2 p3 p1, and in the 2D file the
 * same triangles projected on the x-y plane.
 *
 * The surface is the isosurface T = t closed off at the box (iso.h) with
 * the caps on the top and side faces dropped: the ray-string mesh starts
 * as the resist top and its edge nodes slide on the side walls, so it
 * never contains those faces, while nodes that reach the substrate stop
 * there (thesis 7.3), which the substrate cap reproduces.
 */
#include "fmm.h"
#include "fmt_plot.h"
#include "par.h"
#include "surf.h"
#include "tri_decimate.h"
#include "tri_weld.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct filter {
	const struct fmm *f;
	const double *zl;       /* the z of the levels extracted on (NULL: f's grid) */
	int nk;
	double tol[3];          /* how close to a face counts as on it, um */
	iso_emit emit;
	void *ctx;
	long count;
};

/* 1 if all three vertices lie on one box face other than the substrate */
static int on_face(const struct filter *fl, const double tri[9])
{
	for (int face = 0; face < 6; face++) {
		if (face == 4)      /* zmin: the substrate stays */
			continue;
		int d = face / 2;
		double v = fl->f->bounds[face];
		int all = 1;
		for (int q = 0; q < 3 && all; q++)
			all = fabs(tri[3 * q + d] - v) <= fl->tol[d];
		if (all)
			return 1;
	}
	return 0;
}

static void filter_emit(void *ctx, const double tri[9])
{
	struct filter *fl = ctx;
	double m[9];
	if (fl->zl) {   /* level coordinates to z (fmm_levels) */
		for (int q = 0; q < 9; q++)
			m[q] = q % 3 == 2 ? fmm_level_z(fl->zl, fl->nk, tri[q]) : tri[q];
		tri = m;
	}
	if (on_face(fl, tri))
		return;
	fl->emit(fl->ctx, tri);
	fl->count++;
}

/* t <= 0: the resist top over the columns c0[d] <= i < c1[d] (clipped to
 * the grid's), two triangles per cell on the iso.h diagonal, normals
 * down into the resist */
static long flat_top(const struct fmm *f, const int c0[2], const int c1[2], iso_emit emit,
		     void *ctx)
{
	long count = 0;
	double z = f->bounds[5];
	int lo[2], hi[2];
	for (int d = 0; d < 2; d++) {
		lo[d] = c0[d] < 0 ? 0 : c0[d];
		hi[d] = c1[d] > f->n[d] - 1 ? f->n[d] - 1 : c1[d];
	}
	for (int j = lo[1]; j < hi[1]; j++)
		for (int i = lo[0]; i < hi[0]; i++) {
			double x0 = f->bounds[0] + i * f->h[0], y0 = f->bounds[2] + j * f->h[1];
			double x1 = i + 2 == f->n[0] ? f->bounds[1] : x0 + f->h[0];
			double y1 = j + 2 == f->n[1] ? f->bounds[3] : y0 + f->h[1];
			double a[9] = {x0, y0, z, x1, y1, z, x1, y0, z};
			double b[9] = {x0, y0, z, x0, y1, z, x1, y1, z};
			emit(ctx, a);
			emit(ctx, b);
			count += 2;
		}
	return count;
}

/* The levels a set is extracted on: the grid g (f's own, or fmm_levels'
 * with the z of its levels zl, nk of them). */
struct levels {
	const struct fmm *g;
	const double *zl;
	int nk;
	double tol;             /* the decimation bound left, um */
};

/* The surface over the cells c0[d] <= i < c1[d] (iso_surface_window's
 * numbering, the pad's layers included) of the grid lv (NULL: f's own):
 * fmm_surface for a part of the grid, the parts of a partition giving its
 * triangles in its order. */
static long surface_window(const struct fmm *f, const struct levels *lv, double t, const int c0[3],
			   const int c1[3], iso_emit emit, void *ctx)
{
	/* a surface needs cells: a grid one node thick in some axis has none */
	if (f->n[0] < 2 || f->n[1] < 2 || f->n[2] < 2)
		return 0;
	if (t <= 0)
		return flat_top(f, c0, c1, emit, ctx);
	struct filter fl = {f, lv ? lv->zl : NULL, lv ? lv->nk : 0, {0, 0, 0}, emit, ctx, 0};
	/* iso.h snaps face caps onto the faces exactly; a millionth of a cell
	 * only guards against the rounding of a face coordinate */
	for (int d = 0; d < 3; d++)
		fl.tol[d] = 1e-6 * f->h[d];
	const struct fmm *g = lv ? lv->g : f;
	if (g->n[2] < 2)
		return 0;
	iso_surface_window(g->t, g->rate, g->n[0], g->n[1], g->n[2], g->bounds, t, 1, c0, c1,
			   filter_emit, &fl);
	return fl.count;
}

long fmm_surface(const struct fmm *f, double t, iso_emit emit, void *ctx)
{
	int c0[3] = {-1, -1, -1}, c1[3] = {f->n[0], f->n[1], f->n[2]};
	return surface_window(f, NULL, t, c0, c1, emit, ctx);
}

struct tris {
	double *v;              /* 9 per triangle */
	size_t n, cap;
};

static void collect(void *ctx, const double tri[9])
{
	struct tris *tr = ctx;
	xgrow(&tr->v, &tr->cap, 9 * (tr->n + 1), sizeof *tr->v);
	memcpy(tr->v + 9 * tr->n, tri, 9 * sizeof *tri);
	tr->n++;
}

double fmm_default_tol(const struct fmm *f)
{
	return FMM_TOL_FRACTION * fmin(f->h[0], f->h[1]);
}

/* The x-y tiles a set is decimated in: ntile[d] per axis, of about equal
 * numbers of cells, at most FMM_TILE_CELLS; tile of cell i along d is
 * i * ntile[d] / cells[d]. */
struct tiling {
	int ntile[2], cells[2];
};

static struct tiling tiling_of(const struct fmm *f)
{
	struct tiling tl;
	for (int d = 0; d < 2; d++) {
		tl.cells[d] = f->n[d] > 1 ? f->n[d] - 1 : 1;
		tl.ntile[d] = (tl.cells[d] + FMM_TILE_CELLS - 1) / FMM_TILE_CELLS;
	}
	return tl;
}

/* tile k's seams: its sides inside the box (outer sides: none) */
static void tile_keep(const struct fmm *f, const struct tiling *tl, int k, double keep[4])
{
	int a[2] = {k % tl->ntile[0], k / tl->ntile[0]};
	for (int d = 0; d < 2; d++)
		for (int e = 0; e < 2; e++) {
			int t = a[d] + e;       /* the tile boundary number */
			/* the first cell of tile t: least i with i * nt / cells >= t */
			long i = ((long)t * tl->cells[d] + tl->ntile[d] - 1) / tl->ntile[d];
			keep[2 * d + e] = t == 0 || t == tl->ntile[d] ? INFINITY
								       : f->bounds[2 * d] + (double)i * f->h[d];
		}
}

double fmm_weld_eps(const struct fmm *f)
{
	/* iso.h computes an edge's crossing in each tetrahedron holding it,
	 * equal to rounding: a billionth of a cell welds them, and places a
	 * vertex on a box face (the caps are snapped onto the faces) */
	return 1e-9 * fmax(f->h[0], fmax(f->h[1], f->h[2]));
}

/* Whether the triangles of m cross themselves (surf_crossings, measure's
 * test, in the rate box). */
static int tile_crosses(const struct fmm *f, const struct tri_mesh *m)
{
	struct surf *s = surf_new(f->bounds);
	for (size_t i = 0; i < m->nt; i++) {
		double tri[9];
		for (int c = 0; c < 3; c++)
			memcpy(tri + 3 * c, m->p + 3 * (size_t)m->tv[3 * i + c], 3 * sizeof *tri);
		surf_add(s, tri);
	}
	long c = surf_crossings(s, 1);
	surf_free(s);
	return c > 0;
}

/* Decimation bounds tried in turn, as fractions of tol: a collapse is
 * checked against its own star only, so on thin walls (standing waves
 * without bake) a sequence of them may push a triangle through another
 * that shares no vertex with it; a smaller bound moves less. */
static const double TOL_STEPS[] = {1, 0.25};
enum { NTOL_STEPS = sizeof TOL_STEPS / sizeof TOL_STEPS[0] };

size_t fmm_decimate_tile(const struct fmm *f, struct tri_weld *w, double tol, const double keep[4],
			 struct tri_mesh *out)
{
	double eps = fmm_weld_eps(f);
	/* the welded tile as extracted, kept for a retry and the fallback */
	struct tri_mesh dense = {0};
	dense.nv = tri_weld_take(w, &dense.p, &dense.tv, &dense.nt);
	for (int q = 0; q < NTOL_STEPS; q++) {
		tri_decimate_mesh(&dense, TOL_STEPS[q] * tol, f->bounds, eps, keep, NULL, out);
		if (!tile_crosses(f, out))
			break;
		tri_mesh_free(out);
		/* the extracted triangles as they are, if every bound crosses
		 * (marching tetrahedra of one field never do) */
		if (q + 1 == NTOL_STEPS) {
			*out = dense;
			return out->nt;
		}
	}
	tri_mesh_free(&dense);
	return out->nt;
}

/* The solution sampled at every refine[d]-th node: the rate grid (f
 * itself without refinement: the caller frees only a copy). */
static struct fmm *coarse_view(const struct fmm *f)
{
	if (f->refine[0] <= 1 && f->refine[1] <= 1 && f->refine[2] <= 1)
		return (struct fmm *)f;        /* the rate grid itself: shared, not copied */
	struct fmm *c = xcalloc(1, sizeof *c);
	*c = *f;
	size_t r[3], total = 1;
	for (int d = 0; d < 3; d++) {
		r[d] = f->refine[d] > 0 ? (size_t)f->refine[d] : 1;
		c->n[d] = (int)((size_t)(f->n[d] - 1) / r[d] + 1);
		c->h[d] = f->h[d] * (double)r[d];
		c->refine[d] = 1;
		total *= (size_t)c->n[d];
	}
	c->t = xreallocarray(NULL, total, sizeof *c->t);
	c->rate = f->rate ? xreallocarray(NULL, total, sizeof *c->rate) : NULL;
	size_t q = 0;
	for (size_t k = 0; k < (size_t)c->n[2]; k++)
		for (size_t j = 0; j < (size_t)c->n[1]; j++)
			for (size_t i = 0; i < (size_t)c->n[0]; i++, q++) {
				size_t n = (k * r[2] * (size_t)f->n[1] + j * r[1]) * (size_t)f->n[0] +
					   i * r[0];
				c->t[q] = f->t[n];
				if (c->rate)
					c->rate[q] = f->rate[n];
			}
	return c;
}

/* triangle i as a closed curve p1 p2 p3 p1 (fmt_plot_curves formats in
 * parallel), in 3D and projected on x-y */
static void get3(void *ctx, size_t i, double *c)
{
	const struct tris *tr = ctx;
	memcpy(c, tr->v + 9 * i, 9 * sizeof *c);
	memcpy(c + 9, tr->v + 9 * i, 3 * sizeof *c);
}

static void get2(void *ctx, size_t i, double *c)
{
	const double *v = ((const struct tris *)ctx)->v + 9 * i;
	double q[8] = {v[0], v[1], v[3], v[4], v[6], v[7], v[0], v[1]};
	memcpy(c, q, sizeof q);
}

/* Dense sets (-dense, -tol 0): a batch of sets extracted in parallel, one
 * set per job, so the triangles do not depend on the thread count. */
struct batch {
	const struct fmm *f;
	const double *times;
	struct tris *tr;
	int dense;
};

static void extract_range(void *ctx, size_t lo, size_t hi, int worker)
{
	(void)worker;
	struct batch *b = ctx;
	for (size_t k = lo; k < hi; k++) {
		struct tris *tr = &b->tr[k];
		tr->n = 0;
		fmm_surface(b->f, b->times[k], collect, tr);
		if (!b->dense)
			tr->n = fmm_compact(b->f, &tr->v, tr->n, &tr->cap);
	}
}

/* Decimated sets: every (set, tile) of a batch is one job that extracts
 * the tile's cells alone (surface_window) and decimates them, so a job's
 * memory is bounded by its tile's dense soup and only the decimated
 * triangles are kept; a tile whose nodes all developed before the
 * previous set's time holds the same surface (the substrate) and is
 * copied from that set instead. */
struct tiled {
	const struct fmm *f;
	struct levels *lv;      /* per set of the batch, the grid its tiles are
				 * extracted on */
	const double *times;    /* the batch's times; times[-1] the previous set's if prev */
	int prev;               /* a set was written before the batch */
	struct tiling tl;
	const double *tmax;     /* per tile: the latest arrival time of its nodes */
	struct tri_mesh *out;   /* per job (set q, tile k: q * ntiles + k) */
	struct tri_weld *weld;  /* per worker: a tile's dense surface, welded as
				 * it is extracted (its soup is never held) */
};

/* the cells of tile k along x and y (iso_surface_window's numbering: the
 * first and last tiles take the pad's layer), all of z */
static void tile_cells(const struct fmm *f, const struct tiling *tl, int k, int c0[3], int c1[3])
{
	int a[2] = {k % tl->ntile[0], k / tl->ntile[0]};
	for (int d = 0; d < 2; d++) {
		/* the first cell of tile t: least i with i * nt / cells >= t */
		long i0 = ((long)a[d] * tl->cells[d] + tl->ntile[d] - 1) / tl->ntile[d];
		long i1 = ((long)(a[d] + 1) * tl->cells[d] + tl->ntile[d] - 1) / tl->ntile[d];
		c0[d] = a[d] == 0 ? -1 : (int)i0;
		c1[d] = a[d] + 1 == tl->ntile[d] ? f->n[d] : (int)i1;
	}
	c0[2] = -1;
	c1[2] = f->n[2];
}

/* per tile, the latest arrival time over the nodes of its cells */
static double *tile_tmax(const struct fmm *f, const struct tiling *tl)
{
	size_t nt = (size_t)tl->ntile[0] * (size_t)tl->ntile[1];
	double *m = xreallocarray(NULL, nt, sizeof *m);
	for (size_t k = 0; k < nt; k++) {
		int c0[3], c1[3];
		tile_cells(f, tl, (int)k, c0, c1);
		double w = -INFINITY;
		for (int kz = 0; kz < f->n[2]; kz++)
			for (int j = c0[1] < 0 ? 0 : c0[1]; j <= c1[1] && j < f->n[1]; j++) {
				const double *row = f->t + ((size_t)kz * (size_t)f->n[1] + (size_t)j) *
								   (size_t)f->n[0];
				for (int i = c0[0] < 0 ? 0 : c0[0]; i <= c1[0] && i < f->n[0]; i++)
					w = fmax(w, row[i]);
			}
		m[k] = w;
	}
	return m;
}

/* whether set q of the batch copies tile k from the set before it */
static int tile_same(const struct tiled *b, int q, size_t k)
{
	if (q == 0 && !b->prev)
		return 0;
	double t0 = b->times[q - 1], t1 = b->times[q];
	return t0 > 0 && t1 > 0 && b->tmax[k] < t0 && b->tmax[k] < t1;
}

static void weld_collect(void *ctx, const double tri[9])
{
	tri_weld_add(ctx, tri);
}

static void tile_range(void *ctx, size_t lo, size_t hi, int worker)
{
	struct tiled *b = ctx;
	size_t nt = (size_t)b->tl.ntile[0] * (size_t)b->tl.ntile[1];
	struct tri_weld *w = &b->weld[worker];
	for (size_t j = lo; j < hi; j++) {
		int q = (int)(j / nt), k = (int)(j % nt);
		struct tri_mesh *o = &b->out[j];
		o->nt = 0;
		if (tile_same(b, q, (size_t)k))
			continue;
		int c0[3], c1[3];
		double keep[4];
		tile_cells(b->lv[q].g, &b->tl, k, c0, c1);
		tile_keep(b->f, &b->tl, k, keep);
		w->eps = fmm_weld_eps(b->f);
		surface_window(b->f, &b->lv[q], b->times[q], c0, c1, weld_collect, w);
		tri_mesh_free(o);
		fmm_decimate_tile(b->f, w, b->lv[q].tol, keep, o);
	}
}

/* one set's tiles as one list of triangles (for the writers' get) */
struct set_view {
	const struct tri_mesh *tile;
	const size_t *start;    /* ntiles + 1 prefix sums of the counts */
	size_t nt;
};

/* triangle i of the set: its three corners' coordinates */
static void view_tri(const struct set_view *sv, size_t i, const double *c[3])
{
	size_t lo = 0, hi = sv->nt;     /* the tile k with start[k] <= i < start[k + 1] */
	while (hi - lo > 1) {
		size_t mid = (lo + hi) / 2;
		if (sv->start[mid] <= i)
			lo = mid;
		else
			hi = mid;
	}
	const struct tri_mesh *m = &sv->tile[lo];
	const int *tv = m->tv + 3 * (i - sv->start[lo]);
	for (int s = 0; s < 3; s++)
		c[s] = m->p + 3 * (size_t)tv[s];
}

static void view3(void *ctx, size_t i, double *c)
{
	const double *v[3];
	view_tri(ctx, i, v);
	for (int s = 0; s < 4; s++)
		memcpy(c + 3 * s, v[s % 3], 3 * sizeof *c);
}

static void view2(void *ctx, size_t i, double *c)
{
	const double *v[3];
	view_tri(ctx, i, v);
	double q[8] = {v[0][0], v[0][1], v[1][0], v[1][1], v[2][0], v[2][1], v[0][0], v[0][1]};
	memcpy(c, q, sizeof q);
}

static void write_set(struct plot_writer *w3, struct plot_writer *w2, const struct fmm *f,
		      double t, size_t n, void (*g3)(void *, size_t, double *),
		      void (*g2)(void *, size_t, double *), void *ctx)
{
	if (n > PLOT_MAX_COUNT)
		die("fmm: %zu triangles at t = %g s, more than a plot file holds", n, t);
	if (w3) {
		fmt_plot_begin_set(w3, f->bounds, (long)n);
		fmt_plot_curves(w3, n, 4, g3, ctx);
	}
	if (w2) {
		fmt_plot_begin_set(w2, f->bounds, (long)n);
		fmt_plot_curves(w2, n, 4, g2, ctx);
	}
}

static void tri_mesh_copy(struct tri_mesh *to, const struct tri_mesh *from)
{
	tri_mesh_free(to);
	to->p = xreallocarray(NULL, 3 * from->nv + 1, sizeof *to->p);
	to->tv = xreallocarray(NULL, 3 * from->nt + 1, sizeof *to->tv);
	memcpy(to->p, from->p, 3 * from->nv * sizeof *to->p);
	memcpy(to->tv, from->tv, 3 * from->nt * sizeof *to->tv);
	to->nv = from->nv;
	to->nt = from->nt;
}

static void levels_free(const struct fmm *f, struct levels *lv)
{
	if (lv->g != f)
		fmm_free((struct fmm *)lv->g);
	free((double *)lv->zl);
	*lv = (struct levels){NULL, NULL, 0, 0};
}

/* The levels of the set at time t (t <= 0, the flat top: f's own) within
 * a share of tol, and the decimation bound left: tol less the levels'
 * estimate, with a margin for the estimate's own error. */
static void levels_of(const struct fmm *f, struct levels *lv, double t, double tmax, double tol)
{
	levels_free(f, lv);
	if (t <= 0) {
		*lv = (struct levels){f, NULL, 0, tol};
		return;
	}
	double *zl, used;
	lv->g = fmm_levels(f, t, tmax, FMM_LEVEL_FRACTION * tol, &zl, &used);
	if (3 * (long)lv->g->n[2] > (long)f->n[2]) {
		fmm_free((struct fmm *)lv->g);
		free(zl);
		lv->g = fmm_levels(f, t, tmax, FMM_LEVEL_FRACTION_LOW * tol, &zl, &used);
	}
	if (3 * (long)lv->g->n[2] > (long)f->n[2]) {  /* too few removed to pay */
		fmm_free((struct fmm *)lv->g);
		free(zl);
		*lv = (struct levels){f, NULL, 0, tol};
		return;
	}
	lv->zl = zl;
	lv->nk = lv->g->n[2];
	lv->tol = tol - FMM_LEVEL_MARGIN * used;
}

static void write_tiled(const struct fmm *f, const double *times, int ntimes,
			struct plot_writer *w3, struct plot_writer *w2, double tol)
{
	int nb = par_threads();
	/* the surfaces extracted on z levels within a share of tol, and
	 * decimated within the rest */
	double tmax = 0;
	for (int q = 0; q < ntimes; q++)
		tmax = fmax(tmax, times[q]);
	struct levels *lv = xcalloc((size_t)nb, sizeof *lv);
	struct tiled b = {f, lv, times, 0, tiling_of(f), NULL, NULL, NULL};
	size_t nt = (size_t)b.tl.ntile[0] * (size_t)b.tl.ntile[1];
	double *tmaxs = tile_tmax(f, &b.tl);
	b.tmax = tmaxs;
	struct tri_mesh *out = xcalloc((size_t)nb * nt, sizeof *out);
	struct tri_mesh *last = xcalloc(nt, sizeof *last);      /* the previous set's tiles */
	b.weld = xcalloc((size_t)nb, sizeof *b.weld);
	size_t *start = xreallocarray(NULL, nt + 1, sizeof *start);
	for (int k0 = 0; k0 < ntimes; k0 += nb) {
		int m = ntimes - k0 < nb ? ntimes - k0 : nb;
		b.times = times + k0;
		b.prev = k0 > 0;
		b.out = out;
		for (int q = 0; q < m; q++)
			levels_of(f, &lv[q], times[k0 + q], tmax, tol);
		par_for((size_t)m * nt, 1, tile_range, &b);
		for (int q = 0; q < m; q++) {
			struct tri_mesh *set = out + (size_t)q * nt;
			start[0] = 0;
			for (size_t k = 0; k < nt; k++) {
				if (tile_same(&b, q, k)) {
					const struct tri_mesh *from = q > 0 ? &out[(size_t)(q - 1) * nt + k] : &last[k];
					tri_mesh_copy(&set[k], from);
				}
				start[k + 1] = start[k] + set[k].nt;
			}
			struct set_view sv = {set, start, nt};
			write_set(w3, w2, f, times[k0 + q], start[nt], view3, view2, &sv);
		}
		for (size_t k = 0; k < nt; k++) {       /* the batch's last set is kept */
			struct tri_mesh x = last[k];
			last[k] = out[(size_t)(m - 1) * nt + k];
			out[(size_t)(m - 1) * nt + k] = x;
		}
	}
	for (size_t j = 0; j < (size_t)nb * nt; j++)
		tri_mesh_free(&out[j]);
	for (size_t k = 0; k < nt; k++)
		tri_mesh_free(&last[k]);
	for (int q = 0; q < nb; q++)
		tri_weld_free(&b.weld[q]);
	free(out);
	free(last);
	free(b.weld);
	free(start);
	free(tmaxs);
	for (int q = 0; q < nb; q++)
		levels_free(f, &lv[q]);
	free(lv);
}

void fmm_write_curves(const struct fmm *fine, const double *times, int ntimes,
		      const char *path3d, const char *path2d, int dense, double tol)
{
	struct fmm *f = coarse_view(fine);
	if (tol < 0)
		tol = fmm_default_tol(f);
	struct plot_writer *w3 = path3d ? fmt_plot_open(path3d, 3) : NULL;
	struct plot_writer *w2 = path2d ? fmt_plot_open(path2d, 2) : NULL;
	fmt_plot_labels(w3, fmt_labels_std(LABELS_SURFACE));
	fmt_plot_labels(w2, fmt_labels_std(LABELS_TOPVIEW));
	if (!dense && tol > 0) {
		write_tiled(f, times, ntimes, w3, w2, tol);
	} else {
		/* sets are extracted a thread's worth at a time and written
		 * in order */
		int nb = par_threads();
		struct tris *all = xcalloc((size_t)nb, sizeof *all);
		for (int k0 = 0; k0 < ntimes; k0 += nb) {
			int m = ntimes - k0 < nb ? ntimes - k0 : nb;
			struct batch b = {f, times + k0, all, dense};
			par_for((size_t)m, 1, extract_range, &b);
			for (int q = 0; q < m; q++)
				write_set(w3, w2, f, times[k0 + q], all[q].n, get3, get2, &all[q]);
		}
		for (int q = 0; q < nb; q++)
			free(all[q].v);
		free(all);
	}
	if (f != fine)
		fmm_free(f);
	if (w3)
		fmt_plot_close(w3);
	if (w2)
		fmt_plot_close(w2);
}
