/*
 * fmm_compact.c - the fast-marching surface written compactly: flat
 * regions as large triangles.
 *
 * Marching tetrahedra (iso.h) cut every grid cell into six tetrahedra, so
 * a horizontal plane - the substrate where the resist has cleared, the
 * resist top of a t = 0 set, a top the developer lowers uniformly - comes
 * out as two to eight triangles per x-y cell.  Here the columns of cells
 * (i, j) whose whole surface is one such plane, exactly (the three z of
 * every triangle equal, bit for bit, and the triangles' areas summing to
 * the cell's), are joined into rectangles of equal z and orientation,
 * greedily (longest run in x, then as many rows as repeat it), and each
 * rectangle is written as a fan from its centre to the vertices on its
 * perimeter: its corners and every vertex the dense triangles had on it.
 * Those are the vertices the neighbouring columns' triangles have on the
 * shared faces (the Kuhn split triangulates a face alike from both
 * sides), so the mesh stays conforming, with no T-junction and no crack,
 * and covers the same points: area and enclosed volume are those of the
 * dense surface up to rounding.  Nothing else moves: the other triangles
 * are written as they were, in their order, and the rectangles follow in
 * row order.  A rectangle whose fan would need more triangles than it
 * replaces is left as it was.
 */
#include "fmm.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* grid line k of axis d, the same expression as iso.c's points */
static double line(const struct fmm *f, int d, int k)
{
	return f->bounds[2 * d] + (f->bounds[2 * d + 1] - f->bounds[2 * d]) * k / (f->n[d] - 1);
}

static int clampi(long v, int lo, int hi)
{
	return v < lo ? lo : v > hi ? hi : (int)v;
}

/* cell index along axis d holding coordinate x (clamped to the grid) */
static int cell_of(const struct fmm *f, int d, double x)
{
	double u = (x - f->bounds[2 * d]) / f->h[d];
	return clampi((long)floor(u), 0, f->n[d] - 2);
}

/* the cells of axis d that the closed range [lo, hi] enters: their
 * interior, or both neighbours of a grid line the range lies on */
static void cell_range(const struct fmm *f, int d, double lo, double hi, int *a, int *b)
{
	double u = (lo - f->bounds[2 * d]) / f->h[d], v = (hi - f->bounds[2 * d]) / f->h[d];
	long ia = (long)floor(u + 1e-9), ib = (long)ceil(v - 1e-9) - 1;
	if (ib < ia) {
		long r = lround(u);
		ia = r - 1;
		ib = r;
	}
	*a = clampi(ia, 0, f->n[d] - 2);
	*b = clampi(ib, 0, f->n[d] - 2);
}

static double tri_area_z(const double *t)
{
	return 0.5 * ((t[3] - t[0]) * (t[7] - t[1]) - (t[4] - t[1]) * (t[6] - t[0]));
}

struct col {
	double z, area;
	int sign;               /* +1 normal up, -1 down */
	int state;              /* 0 empty, 1 flat so far, -1 not flat, 2 merged */
	int ntri;
};

struct pt {
	double s, x, y;
};

static int pt_cmp(const void *a, const void *b)
{
	const struct pt *p = a, *q = b;
	if (p->s != q->s)
		return p->s < q->s ? -1 : 1;
	if (p->x != q->x)
		return p->x < q->x ? -1 : 1;
	return (p->y > q->y) - (p->y < q->y);
}

static int is_corner(const struct pt *p, double corner[4][2])
{
	for (int k = 0; k < 4; k++)
		if (p->x == corner[k][0] && p->y == corner[k][1])
			return 1;
	return 0;
}

static void push(double **v, size_t *n, size_t *cap, const double a[3], const double b[3],
		 const double c[3])
{
	xgrow(v, cap, 9 * (*n + 1), sizeof **v);
	double *t = *v + 9 * *n;
	memcpy(t, a, 3 * sizeof *t);
	memcpy(t + 3, b, 3 * sizeof *t);
	memcpy(t + 6, c, 3 * sizeof *t);
	(*n)++;
}

/* Sorts the n triangles v into the grid columns (cx a row): each
 * horizontal one into its column's record (home[t], or -1), and a column
 * any other triangle touches, or whose horizontal triangles differ in z
 * or side or do not cover it, marked -1. */
