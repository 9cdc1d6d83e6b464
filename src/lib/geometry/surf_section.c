/*
 * surf_section.c - horizontal sections of a triangle soup, the spans of
 * a line across a section, the area of one developed region of it, and
 * vertical profiles (see surf.h).
 *
 * A section is the set of segments where the plane cuts the triangles; no
 * attempt is made to chain them into polygons, since a delooped surface
 * may have small gaps and a surface that covers the box ends on the box
 * walls.  Instead a line across the section is cut where it crosses the
 * segments, and each stretch between crossings is classified by the
 * vertical-ray test inside it.  The area of a region is the sum of
 * its stretches on closely spaced parallel lines (the midpoint rule
 * across the lines, exact along them), stretches on neighbouring lines
 * being joined into one region where they overlap (union-find).
 *
 * Cut points are computed from the edge's two ends taken in one canonical
 * order (the lower end first), so the two triangles or segments sharing an
 * edge or end produce the same bits and a crossing is never counted twice
 * or lost.
 */
#include "surf.h"
#include "unionfind.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void surf_section(const struct surf *s, double z, struct surf_section *sec)
{
	size_t cap = 0;
	sec->z = z;
	sec->nseg = 0;
	sec->seg = NULL;
	for (size_t t = 0; t < s->ntri; t++) {
		const double *p = s->v + 9 * t;
		int up[3], nup = 0;
		for (int k = 0; k < 3; k++)
			nup += up[k] = p[3 * k + 2] >= z;
		if (nup == 0 || nup == 3)
			continue;
		double out[4];
		int m = 0;
		for (int k = 0; k < 3; k++) {
			const double *a = p + 3 * k, *b = p + 3 * ((k + 1) % 3);
			if (up[k] == up[(k + 1) % 3])
				continue;
			if (a[2] > b[2]) {
				const double *q = a;
				a = b;
				b = q;
			}
			double f = (z - a[2]) / (b[2] - a[2]);
			out[m++] = a[0] + f * (b[0] - a[0]);
			out[m++] = a[1] + f * (b[1] - a[1]);
		}
		xgrow(&sec->seg, &cap, 4 * (sec->nseg + 1), sizeof *sec->seg);
		memcpy(sec->seg + 4 * sec->nseg, out, sizeof out);
		sec->nseg++;
	}
}

void surf_section_free(struct surf_section *sec)
{
	free(sec->seg);
	sec->seg = NULL;
	sec->nseg = 0;
}

/* Where segment a-b (2D) crosses the line: axis 0 is y = c, the position
 * returned is x; axis 1 is x = c, position y.  Returns 0 if it does not
 * cross.  An end counts as beyond the line only if strictly beyond (> c),
 * as in the ray test's crossing rule, so that a line through a vertex of
 * the section is cut as the ray test sees it. */
static int seg_cut(const double *a, const double *b, int axis, double c, double *pos)
{
	double pa = a[1 - axis], pb = b[1 - axis]; /* across the line */
	if ((pa > c) == (pb > c))
		return 0;
	if (pa > pb) {
		const double *q = a;
		a = b;
		b = q;
		double t = pa;
		pa = pb;
		pb = t;
	}
	*pos = a[axis] + (c - pa) * (b[axis] - a[axis]) / (pb - pa);
	return 1;
}

static int cmp_double(const void *x, const void *y)
{
	double a = *(const double *)x, b = *(const double *)y;
	return (a > b) - (a < b);
}

/* The kind of the point at t on the line: 1 resist, 0 developed. */
static int kind_at(const struct surf *s, double z, int axis, double c, double t)
{
	return (axis == 0 ? surf_above(s, t, c, z) : surf_above(s, c, t, z)) & 1;
}

/* Where the kind changes between a (kind ka) and b, by bisection with the
 * ray test, to 1e-13 of the box. */
static double find_flip(const struct surf *s, double z, int axis, double c,
			double a, int ka, double b, double tol)
{
	while (fabs(b - a) > tol) {
		double m = 0.5 * (a + b);
		if (m == a || m == b)
			break;
		if (kind_at(s, z, axis, c, m) == ka)
			a = m;
		else
			b = m;
	}
	return 0.5 * (a + b);
}

