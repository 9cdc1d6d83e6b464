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
#include "tri_decimate.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct filter {
	const struct fmm *f;
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
	if (on_face(fl, tri))
		return;
	fl->emit(fl->ctx, tri);
	fl->count++;
}

/* t <= 0: the resist top, two triangles per cell on the iso.h diagonal,
 * normals down into the resist */
static long flat_top(const struct fmm *f, iso_emit emit, void *ctx)
{
	long count = 0;
	double z = f->bounds[5];
	for (int j = 0; j + 1 < f->n[1]; j++)
		for (int i = 0; i + 1 < f->n[0]; i++) {
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

long fmm_surface(const struct fmm *f, double t, iso_emit emit, void *ctx)
{
	/* a surface needs cells: a grid one node thick in some axis has none */
	if (f->n[0] < 2 || f->n[1] < 2 || f->n[2] < 2)
		return 0;
	if (t <= 0)
		return flat_top(f, emit, ctx);
	struct filter fl = {f, {0, 0, 0}, emit, ctx, 0};
	/* iso.h snaps face caps onto the faces exactly; a millionth of a cell
	 * only guards against the rounding of a face coordinate */
	for (int d = 0; d < 3; d++)
		fl.tol[d] = 1e-6 * f->h[d];
	iso_surface_speed(f->t, f->rate, f->n[0], f->n[1], f->n[2], f->bounds, t, 1, filter_emit,
			  &fl);
	return fl.count;
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

/* the tile of a triangle: that of the cell holding its centroid */
static int tile_of(const struct fmm *f, const struct tiling *tl, const double *t)
{
	int a[2];
	for (int d = 0; d < 2; d++) {
		double c = (t[d] + t[3 + d] + t[6 + d]) / 3;
		long i = f->h[d] > 0 ? (long)floor((c - f->bounds[2 * d]) / f->h[d]) : 0;
		i = i < 0 ? 0 : i >= tl->cells[d] ? tl->cells[d] - 1 : i;
		a[d] = (int)(i * tl->ntile[d] / tl->cells[d]);
	}
	return a[1] * tl->ntile[0] + a[0];
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

size_t fmm_decimate_tile(const struct fmm *f, double *v, size_t n, double tol, const double keep[4])
{
	double h = fmax(f->h[0], fmax(f->h[1], f->h[2]));
	/* iso.h computes an edge's crossing in each tetrahedron holding it,
	 * equal to rounding: a billionth of a cell welds them, and places a
	 * vertex on a box face (the caps are snapped onto the faces) */
	return tri_decimate(v, n, tol, 1e-9 * h, f->bounds, 1e-9 * h, keep, NULL);
}

/* The solution sampled at every refine[d]-th node: the rate grid. */
static struct fmm *coarse_view(const struct fmm *f)
{
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

/* the sets of one batch, extracted in parallel: one per time */
struct batch {
	const struct fmm *f;
	const double *times;
	struct tris *tr;
	int dense;
	double tol;             /* decimation bound, um (0: exact-flat compaction only) */
	/* decimation: set s's triangles grouped by tile, job j = s * ntiles + k
	 * the triangles first[j] to first[j] + count[j] - 1 of set s, count[j]
	 * then the number kept */
	struct tiling tl;
	size_t *first, *count;
};

static void extract_range(void *ctx, size_t lo, size_t hi, int worker)
{
	(void)worker;
	struct batch *b = ctx;
	for (size_t k = lo; k < hi; k++) {
		struct tris *tr = &b->tr[k];
		tr->n = 0;
		fmm_surface(b->f, b->times[k], collect, tr);
		if (!b->dense && !(b->tol > 0))
			tr->n = fmm_compact(b->f, &tr->v, tr->n, &tr->cap);
	}
}

static void decimate_range(void *ctx, size_t lo, size_t hi, int worker)
{
	(void)worker;
	struct batch *b = ctx;
	size_t nt = (size_t)b->tl.ntile[0] * (size_t)b->tl.ntile[1];
	for (size_t j = lo; j < hi; j++) {
		double keep[4];
		tile_keep(b->f, &b->tl, (int)(j % nt), keep);
		b->count[j] = fmm_decimate_tile(b->f, b->tr[j / nt].v + 9 * b->first[j], b->count[j],
						b->tol, keep);
	}
}

/* set tr's triangles grouped by tile (stably), their ranges in first and
 * count */
static void group(const struct fmm *f, const struct tiling *tl, struct tris *tr, size_t *first,
		  size_t *count)
{
	size_t nt = (size_t)tl->ntile[0] * (size_t)tl->ntile[1];
	int *tile = xreallocarray(NULL, tr->n + 1, sizeof *tile);
	memset(count, 0, nt * sizeof *count);
	for (size_t i = 0; i < tr->n; i++) {
		tile[i] = tile_of(f, tl, tr->v + 9 * i);
		count[tile[i]]++;
	}
	size_t at = 0;
	for (size_t k = 0; k < nt; k++) {
		first[k] = at;
		at += count[k];
	}
	if (nt > 1) {
		double *w = xreallocarray(NULL, 9 * tr->n + 1, sizeof *w);
		size_t *fill = xcalloc(nt, sizeof *fill);
		for (size_t i = 0; i < tr->n; i++) {
			size_t k = (size_t)tile[i];
			memcpy(w + 9 * (first[k] + fill[k]++), tr->v + 9 * i, 9 * sizeof *w);
		}
		free(fill);
		free(tr->v);
		tr->v = w;
		tr->cap = 9 * tr->n + 1;
	}
	free(tile);
}

/* the kept triangles of each tile moved together, in tile order */
static void ungroup(struct tris *tr, const size_t *first, const size_t *count, size_t nt)
{
	size_t out = 0;
	for (size_t k = 0; k < nt; k++) {
		if (out != first[k])
			memmove(tr->v + 9 * out, tr->v + 9 * first[k], 9 * count[k] * sizeof *tr->v);
		out += count[k];
	}
	tr->n = out;
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
	/* sets are extracted a thread's worth at a time (each set is one
	 * thread's work, so the triangles do not depend on the thread
	 * count), and written in order */
	int nb = par_threads();
	struct tris *all = xcalloc((size_t)nb, sizeof *all);
	struct tiling tl = tiling_of(f);
	size_t nt = (size_t)tl.ntile[0] * (size_t)tl.ntile[1];
	size_t *first = xreallocarray(NULL, (size_t)nb * nt, sizeof *first);
	size_t *count = xreallocarray(NULL, (size_t)nb * nt, sizeof *count);
	for (int k0 = 0; k0 < ntimes; k0 += nb) {
		int m = ntimes - k0 < nb ? ntimes - k0 : nb;
		struct batch b = {f, times + k0, all, dense, tol, tl, first, count};
		par_for((size_t)m, 1, extract_range, &b);
		if (!dense && tol > 0) {
			/* every tile of every set one job: parallel even for one
			 * set, and the memory a job needs bounded by the tile */
			for (int q = 0; q < m; q++)
				group(f, &tl, &all[q], first + (size_t)q * nt, count + (size_t)q * nt);
			par_for((size_t)m * nt, 1, decimate_range, &b);
			for (int q = 0; q < m; q++)
				ungroup(&all[q], first + (size_t)q * nt, count + (size_t)q * nt, nt);
		}
		for (int q = 0; q < m; q++) {
			struct tris *tr = &all[q];
			int k = k0 + q;
			if (tr->n > PLOT_MAX_COUNT)
				die("fmm: %zu triangles at t = %g s, more than a plot file holds",
				    tr->n, times[k]);
			if (w3) {
				fmt_plot_begin_set(w3, f->bounds, (long)tr->n);
				fmt_plot_curves(w3, tr->n, 4, get3, tr);
			}
			if (w2) {
				fmt_plot_begin_set(w2, f->bounds, (long)tr->n);
				fmt_plot_curves(w2, tr->n, 4, get2, tr);
			}
		}
	}
	for (int q = 0; q < nb; q++)
		free(all[q].v);
	free(all);
	free(first);
	free(count);
	fmm_free(f);
	if (w3)
		fmt_plot_close(w3);
	if (w2)
		fmt_plot_close(w2);
}
