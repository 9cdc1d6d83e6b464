/*
 * fmm_query.c - point queries on a fast-marching solution: T anywhere
 * (trilinear), and the distance from a point to the developed surface
 * T = t, the measure by which etch's two engines are cross-checked
 * (median node distance of the ray-string mesh to the fast-marching
 * front, in grid cells).
 *
 * The distance starts from the first-order estimate |T - t| / |grad T|
 * (|grad T| = 1/R by the eikonal equation), refined by bracketing the
 * crossing along the gradient line and bisecting: near a smooth surface
 * the gradient is its normal, so this is the normal distance.  The point
 * found is on the surface, so its distance bounds the true one; the
 * triangles of the surface inside that ball are then searched for the
 * nearest, which makes the answer the Euclidean distance to the written
 * surface also where T has kinks (fronts that met) and the gradient line
 * goes astray.  For many points (fmm_distance_many, the cross-check's
 * statistic) the cells the surface cuts are listed once, bucketed, and
 * each point's search extracts only those of its block: the same
 * triangles, so the same distances, at a small part of the cost.
 */
#include "fmm.h"
#include "iso.h"
#include "par.h"
#include "surf.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Bisection steps: 60 halvings take any bracket below a double's
 * resolution of it. */
enum { BISECT_STEPS = 60, BRACKET_STEPS = 60 };

void fmm_cell(const struct fmm *f, const double p[3], int lo[3], double w[3])
{
	for (int d = 0; d < 3; d++) {
		lo[d] = 0;
		w[d] = 0;
		if (f->n[d] < 2)
			continue;
		double x = fmin(fmax(p[d], f->bounds[2 * d]), f->bounds[2 * d + 1]);
		double u = (x - f->bounds[2 * d]) / f->h[d];
		lo[d] = (int)u;
		if (lo[d] > f->n[d] - 2)
			lo[d] = f->n[d] - 2;
		w[d] = u - lo[d];
	}
}

static double trilinear(const struct fmm *f, const double *v, const double p[3])
{
	int lo[3];
	double w[3];
	fmm_cell(f, p, lo, w);
	size_t sy = (size_t)f->n[0], sz = sy * (size_t)f->n[1];
	double sum = 0;
	for (int q = 0; q < 8; q++) {
		double wq = 1;
		size_t n = 0;
		for (int d = 0; d < 3; d++) {
			int e = (q >> d) & 1;
			wq *= e ? w[d] : 1 - w[d];
			n += (size_t)(lo[d] + e) * (d == 0 ? 1 : d == 1 ? sy : sz);
		}
		if (wq > 0)
			sum += wq * v[n];
	}
	return sum;
}

double fmm_time_at(const struct fmm *f, const double p[3])
{
	return trilinear(f, f->t, p);
}

double fmm_rate_at(const struct fmm *f, const double p[3])
{
	return f->rate ? trilinear(f, f->rate, p) : 0;
}

/* grad T by central differences over half a cell, one-sided at the box */
static void gradient(const struct fmm *f, const double p[3], double g[3])
{
	for (int d = 0; d < 3; d++) {
		g[d] = 0;
		if (f->n[d] < 2)
			continue;
		double a[3] = {p[0], p[1], p[2]}, b[3] = {p[0], p[1], p[2]};
		a[d] = fmax(p[d] - 0.5 * f->h[d], f->bounds[2 * d]);
		b[d] = fmin(p[d] + 0.5 * f->h[d], f->bounds[2 * d + 1]);
		if (b[d] > a[d])
			g[d] = (fmm_time_at(f, b) - fmm_time_at(f, a)) / (b[d] - a[d]);
	}
}

static double along(const struct fmm *f, const double p[3], const double u[3], double s)
{
	double x[3] = {p[0] + s * u[0], p[1] + s * u[1], p[2] + s * u[2]};
	return fmm_time_at(f, x);
}

struct nearest {
	const double *p;
	double best2;
};