static void push_span(struct surf_span **spans, size_t *cap, size_t *m,
		      double lo, double hi, int resist)
{
	if (*m && (*spans)[*m - 1].resist == resist) {
		(*spans)[*m - 1].hi = hi;
		return;
	}
	xgrow(spans, cap, *m + 1, sizeof **spans);
	(*spans)[(*m)++] = (struct surf_span){lo, hi, resist};
}

/* Sample points of a stretch between two cuts, as fractions of it: near
 * both ends and at three irrational places inside. */
enum { NSAMPLE = 5 };
static const double sample_at[NSAMPLE] = {
	1e-4, 0.5 - 0.2071067811865476, 0.5, 0.5 + 0.2071067811865476, 1 - 1e-4};

/* Spans of a line from sorted cut positions cut[0..n-1], between lo and
 * hi, merged.  Each stretch between cuts is classified by the ray test at
 * its sample points.  Normally they agree.  Where they do not, either the
 * section has a gap (an open border left by delooping lets the line pass
 * a wall without a cut) or a point fell exactly on the surface where the
 * line touches the section without crossing it; the ray test, which needs
 * no closed curve, then decides: the stretch is split where its answer
 * changes (bisection), and pieces shorter than SPAN_MIN of the box (a
 * touching point) are dropped. */
#define SPAN_MIN 1e-9
static size_t spans_from_cuts(const struct surf *s, double z, int axis, double c,
			      const double *cut, size_t n, double lo, double hi,
			      struct surf_span **spans, size_t *cap)
{
	size_t m = 0;
	double prev = lo, tol = 1e-13 * (hi - lo), shortest = SPAN_MIN * (hi - lo);
	for (size_t k = 0; k <= n; k++) {
		double next = k < n ? fmin(fmax(cut[k], lo), hi) : hi;
		if (!(next > prev))
			continue;
		double t[NSAMPLE];
		int kind[NSAMPLE], same = 1;
		for (int i = 0; i < NSAMPLE; i++) {
			t[i] = prev + sample_at[i] * (next - prev);
			kind[i] = kind_at(s, z, axis, c, t[i]);
			same &= kind[i] == kind[0];
		}
		if (same) {
			push_span(spans, cap, &m, prev, next, kind[0]);
		} else {
			double a = prev;
			for (int i = 0; i + 1 < NSAMPLE; i++) {
				if (kind[i] == kind[i + 1])
					continue;
				double f = find_flip(s, z, axis, c, t[i], kind[i], t[i + 1], tol);
				/* a piece too short joins the next one */
				if (f - a >= shortest) {
					push_span(spans, cap, &m, a, f, kind[i]);
					a = f;
				}
			}
			if (next - a < shortest && m > 0 && (*spans)[m - 1].hi == a)
				(*spans)[m - 1].hi = next;
			else
				push_span(spans, cap, &m, a, next, kind[NSAMPLE - 1]);
		}
		prev = next;
	}
	return m;
}

size_t surf_line_spans(const struct surf *s, const struct surf_section *sec,
		       int axis, double c, struct surf_span **spans, size_t *cap)
{
	double *cut = NULL;
	size_t n = 0, ccap = 0;
	for (size_t k = 0; k < sec->nseg; k++) {
		double pos;
		if (seg_cut(sec->seg + 4 * k, sec->seg + 4 * k + 2, axis, c, &pos)) {
			xgrow(&cut, &ccap, n + 1, sizeof *cut);
			cut[n++] = pos;
		}
	}
	if (n)
		qsort(cut, n, sizeof *cut, cmp_double);
	size_t m = spans_from_cuts(s, sec->z, axis, c, cut, n, s->box[2 * axis],
				   s->box[2 * axis + 1], spans, cap);
	free(cut);
	return m;
}

struct surf_span surf_span_at(const struct surf *s, const struct surf_section *sec,
			      int axis, double c, double t)
{
	struct surf_span *sp = NULL, r = {t, t, 1};
	size_t cap = 0;
	size_t m = surf_line_spans(s, sec, axis, c, &sp, &cap);
	for (size_t k = 0; k < m; k++)
		if (sp[k].lo <= t && (t < sp[k].hi || k == m - 1)) {
			r = sp[k];
			break;
		}
	free(sp);
	return r;
}


/* The lines of surf_region_area: y_j = y + j h for j in [j0, j1]. */
static double line_y(double y, double h, long j) { return y + (double)j * h; }

