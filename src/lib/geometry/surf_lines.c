/*
 * surf_lines.c - many parallel lines across a section at once, and the
 * lines on which a feature's edges are sampled (see surf_lines.h).
 *
 * A line's spans depend only on the segments of the section it crosses,
 * so each segment is handed to the lines its extent across them spans
 * (a binary search in the ascending line positions) and each line is
 * then cut by surf_line_spans on its own short list: the same cuts, the
 * same ray tests, the same spans as with the whole section, at the cost
 * of the crossings.  Lines are independent and run on the thread pool,
 * each writing only its own result.
 *
 * The sampling lines follow the mesh when it has rows: a rough edge
 * meshed row by row is piecewise linear between its rows, and reading it
 * anywhere else would average neighbouring rows and shrink its measured
 * roughness (by a third for an edge whose rows are uncorrelated).
 */
#include "surf_lines.h"
#include "par.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The first of the n ascending c[] that is >= x (above: > x), n if none. */
static size_t bound(const double *c, size_t n, double x, int above)
{
	size_t a = 0, b = n;
	while (a < b) {
		size_t m = a + (b - a) / 2;
		if (c[m] < x || (above && c[m] == x))
			a = m + 1;
		else
			b = m;
	}
	return a;
}

/* The lines the segment may cross, first to end - 1: those with c
 * between its ends across them, both included. */
static void seg_lines(const double *seg, int axis, const double *c, size_t n,
		      size_t *first, size_t *end)
{
	double pa = seg[1 - axis], pb = seg[3 - axis];
	*first = bound(c, n, fmin(pa, pb), 0);
	*end = bound(c, n, fmax(pa, pb), 1);
}

struct lines_job {
	const struct surf *s;
	double z;
	int axis;
	const double *c;
	const size_t *start;    /* line l's segments: seg[4 start[l] ..] */
	double *seg;
	struct surf_line *out;
};

static void lines_run(void *ctx, size_t lo, size_t hi, int worker)
{
	const struct lines_job *j = ctx;
	(void)worker;
	for (size_t l = lo; l < hi; l++) {
		struct surf_section sub = {j->z, j->start[l + 1] - j->start[l],
					   j->seg + 4 * j->start[l]};
		size_t cap = 0;
		j->out[l].sp = NULL;
		j->out[l].n = surf_line_spans(j->s, &sub, j->axis, j->c[l], &j->out[l].sp, &cap);
	}
}

/* Lines per piece of the thread pool's split: a line costs a few ray
 * tests per span, so pieces of 16 are worth a thread's start. */
enum { LINES_CHUNK = 16 };

struct surf_line *surf_lines_spans(const struct surf *s, const struct surf_section *sec,
				   int axis, const double *c, size_t n)
{
	size_t *start = xcalloc(n + 1, sizeof *start);
	for (size_t k = 0; k < sec->nseg; k++) {
		size_t a, b;
		seg_lines(sec->seg + 4 * k, axis, c, n, &a, &b);
		for (size_t l = a; l < b; l++)
			start[l + 1]++;
	}
	for (size_t l = 0; l < n; l++)
		start[l + 1] += start[l];
	double *seg = xreallocarray(NULL, start[n] ? 4 * start[n] : 1, sizeof *seg);
	size_t *fill = xreallocarray(NULL, n ? n : 1, sizeof *fill);
	memcpy(fill, start, n * sizeof *fill);
	for (size_t k = 0; k < sec->nseg; k++) {
		size_t a, b;
		seg_lines(sec->seg + 4 * k, axis, c, n, &a, &b);
		for (size_t l = a; l < b; l++)
			memcpy(seg + 4 * fill[l]++, sec->seg + 4 * k, 4 * sizeof *seg);
	}
	free(fill);
	struct surf_line *out = xcalloc(n ? n : 1, sizeof *out);
	struct lines_job job = {s, sec->z, axis, c, start, seg, out};
	par_for(n, LINES_CHUNK, lines_run, &job);
	free(seg);
	free(start);
	return out;
}