static void nearest_emit(void *ctx, const double tri[9])
{
	struct nearest *nr = ctx;
	double e = surf_point_tri_dist2(nr->p, tri, tri + 3, tri + 6);
	if (e < nr->best2)
		nr->best2 = e;
}

/* Largest block searched for the exact distance, in cells: beyond it
 * the gradient-line distance stands (a query costs at most this much
 * isosurface work). */
#define MAX_BLOCK_CELLS 4000000.0

/* Cells per axis of a bucket of the cut-cell index. */
enum { CUT_BUCKET = 4 };

/* The cells of the grid that the surface T = t cuts (some corners below
 * t, some not: the only cells marching tetrahedra emits triangles in),
 * bucketed by CUT_BUCKET^3 blocks of cells: built once for many points,
 * so that a point's block search visits its cut cells, not every cell. */
struct cut_index {
	int nb[3];              /* buckets per axis */
	size_t *start;          /* bucket b's cells: cell[start[b]] to cell[start[b + 1]] */
	int (*cell)[3];         /* lower corners of the cut cells, bucket by bucket */
};

/* A worker's block of values (block-sized, written only at the corners
 * of the cells it extracts). */
struct dist_scratch {
	double *v;
	size_t cap;
};

static int cell_cut(const struct fmm *f, int i, int j, int k, double t)
{
	size_t sy = (size_t)f->n[0], sz = sy * (size_t)f->n[1];
	const double *c = f->t + (size_t)k * sz + (size_t)j * sy + (size_t)i;
	int below = 0;
	for (int q = 0; q < 8; q++)
		below += c[(q & 1) + ((q >> 1) & 1) * sy + ((q >> 2) & 1) * sz] < t;
	return below > 0 && below < 8;
}

static size_t bucket_of(const struct cut_index *x, int i, int j, int k)
{
	return ((size_t)(k / CUT_BUCKET) * (size_t)x->nb[1] + (size_t)(j / CUT_BUCKET)) *
		       (size_t)x->nb[0] + (size_t)(i / CUT_BUCKET);
}

/* The index of the cells cut by T = t (f has two nodes or more per axis). */
static void cut_index_build(const struct fmm *f, double t, struct cut_index *x)
{
	size_t nbk = 1;
	for (int d = 0; d < 3; d++) {
		x->nb[d] = (f->n[d] - 1 + CUT_BUCKET - 1) / CUT_BUCKET;
		nbk *= (size_t)x->nb[d];
	}
	x->start = xreallocarray(NULL, nbk + 1, sizeof *x->start);
	memset(x->start, 0, (nbk + 1) * sizeof *x->start);
	/* two passes: count the cut cells per bucket, then place them */
	for (int k = 0; k < f->n[2] - 1; k++)
		for (int j = 0; j < f->n[1] - 1; j++)
			for (int i = 0; i < f->n[0] - 1; i++)
				if (cell_cut(f, i, j, k, t))
					x->start[bucket_of(x, i, j, k) + 1]++;
	for (size_t b = 0; b < nbk; b++)
		x->start[b + 1] += x->start[b];
	x->cell = xreallocarray(NULL, x->start[nbk] + 1, sizeof *x->cell);
	size_t *fill = xreallocarray(NULL, nbk, sizeof *fill);
	memcpy(fill, x->start, nbk * sizeof *fill);
	for (int k = 0; k < f->n[2] - 1; k++)
		for (int j = 0; j < f->n[1] - 1; j++)
			for (int i = 0; i < f->n[0] - 1; i++)
				if (cell_cut(f, i, j, k, t)) {
					int *c = x->cell[fill[bucket_of(x, i, j, k)]++];
					c[0] = i, c[1] = j, c[2] = k;
				}
	free(fill);
}

/* The squared distance from p to grid cell c (its box, in the grid's
 * coordinates) */