/* The cut positions of the nl lines from j0 on, bucketed by line: those
 * of line l are cut[start[l]] to cut[start[l + 1] - 1], sorted.  Each
 * segment is only tried on the lines its y range spans. */
static double *bucket_cuts(const struct surf_section *sec, double y, double h,
			   long j0, long nl, size_t *start)
{
	double *cut = NULL;
	size_t *fill = NULL;
	memset(start, 0, ((size_t)nl + 1) * sizeof *start);
	for (int pass = 0; pass < 2; pass++) {
		if (pass == 1) {
			for (long l = 0; l < nl; l++)
				start[l + 1] += start[l];
			cut = xreallocarray(NULL, start[nl] ? start[nl] : 1, sizeof *cut);
			fill = xreallocarray(NULL, (size_t)nl, sizeof *fill);
			memcpy(fill, start, (size_t)nl * sizeof *fill);
		}
		for (size_t k = 0; k < sec->nseg; k++) {
			const double *a = sec->seg + 4 * k, *b = a + 2;
			double ya = fmin(a[1], b[1]), yb = fmax(a[1], b[1]);
			long ja = (long)floor((ya - y) / h) - 1, jb = (long)ceil((yb - y) / h) + 1;
			ja = ja < j0 ? j0 : ja;
			jb = jb > j0 + nl - 1 ? j0 + nl - 1 : jb;
			for (long j = ja; j <= jb; j++) {
				double pos;
				if (!seg_cut(a, b, 0, line_y(y, h, j), &pos))
					continue;
				if (pass == 0)
					start[j - j0 + 1]++;
				else
					cut[fill[j - j0]++] = pos;
			}
		}
	}
	free(fill);
	for (long l = 0; l < nl; l++)
		if (start[l + 1] > start[l])
			qsort(cut + start[l], start[l + 1] - start[l], sizeof *cut, cmp_double);
	return cut;
}

double surf_region_tests(const struct surf *s, const struct surf_section *sec, double h,
			 double *stretches)
{
	/* the cuts of the lines: each segment crosses about its height / h */
	double cuts = 0;
	for (size_t k = 0; k < sec->nseg; k++)
		cuts += fabs(sec->seg[4 * k + 3] - sec->seg[4 * k + 1]) / h + 1;
	double lines = (s->box[3] - s->box[2]) / h + 1;
	double cells = (double)s->gnx * s->gny;
	double per = cells > 0 ? (double)s->gstart[s->gnx * s->gny] / cells + 1 : (double)s->ntri;
	*stretches = lines + cuts;
	return (lines + cuts) * NSAMPLE * per;
}