static void columns(const struct fmm *f, const double *v, size_t n, struct col *c, int *home)
{
	int cx = f->n[0] - 1, cy = f->n[1] - 1;
	for (size_t t = 0; t < n; t++) {
		const double *p = v + 9 * t;
		home[t] = -1;
		if (p[2] == p[5] && p[5] == p[8]) {
			int i = cell_of(f, 0, (p[0] + p[3] + p[6]) / 3);
			int j = cell_of(f, 1, (p[1] + p[4] + p[7]) / 3);
			size_t q = (size_t)j * (size_t)cx + (size_t)i;
			double a = tri_area_z(p);
			int s = a > 0 ? 1 : -1;
			home[t] = (int)q;
			c[q].ntri++;
			if (c[q].state == 0) {
				c[q].state = 1;
				c[q].z = p[2];
				c[q].sign = s;
			} else if (c[q].state == 1 && (c[q].z != p[2] || c[q].sign != s))
				c[q].state = -1;
			c[q].area += fabs(a);
			continue;
		}
		double lo[2], hi[2];
		for (int d = 0; d < 2; d++) {
			lo[d] = fmin(p[d], fmin(p[3 + d], p[6 + d]));
			hi[d] = fmax(p[d], fmax(p[3 + d], p[6 + d]));
		}
		int ia, ib, ja, jb;
		cell_range(f, 0, lo[0], hi[0], &ia, &ib);
		cell_range(f, 1, lo[1], hi[1], &ja, &jb);
		for (int j = ja; j <= jb; j++)
			for (int i = ia; i <= ib; i++)
				c[(size_t)j * (size_t)cx + (size_t)i].state = -1;
	}
	for (int j = 0; j < cy; j++)
		for (int i = 0; i < cx; i++) {
			struct col *q = &c[(size_t)j * (size_t)cx + (size_t)i];
			double cell = (line(f, 0, i + 1) - line(f, 0, i)) * (line(f, 1, j + 1) - line(f, 1, j));
			if (q->state == 1 && !(fabs(q->area - cell) <= 1e-9 * cell))
				q->state = -1;
		}
}

/* The horizontal triangles by column: bycol[start[q] .. start[q + 1])
 * are column q's, in their order (a counting sort). */
static size_t *by_column(const int *home, size_t n, size_t ncol, size_t **startp)
{
	size_t *start = *startp = xcalloc(ncol + 1, sizeof *start);
	for (size_t t = 0; t < n; t++)
		if (home[t] >= 0)
			start[home[t] + 1]++;
	for (size_t q = 0; q < ncol; q++)
		start[q + 1] += start[q];
	size_t *bycol = xreallocarray(NULL, start[ncol] + 1, sizeof *bycol), *fill = xcalloc(ncol, sizeof *fill);
	for (size_t t = 0; t < n; t++)
		if (home[t] >= 0) {
			size_t q = (size_t)home[t];
			bycol[start[q] + fill[q]++] = t;
		}
	free(fill);
	return bycol;
}

/* A rectangle of columns and the triangles of the grid, as compaction
 * reads them. */
struct rect {
	const struct fmm *f;
	const double *v;                /* the triangles */
	struct col *c;                  /* the columns, cx a row */
	int cx;
	const size_t *start, *bycol;    /* by_column */
	int i, j, w, h;                 /* the rectangle's first column, size */
	double X0, X1, Y0, Y1;          /* its sides */
};

/* The vertices on the perimeter of rectangle r, counter-clockwise from
 * (X0, Y0), one per place, in *pt; marks its columns 2 and counts their
 * triangles in *replaced.  Returns the count. */
static size_t perimeter(const struct rect *r, struct pt **ptp, size_t *cappt, long *replaced)
{
	double X0 = r->X0, X1 = r->X1, Y0 = r->Y0, Y1 = r->Y1;
	double W = X1 - X0, H = Y1 - Y0;
	size_t npt = 0;
	*replaced = 0;
	for (int jj = r->j; jj < r->j + r->h; jj++)
		for (int ii = r->i; ii < r->i + r->w; ii++) {
			size_t q = (size_t)jj * (size_t)r->cx + (size_t)ii;
			r->c[q].state = 2;
			*replaced += r->c[q].ntri;
			if (jj != r->j && jj != r->j + r->h - 1 && ii != r->i && ii != r->i + r->w - 1)
				continue;
			for (size_t k = r->start[q]; k < r->start[q + 1]; k++)
				for (int m = 0; m < 3; m++) {
					const double *p = r->v + 9 * r->bycol[k] + 3 * m;
					double s;
					if (p[1] == Y0)
						s = p[0] - X0;
					else if (p[0] == X1)
						s = W + (p[1] - Y0);
					else if (p[1] == Y1)
						s = W + H + (X1 - p[0]);
					else if (p[0] == X0)
						s = 2 * W + H + (Y1 - p[1]);
					else
						continue;
					xgrow(ptp, cappt, npt + 1, sizeof **ptp);
					(*ptp)[npt++] = (struct pt){s, p[0], p[1]};
				}
		}
	struct pt *pt;
	double corner[4][2] = {{X0, Y0}, {X1, Y0}, {X1, Y1}, {X0, Y1}};
	double cs[4] = {0, W, W + H, 2 * W + H};
	for (int k = 0; k < 4; k++) {
		xgrow(ptp, cappt, npt + 1, sizeof **ptp);
		(*ptp)[npt++] = (struct pt){cs[k], corner[k][0], corner[k][1]};
	}
	pt = *ptp;
	qsort(pt, npt, sizeof *pt, pt_cmp);
	/* one point per place: tetrahedra that share an edge compute its
	 * crossing apart, equal only to rounding; the corners, exact, go
	 * first on ties */
	double tol = 1e-9 * fmax(r->f->h[0], r->f->h[1]), len = 2 * (W + H);
	size_t u = 0;
	for (size_t k = 0; k < npt; k++)
		if (u == 0 || pt[k].s - pt[u - 1].s > tol)
			pt[u++] = pt[k];
		else if (is_corner(&pt[k], corner))
			pt[u - 1] = pt[k];
	while (u > 4 && len - pt[u - 1].s <= tol)
		u--;    /* the last point is the first corner */
	return u;
}