static double cell_dist2(const struct fmm *f, const int c[3], const double p[3])
{
	double e = 0;
	for (int d = 0; d < 3; d++) {
		double a = f->bounds[2 * d] + c[d] * f->h[d], b = a + f->h[d];
		double g = p[d] < a ? a - p[d] : p[d] > b ? p[d] - b : 0;
		e += g * g;
	}
	return e;
}

/* The triangles of the block of nodes lo..hi (nb per axis, spanning b)
 * with the block's own coordinates: what iso_surface over the block
 * emits, cell by cell, but only for the cut cells the index lists, and
 * of those only the cells that can hold a triangle nearer than both lim
 * and the nearest so far (the box of the cell, widened by slack for the
 * rounding of the block's coordinates): the nearest distance at or
 * below lim is the one the whole block gives, to the last bit. */
static void block_from_index(const struct fmm *f, const struct cut_index *x,
			     struct dist_scratch *s, const int lo[3], const int hi[3],
			     const int nb[3], const double b[6], double t, double lim,
			     struct nearest *nr)
{
	double slack = 0;
	for (int d = 0; d < 3; d++)
		slack = fmax(slack, 1e-6 * f->h[d] + 1e-12 * (fabs(f->bounds[2 * d]) +
							      fabs(f->bounds[2 * d + 1]) +
							      fabs(nr->p[d])));
	size_t nn = (size_t)nb[0] * (size_t)nb[1] * (size_t)nb[2];
	if (nn > s->cap) {      /* no realloc: the old values need no copy */
		free(s->v);
		s->v = xreallocarray(NULL, nn, sizeof *s->v);
		s->cap = nn;
	}
	size_t sy = (size_t)f->n[0], sz = sy * (size_t)f->n[1];
	size_t by = (size_t)nb[0], bz = by * (size_t)nb[1];
	int b0[3], b1[3];
	for (int d = 0; d < 3; d++) {
		b0[d] = lo[d] / CUT_BUCKET;
		b1[d] = (hi[d] - 1) / CUT_BUCKET;
	}
	for (int bk = b0[2]; bk <= b1[2]; bk++)
		for (int bj = b0[1]; bj <= b1[1]; bj++)
			for (int bi = b0[0]; bi <= b1[0]; bi++) {
				size_t q = ((size_t)bk * (size_t)x->nb[1] + (size_t)bj) *
						   (size_t)x->nb[0] + (size_t)bi;
				for (size_t e = x->start[q]; e < x->start[q + 1]; e++) {
					const int *c = x->cell[e];
					if (c[0] < lo[0] || c[0] >= hi[0] || c[1] < lo[1] ||
					    c[1] >= hi[1] || c[2] < lo[2] || c[2] >= hi[2])
						continue;
					double reach = fmin(lim, sqrt(nr->best2)) + slack;
					if (cell_dist2(f, c, nr->p) > reach * reach)
						continue;
					int c0[3] = {c[0] - lo[0], c[1] - lo[1], c[2] - lo[2]};
					int c1[3] = {c0[0] + 1, c0[1] + 1, c0[2] + 1};
					for (int r = 0; r < 8; r++) {
						int u = r & 1, w = (r >> 1) & 1, z = (r >> 2) & 1;
						s->v[(size_t)(c0[2] + z) * bz + (size_t)(c0[1] + w) * by +
						     (size_t)(c0[0] + u)] =
							f->t[(size_t)(c[2] + z) * sz + (size_t)(c[1] + w) * sy +
							     (size_t)(c[0] + u)];
					}
					iso_surface_window(s->v, NULL, nb[0], nb[1], nb[2], b, t, 0, c0, c1,
							   nearest_emit, nr);
				}
			}
}

/* The distance from p to the triangulated surface T = t (the triangles
 * fmm_surface writes, without the caps), searched in blocks of cells
 * around p that double until the nearest triangle lies inside the ball
 * the block contains; INFINITY if none within the largest block.  With
 * an index x of the cut cells (and scratch s) only those are extracted:
 * the same triangles, in the block's own coordinates, so the same
 * distance to the last bit. */