void surf_region_box(const struct surf *s, const struct surf_section *sec,
		 double x, double y, double h, struct surf_region_box *rg)
{
	const double *box = s->box;
	int *edge = &rg->edge;
	rg->area = 0;
	rg->bbox[0] = rg->bbox[1] = x;
	rg->bbox[2] = rg->bbox[3] = y;
	long j0 = (long)ceil((box[2] - y) / h), j1 = (long)floor((box[3] - y) / h);
	while (line_y(y, h, j0) < box[2])
		j0++;
	while (line_y(y, h, j1) > box[3])
		j1--;
	long nl = j1 - j0 + 1;
	*edge = 0;
	if (nl <= 0)
		return;
	size_t *start = xreallocarray(NULL, (size_t)nl + 1, sizeof *start);
	double *cut = bucket_cuts(sec, y, h, j0, nl, start);

	/* the developed spans of every line: dev[lstart[l] .. lstart[l+1]-1] */
	struct surf_span *sp = NULL, *dev = NULL;
	size_t spcap = 0, devcap = 0, ndev = 0;
	size_t *lstart = xreallocarray(NULL, (size_t)nl + 1, sizeof *lstart);
	for (long l = 0; l < nl; l++) {
		size_t m = spans_from_cuts(s, sec->z, 0, line_y(y, h, l + j0), cut + start[l],
					   start[l + 1] - start[l], box[0], box[1], &sp, &spcap);
		lstart[l] = ndev;
		for (size_t k = 0; k < m; k++)
			if (!sp[k].resist) {
				xgrow(&dev, &devcap, ndev + 1, sizeof *dev);
				dev[ndev++] = sp[k];
			}
	}
	lstart[nl] = ndev;
	free(sp);
	free(cut);
	free(start);

	/* spans of neighbouring lines that overlap are one region */
	size_t *parent = xreallocarray(NULL, ndev ? ndev : 1, sizeof *parent);
	for (size_t k = 0; k < ndev; k++)
		parent[k] = k;
	for (long l = 0; l + 1 < nl; l++) {
		size_t a = lstart[l], b = lstart[l + 1];
		while (a < lstart[l + 1] && b < lstart[l + 2]) {
			if (fmax(dev[a].lo, dev[b].lo) < fmin(dev[a].hi, dev[b].hi))
				uf_join(parent, a, b);
			if (dev[a].hi < dev[b].hi)
				a++;
			else
				b++;
		}
	}

	/* the region of (x, y): the line through y is line -j0 */
	size_t root = (size_t)-1;
	for (size_t k = lstart[-j0]; k < lstart[-j0 + 1]; k++)
		if (dev[k].lo <= x && (x < dev[k].hi || dev[k].hi >= box[1])) {
			root = uf_find(parent, k);
			break;
		}
	/* its area: each span stands for the band of its line, half way to
	 * the next lines (to the box edge for the first and last) */
	double area = 0, *bb = rg->bbox;
	for (long l = 0; l < nl && root != (size_t)-1; l++) {
		double yl = line_y(y, h, l + j0);
		double b0 = l == 0 ? box[2] : yl - 0.5 * h;
		double b1 = l == nl - 1 ? box[3] : yl + 0.5 * h;
		for (size_t k = lstart[l]; k < lstart[l + 1]; k++) {
			if (uf_find(parent, k) != root)
				continue;
			area += (dev[k].hi - dev[k].lo) * (b1 - b0);
			if (dev[k].lo <= box[0] || dev[k].hi >= box[1] || l == 0 || l == nl - 1)
				*edge = 1;
			bb[0] = fmin(bb[0], dev[k].lo);
			bb[1] = fmax(bb[1], dev[k].hi);
			bb[2] = fmin(bb[2], b0);
			bb[3] = fmax(bb[3], b1);
		}
	}
	rg->area = area;
	free(parent);
	free(lstart);
	free(dev);
}

double surf_region_area(const struct surf *s, const struct surf_section *sec,
			double x, double y, double h, int *edge)
{
	struct surf_region_box rg;
	surf_region_box(s, sec, x, y, h, &rg);
	*edge = rg.edge;
	return rg.area;
}

double surf_top_along(const struct surf *s, int axis, double c, double lo, double hi)
{
	/* axis 0: the plane y = c, positions along x; axis 1: x = c, along y */
	int across = 1 - axis;
	double top = s->box[4];
	int found = 0;
	for (size_t t = 0; t < s->ntri; t++) {
		const double *p = s->v + 9 * t;
		int up[3], nup = 0;
		for (int k = 0; k < 3; k++)
			nup += up[k] = p[3 * k + across] >= c;
		if (nup == 0 || nup == 3)
			continue;
		double q[4];
		int m = 0;
		for (int k = 0; k < 3; k++) {
			const double *a = p + 3 * k, *b = p + 3 * ((k + 1) % 3);
			if (up[k] == up[(k + 1) % 3])
				continue;
			if (a[across] > b[across]) {
				const double *r = a;
				a = b;
				b = r;
			}
			double f = (c - a[across]) / (b[across] - a[across]);
			q[m++] = a[axis] + f * (b[axis] - a[axis]);
			q[m++] = a[2] + f * (b[2] - a[2]);
		}
		/* the segment (q0, z0)-(q1, z1) clipped to [lo, hi] */
		double t0 = q[0], z0 = q[1], t1 = q[2], z1 = q[3];
		if (t0 > t1) {
			double r = t0;
			t0 = t1, t1 = r;
			r = z0;
			z0 = z1, z1 = r;
		}
		if (t1 < lo || t0 > hi)
			continue;
		double za = z0, zb = z1;
		if (t1 > t0) {
			if (t0 < lo)
				za = z0 + (lo - t0) / (t1 - t0) * (z1 - z0);
			if (t1 > hi)
				zb = z0 + (hi - t0) / (t1 - t0) * (z1 - z0);
		}
		double zm = fmax(za, zb);
		if (!found || zm > top)
			top = zm;
		found = 1;
	}
	return top;
}