/* The large triangles of rectangle r at height z on the side sign: two if
 * its perimeter is its four corners, else a fan from its centre over the
 * npt points pt. */
static void fan(const struct rect *r, double z, int sign, const struct pt *pt, size_t npt,
		double **add, size_t *nadd, size_t *capadd)
{
	double X0 = r->X0, X1 = r->X1, Y0 = r->Y0, Y1 = r->Y1;
	if (npt == 4) {
		double a[3] = {X0, Y0, z}, b[3] = {X1, Y0, z}, cc[3] = {X1, Y1, z},
		       d[3] = {X0, Y1, z};
		if (sign > 0) {
			push(add, nadd, capadd, a, b, cc);
			push(add, nadd, capadd, a, cc, d);
		} else {
			push(add, nadd, capadd, a, cc, b);
			push(add, nadd, capadd, a, d, cc);
		}
		return;
	}
	double W = X1 - X0, H = Y1 - Y0;
	double m[3] = {X0 + 0.5 * W, Y0 + 0.5 * H, z};
	for (size_t k = 0; k < npt; k++) {
		const struct pt *p = &pt[k], *q = &pt[(k + 1) % npt];
		double a[3] = {p->x, p->y, z}, b[3] = {q->x, q->y, z};
		if (sign > 0)
			push(add, nadd, capadd, m, a, b);
		else
			push(add, nadd, capadd, m, b, a);
	}
}

size_t fmm_compact(const struct fmm *f, double **vp, size_t n, size_t *capp)
{
	double *v = *vp;
	if (f->n[0] < 2 || f->n[1] < 2 || n == 0)
		return n;
	int cx = f->n[0] - 1, cy = f->n[1] - 1;
	size_t ncol = (size_t)cx * (size_t)cy;
	struct col *c = xcalloc(ncol, sizeof *c);
	int *home = xreallocarray(NULL, n, sizeof *home);     /* column or -1 */
	columns(f, v, n, c, home);
	size_t *start;
	size_t *bycol = by_column(home, n, ncol, &start);
	char *drop = xcalloc(n, 1);
	double *add = NULL;
	size_t nadd = 0, capadd = 0, cappt = 0;
	struct pt *pt = NULL;
	struct rect r = {.f = f, .v = v, .c = c, .cx = cx, .start = start, .bycol = bycol};
	for (int j = 0; j < cy; j++)
		for (int i = 0; i < cx; i++) {
			struct col *q0 = &c[(size_t)j * (size_t)cx + (size_t)i];
			if (q0->state != 1)
				continue;
#define SAME(qq) ((qq)->state == 1 && (qq)->z == q0->z && (qq)->sign == q0->sign)
			int w = 1;
			while (i + w < cx && SAME(&c[(size_t)j * (size_t)cx + (size_t)(i + w)]))
				w++;
			int h = 1;
			for (; j + h < cy; h++) {
				int ok = 1;
				for (int k = 0; k < w && ok; k++)
					ok = SAME(&c[(size_t)(j + h) * (size_t)cx + (size_t)(i + k)]);
				if (!ok)
					break;
			}
#undef SAME
			r.i = i, r.j = j, r.w = w, r.h = h;
			r.X0 = line(f, 0, i), r.X1 = line(f, 0, i + w);
			r.Y0 = line(f, 1, j), r.Y1 = line(f, 1, j + h);
			long replaced;
			size_t npt = perimeter(&r, &pt, &cappt, &replaced);
			long need = npt == 4 ? 2 : (long)npt;
			if (need >= replaced)
				continue;       /* as it was: its columns stay marked 2 */
			for (int jj = j; jj < j + h; jj++)
				for (int ii = i; ii < i + w; ii++) {
					size_t q = (size_t)jj * (size_t)cx + (size_t)ii;
					for (size_t k = start[q]; k < start[q + 1]; k++)
						drop[bycol[k]] = 1;
				}
			fan(&r, q0->z, q0->sign, pt, npt, &add, &nadd, &capadd);
		}
	size_t out = 0;
	for (size_t t = 0; t < n; t++)
		if (!drop[t]) {
			if (out != t)
				memmove(v + 9 * out, v + 9 * t, 9 * sizeof *v);
			out++;
		}
	xgrow(&v, capp, 9 * (out + nadd), sizeof *v);
	if (nadd)
		memcpy(v + 9 * out, add, 9 * nadd * sizeof *v);
	*vp = v;
	free(add);
	free(pt);
	free(drop);
	free(bycol);
	free(start);
	free(home);
	free(c);
	return out + nadd;
}