static double surface_distance(const struct fmm *f, const struct cut_index *x,
			       struct dist_scratch *s, const double p[3], double t, double radius)
{
	double hmax = fmax(f->h[0], fmax(f->h[1], f->h[2]));
	radius = fmax(radius, 1e-3 * hmax);
	for (;;) {
		int lo[3], hi[3], nb[3], whole = 1;
		double cells = 1, b[6];
		for (int d = 0; d < 3; d++) {
			double u0 = (p[d] - radius - f->bounds[2 * d]) / f->h[d];
			double u1 = (p[d] + radius - f->bounds[2 * d]) / f->h[d];
			lo[d] = u0 <= 0 ? 0 : (int)fmin(floor(u0), f->n[d] - 2);
			hi[d] = u1 >= f->n[d] - 1 ? f->n[d] - 1 : (int)fmax(ceil(u1), lo[d] + 1);
			whole &= lo[d] == 0 && hi[d] == f->n[d] - 1;
			nb[d] = hi[d] - lo[d] + 1;
			cells *= nb[d] - 1;
			b[2 * d] = f->bounds[2 * d] + lo[d] * f->h[d];
			b[2 * d + 1] = hi[d] == f->n[d] - 1 ? f->bounds[2 * d + 1]
							     : f->bounds[2 * d] + hi[d] * f->h[d];
		}
		if (cells > MAX_BLOCK_CELLS)
			return INFINITY;
		struct nearest nr = {p, INFINITY};
		if (x) {
			block_from_index(f, x, s, lo, hi, nb, b, t, whole ? INFINITY : radius, &nr);
		} else {
			size_t nn = (size_t)nb[0] * (size_t)nb[1] * (size_t)nb[2];
			double *v = xreallocarray(NULL, nn, sizeof *v);
			size_t m = 0;
			for (int k = lo[2]; k <= hi[2]; k++)
				for (int j = lo[1]; j <= hi[1]; j++) {
					const double *row =
						f->t + ((size_t)k * (size_t)f->n[1] + (size_t)j) *
							       (size_t)f->n[0];
					for (int i = lo[0]; i <= hi[0]; i++)
						v[m++] = row[i];
				}
			iso_surface(v, nb[0], nb[1], nb[2], b, t, 0, nearest_emit, &nr);
			free(v);
		}
		double dist = sqrt(nr.best2);
		if (dist <= radius || whole)
			return dist;
		radius *= 2;
	}
}

/* fmm_distance, its exact search through the index x (with scratch s)
 * when x is not NULL */