void surf_lines_free(struct surf_line *l, size_t n)
{
	if (!l)
		return;
	for (size_t i = 0; i < n; i++)
		free(l[i].sp);
	free(l);
}

/* Vertex coordinates closer than ROW_TOL of the box length are one row
 * (etch prints 17 digits; a grid's rows computed two ways differ in the
 * last bits only).  Rows are evenly spaced when every one lies within
 * GRID_TOL of the spacing from a whole number of spacings, and a whole
 * number of spacings fills the box to the same tolerance. */
#define ROW_TOL 1e-9
#define GRID_TOL 1e-6

static int cmp_double(const void *x, const void *y)
{
	double a = *(const double *)x, b = *(const double *)y;
	return (a > b) - (a < b);
}

/* The distinct vertex coordinates along fa strictly inside the box
 * (beyond ROW_TOL of its sides), ascending; returns their count. */
static size_t distinct_rows(const struct surf *s, int fa, double **out)
{
	double lo = s->box[2 * fa], hi = s->box[2 * fa + 1], tol = ROW_TOL * (hi - lo);
	double *v = xreallocarray(NULL, 3 * s->ntri + 1, sizeof *v);
	size_t m = 0;
	for (size_t i = 0; i < 3 * s->ntri; i++) {
		double x = s->v[3 * i + fa];
		if (x > lo + tol && x < hi - tol)
			v[m++] = x;
	}
	qsort(v, m, sizeof *v, cmp_double);
	size_t u = 0;
	for (size_t i = 0; i < m; i++)
		if (u == 0 || v[i] - v[u - 1] > tol)
			v[u++] = v[i];
	*out = v;
	return u;
}

/* The rows' spacing and their count in the box length if the u rows v[]
 * are evenly spaced and fill it; 0 otherwise. */
static size_t grid_of(const double *v, size_t u, double len, double *h)
{
	if (u < 2)
		return 0;
	*h = v[1] - v[0];
	for (size_t i = 2; i < u; i++)
		*h = fmin(*h, v[i] - v[i - 1]);
	for (size_t i = 1; i < u; i++) {
		double k = (v[i] - v[0]) / *h;
		if (fabs(k - round(k)) > GRID_TOL)
			return 0;
	}
	double q = len / *h;
	if (!(q < 1e15) || fabs(q - round(q)) > GRID_TOL * fmax(1, q))
		return 0;
	return (size_t)round(q);
}

double *surf_sample_lines(const struct surf *s, int fa, size_t nmin, size_t nmax,
			  size_t *n, size_t *rows)
{
	double lo = s->box[2 * fa], hi = s->box[2 * fa + 1], len = hi - lo;
	double *v, h = 0;
	size_t u = distinct_rows(s, fa, &v);
	size_t m = grid_of(v, u, len, &h);
	size_t r = m ? (nmin + m - 1) / m : 0;
	double *c;
	if (m && m * r <= nmax) {
		/* row k0 is v[0]; rows below it down to the box's low side */
		long k0 = (long)floor((v[0] - lo) / h + GRID_TOL);
		*n = m * r;
		*rows = m;
		c = xreallocarray(NULL, *n, sizeof *c);
		size_t iv = 0;
		for (size_t j = 0; j < *n; j++) {
			long k = (long)(j / r) - k0;          /* rows from v[0] */
			double row = v[0] + (double)k * h;
			/* a row with vertices is read at their coordinate */
			while (iv < u && v[iv] < row - 0.5 * h)
				iv++;
			if (j % r == 0 && iv < u && fabs(v[iv] - row) <= GRID_TOL * h)
				row = v[iv];
			double x = row + (double)(j % r) * h / (double)r;
			c[j] = j == 0 && x - lo <= GRID_TOL * h ? lo : x;
		}
	} else {
		*n = m ? nmax : nmin;
		*rows = 0;
		c = xreallocarray(NULL, *n, sizeof *c);
		for (size_t j = 0; j < *n; j++)
			c[j] = lo + ((double)j + 0.5) * len / (double)*n;
	}
	free(v);
	return c;
}