static double distance(const struct fmm *f, const struct cut_index *x, struct dist_scratch *s,
		       const double p[3], double t)
{
	double q[3];
	for (int d = 0; d < 3; d++)
		q[d] = fmin(fmax(p[d], f->bounds[2 * d]), f->bounds[2 * d + 1]);
	double t0 = fmm_time_at(f, q);
	if (t0 >= 0.5 * FMM_UNREACHED)
		return FMM_UNREACHED;
	double phi0 = t0 - t;
	if (phi0 == 0)
		return 0;
	/* developed resist: the substrate below is surface too */
	double sub = INFINITY;
	if (phi0 < 0) {
		double b[3] = {q[0], q[1], f->bounds[4]};
		if (fmm_time_at(f, b) < t)
			sub = q[2] - f->bounds[4];
	}
	double hmax = fmax(f->h[0], fmax(f->h[1], f->h[2]));
	if (f->n[0] < 2 || f->n[1] < 2 || f->n[2] < 2)
		return sub < INFINITY ? sub : FMM_UNREACHED;
	double g[3];
	gradient(f, q, g);
	double gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
	double est = gn > 0 ? fabs(phi0) / gn : 2 * hmax;
	/* a crossing along the gradient line: a point of the surface, so an
	 * upper bound on the distance (and the distance itself where the
	 * surface is smooth on the scale of the distance) */
	double dline = INFINITY;
	if (gn > 0) {
		double sg = phi0 > 0 ? -1 : 1, u[3];
		for (int d = 0; d < 3; d++)
			u[d] = sg * g[d] / gn;
		double diag = 0;
		for (int d = 0; d < 3; d++)
			diag += (f->bounds[2 * d + 1] - f->bounds[2 * d]) *
				(f->bounds[2 * d + 1] - f->bounds[2 * d]);
		diag = sqrt(diag);
		double lo = 0, hi = est, step = est;
		int found = 0;
		for (int k = 0; k < BRACKET_STEPS && lo <= diag; k++) {
			double ph = along(f, q, u, hi) - t;
			if ((ph > 0) != (phi0 > 0) || ph == 0) {
				found = 1;
				break;
			}
			lo = hi;
			step *= 1.5;
			hi = lo + step;
		}
		if (found) {
			for (int k = 0; k < BISECT_STEPS; k++) {
				double mid = 0.5 * (lo + hi);
				if (mid <= lo || mid >= hi)
					break;
				double pm = along(f, q, u, mid) - t;
				if ((pm > 0) == (phi0 > 0) && pm != 0)
					lo = mid;
				else
					hi = mid;
			}
			dline = 0.5 * (lo + hi);
		}
	}
	/* where fronts meet (loops, the fingers of thesis Figure 8.16) T has
	 * a kink and the gradient line can miss the nearest part of the
	 * surface: search the triangles within the ball it gives */
	double bound = fmin(dline, sub);
	double dsurf = surface_distance(f, x, s, q, t, bound < INFINITY ? bound : est);
	double d = fmin(fmin(dline, sub), dsurf);
	return d < INFINITY ? d : est;
}

double fmm_distance(const struct fmm *f, const double p[3], double t)
{
	return distance(f, NULL, NULL, p, t);
}

struct many {
	const struct fmm *f;
	const struct cut_index *x;
	struct dist_scratch *s;        /* one per worker */
	const double *p;
	double t, *d;
};

static void many_range(void *ctx, size_t lo, size_t hi, int worker)
{
	struct many *m = ctx;
	for (size_t i = lo; i < hi; i++)
		m->d[i] = distance(m->f, m->x, m->s + worker, m->p + 3 * i, m->t);
}

void fmm_distance_many(const struct fmm *f, const double *p, size_t n, double t, double *d)
{
	if (n == 0)
		return;
	if (f->n[0] < 2 || f->n[1] < 2 || f->n[2] < 2) {        /* no cells: no search */
		for (size_t i = 0; i < n; i++)
			d[i] = distance(f, NULL, NULL, p + 3 * i, t);
		return;
	}
	struct cut_index x;
	cut_index_build(f, t, &x);
	int nw = par_threads();
	struct dist_scratch *s = xreallocarray(NULL, (size_t)nw, sizeof *s);
	memset(s, 0, (size_t)nw * sizeof *s);
	struct many m = {f, &x, s, p, t, d};
	par_for(n, 8, many_range, &m);
	for (int w = 0; w < nw; w++)
		free(s[w].v);
	free(s);
	free(x.start);
	free(x.cell);
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

void fmm_distance_stats(const struct fmm *f, const double *p, size_t n, double t,
			double *median, double *p95)
{
	*median = *p95 = 0;
	if (n == 0)
		return;
	double *d = xreallocarray(NULL, n, sizeof *d);
	fmm_distance_many(f, p, n, t, d);
	qsort(d, n, sizeof *d, cmp_double);
	/* nearest rank: the smallest value with at least q*n values at or below it */
	size_t im = (n + 1) / 2, i95 = (size_t)ceil(0.95 * (double)n);
	*median = d[im - 1];
	*p95 = d[(i95 < 1 ? 1 : i95) - 1];
	free(d);
}
