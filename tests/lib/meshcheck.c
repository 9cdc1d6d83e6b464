/*
 * meshcheck - test tool: the surfaces of a curves.plot (every curve a
 * triangle p1 p2 p3 p1), checked and compared independently of the code
 * that made them (the decimation of src/lib/geometry/tri_decimate.c).
 *
 *   meshcheck stat FILE.plot
 *     per set one line: "set k triangles n area A volume V vertices nv
 *     edges ne euler chi open no offbox nf bad nb": the area, the signed
 *     volume with the origin (sum p0 . p1 x p2 / 6), the vertices (welded
 *     on a 1e-9 um lattice), edges and Euler characteristic nv - ne + n,
 *     the edges of one triangle (open), those of them not lying in one
 *     face of the set's bounds (offbox, within 1e-9 um), and the edges of
 *     three or more triangles or of two with the same direction (bad).
 *
 *   meshcheck dist A.plot B.plot CAP
 *     per set pair one line "set k ab dAB ba dBA": the largest distance
 *     (um) from points sampled on A's triangles (15 per triangle: the
 *     barycentric grid of step 1/4, vertices and edges included) to the
 *     nearest triangle of B, and the reverse; distances beyond CAP (um)
 *     are reported as CAP.  Point-to-triangle distances by brute force
 *     over the triangles a uniform grid of cells lists near the point; a
 *     point's search ends at a triangle within the largest distance so
 *     far, which that point cannot change (the result of a full search).
 *
 *   meshcheck nodes A.plot B.plot CAP
 *     per set pair one line "set k nodes n mean m p95 p max x": the
 *     distances (um) from the distinct vertices of A's triangles to the
 *     nearest triangle of B (full search among those listed near the
 *     vertex; beyond CAP reported as CAP), their mean, 95th percentile
 *     (nearest rank) and largest.
 */
#include "fmt_plot.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void tri_of(const struct plot_set *s, int c, const char *path, int k, double t[9])
{
	if (s->curves[c].npts != 4)
		die("%s: set %d: a curve of %d points, not a triangle", path, k + 1, s->curves[c].npts);
	memcpy(t, s->curves[c].p, 9 * sizeof *t);
}

/* ---- stat ---- */

struct edge {
	long long a[3], b[3];
	int dir;
};

static int lcmp(const long long *a, const long long *b)
{
	for (int d = 0; d < 3; d++)
		if (a[d] != b[d])
			return a[d] < b[d] ? -1 : 1;
	return 0;
}

static int edge_cmp(const void *x, const void *y)
{
	const struct edge *e = x, *f = y;
	int c = lcmp(e->a, f->a);
	return c ? c : lcmp(e->b, f->b);
}

static int vert_cmp(const void *x, const void *y)
{
	return lcmp(x, y);
}

static int stat(const char *path)
{
	struct plot_file *pf = fmt_plot_read(path, 3);
	for (int k = 0; k < pf->nsets; k++) {
		const struct plot_set *s = &pf->sets[k];
		size_t n = (size_t)s->ncurves;
		struct edge *e = xreallocarray(NULL, 3 * n + 1, sizeof *e);
		long long (*vx)[3] = xreallocarray(NULL, 3 * n + 1, sizeof *vx);
		double area = 0, vol = 0;
		for (size_t c = 0; c < n; c++) {
			double p[9];
			tri_of(s, (int)c, path, k, p);
			double u[3], v[3];
			for (int d = 0; d < 3; d++) {
				u[d] = p[3 + d] - p[d];
				v[d] = p[6 + d] - p[d];
			}
			double nn[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
					u[0] * v[1] - u[1] * v[0]};
			area += 0.5 * sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
			vol += (p[0] * (p[4] * p[8] - p[5] * p[7]) - p[1] * (p[3] * p[8] - p[5] * p[6]) +
				p[2] * (p[3] * p[7] - p[4] * p[6])) / 6;
			long long q[3][3];
			for (int m = 0; m < 3; m++)
				for (int d = 0; d < 3; d++)
					q[m][d] = llround(p[3 * m + d] * 1e9);
			for (int m = 0; m < 3; m++) {
				memcpy(vx[3 * c + (size_t)m], q[m], sizeof q[m]);
				struct edge *x = &e[3 * c + (size_t)m];
				const long long *a = q[m], *b = q[(m + 1) % 3];
				x->dir = lcmp(a, b) < 0 ? 1 : -1;
				memcpy(x->a, x->dir > 0 ? a : b, sizeof x->a);
				memcpy(x->b, x->dir > 0 ? b : a, sizeof x->b);
			}
		}
		qsort(vx, 3 * n, sizeof *vx, vert_cmp);
		size_t nv = 0;
		for (size_t i = 0; i < 3 * n; i++)
			nv += i == 0 || lcmp(vx[i], vx[i - 1]) != 0;
		qsort(e, 3 * n, sizeof *e, edge_cmp);
		size_t ne = 0;
		long open = 0, offbox = 0, bad = 0;
		for (size_t i = 0; i < 3 * n;) {
			size_t j = i + 1;
			while (j < 3 * n && edge_cmp(&e[i], &e[j]) == 0)
				j++;
			ne++;
			if (j - i == 1) {
				open++;
				int on = 0;
				for (int f = 0; f < 6 && !on; f++) {
					long long b = llround(s->bounds[f] * 1e9);
					on = llabs(e[i].a[f / 2] - b) <= 1 && llabs(e[i].b[f / 2] - b) <= 1;
				}
				offbox += !on;
			} else if (j - i > 2 || e[i].dir == e[i + 1].dir)
				bad++;
			i = j;
		}
		printf("set %d triangles %zu area %.12g volume %.12g vertices %zu edges %zu euler %ld "
		       "open %ld offbox %ld bad %ld\n", k + 1, n, area, vol, nv, ne,
		       (long)nv - (long)ne + (long)n, open, offbox, bad);
		free(e);
		free(vx);
	}
	fmt_plot_free(pf);
	return 0;
}

/* ---- dist ---- */

static double dot3(const double *a, const double *b)
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* distance from p to triangle t (Ericson, Real-Time Collision Detection
 * 5.1.5: the Voronoi regions of the vertices, edges and face) */
static double pt_tri(const double *p, const double *t)
{
	const double *a = t, *b = t + 3, *c = t + 6;
	double ab[3], ac[3], ap[3], q[3];
	for (int d = 0; d < 3; d++) {
		ab[d] = b[d] - a[d];
		ac[d] = c[d] - a[d];
		ap[d] = p[d] - a[d];
	}
	double d1 = dot3(ab, ap), d2 = dot3(ac, ap);
	if (d1 <= 0 && d2 <= 0) {
		memcpy(q, a, sizeof q);
		goto done;
	}
	double bp[3], cp[3];
	for (int d = 0; d < 3; d++) {
		bp[d] = p[d] - b[d];
		cp[d] = p[d] - c[d];
	}
	double d3 = dot3(ab, bp), d4 = dot3(ac, bp);
	if (d3 >= 0 && d4 <= d3) {
		memcpy(q, b, sizeof q);
		goto done;
	}
	double vc = d1 * d4 - d3 * d2;
	if (vc <= 0 && d1 >= 0 && d3 <= 0) {
		double v = d1 / (d1 - d3);
		for (int d = 0; d < 3; d++)
			q[d] = a[d] + v * ab[d];
		goto done;
	}
	double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
	if (d6 >= 0 && d5 <= d6) {
		memcpy(q, c, sizeof q);
		goto done;
	}
	double vb = d5 * d2 - d1 * d6;
	if (vb <= 0 && d2 >= 0 && d6 <= 0) {
		double w = d2 / (d2 - d6);
		for (int d = 0; d < 3; d++)
			q[d] = a[d] + w * ac[d];
		goto done;
	}
	double va = d3 * d6 - d5 * d4;
	if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
		double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
		for (int d = 0; d < 3; d++)
			q[d] = b[d] + w * (c[d] - b[d]);
		goto done;
	}
	double den = 1 / (va + vb + vc), v = vb * den, w = vc * den;
	for (int d = 0; d < 3; d++)
		q[d] = a[d] + ab[d] * v + ac[d] * w;
done:;
	double r[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
	return sqrt(dot3(r, r));
}

enum { G = 24 };        /* cells per axis */

struct grid {
	double lo[3], cell[3];
	size_t *start, *item;   /* CSR: triangles per cell */
};

static int cell_of(const struct grid *g, int d, double x)
{
	long i = (long)floor((x - g->lo[d]) / g->cell[d]);
	return i < 0 ? 0 : i >= G ? G - 1 : (int)i;
}

/* every triangle listed in the cells its box, grown by cap, overlaps */
static void grid_build(struct grid *g, const struct plot_set *s, double cap)
{
	for (int d = 0; d < 3; d++) {
		g->lo[d] = s->bounds[2 * d] - cap;
		g->cell[d] = (s->bounds[2 * d + 1] - s->bounds[2 * d] + 2 * cap) / G;
		if (!(g->cell[d] > 0))
			g->cell[d] = 1;
	}
	g->start = xcalloc((size_t)G * G * G + 1, sizeof *g->start);
	for (int pass = 0; pass < 2; pass++) {
		size_t *fill = pass ? xcalloc((size_t)G * G * G, sizeof *fill) : NULL;
		for (int c = 0; c < s->ncurves; c++) {
			const double *p = s->curves[c].p;
			int a[3], b[3];
			for (int d = 0; d < 3; d++) {
				double lo = fmin(p[d], fmin(p[3 + d], p[6 + d])) - cap;
				double hi = fmax(p[d], fmax(p[3 + d], p[6 + d])) + cap;
				a[d] = cell_of(g, d, lo);
				b[d] = cell_of(g, d, hi);
			}
			for (int z = a[2]; z <= b[2]; z++)
				for (int y = a[1]; y <= b[1]; y++)
					for (int x = a[0]; x <= b[0]; x++) {
						size_t q = ((size_t)z * G + (size_t)y) * G + (size_t)x;
						if (pass)
							g->item[g->start[q] + fill[q]++] = (size_t)c;
						else
							g->start[q + 1]++;
					}
		}
		if (!pass) {
			for (size_t q = 0; q < (size_t)G * G * G; q++)
				g->start[q + 1] += g->start[q];
			g->item = xreallocarray(NULL, g->start[(size_t)G * G * G] + 1, sizeof *g->item);
		}
		free(fill);
	}
}

/* the distance from p to the nearest triangle listed in its cell (cap if
 * none is nearer); the search stops at the first triangle within enough:
 * the caller wants the largest of these minima, and one at or under the
 * largest so far cannot change it (the same result as the full search).
 * *hint, the triangle found nearest to the previous point (the points
 * come a triangle at a time, close together), is tried first: mostly it
 * is within enough and ends the search at once.  Trying it changes no
 * result: a triangle nearer to p than cap is listed in p's cell anyway,
 * and one farther does not lower the minimum under cap. */
static double nearest(const struct grid *g, const struct plot_set *s, const double *p, double cap,
		      double enough, size_t *hint)
{
	size_t q = ((size_t)cell_of(g, 2, p[2]) * G + (size_t)cell_of(g, 1, p[1])) * G +
		   (size_t)cell_of(g, 0, p[0]);
	double best = fmin(cap, pt_tri(p, s->curves[*hint].p));
	for (size_t k = g->start[q]; k < g->start[q + 1] && best > enough; k++) {
		double d = pt_tri(p, s->curves[g->item[k]].p);
		if (d < best) {
			best = d;
			*hint = g->item[k];
		}
	}
	return best;
}

static double one_side(const struct plot_set *a, const struct plot_set *b, double cap)
{
	if (b->ncurves == 0)   /* no triangle to be near: every point at cap */
		return a->ncurves ? cap : 0;
	struct grid g = {{0, 0, 0}, {0, 0, 0}, NULL, NULL};
	grid_build(&g, b, cap);
	double worst = 0;
	size_t hint = 0;
	for (int c = 0; c < a->ncurves; c++) {
		const double *t = a->curves[c].p;
		for (int i = 0; i <= 4; i++)
			for (int j = 0; i + j <= 4; j++) {
				double u = i / 4.0, v = j / 4.0, w = 1 - u - v, p[3];
				for (int d = 0; d < 3; d++)
					p[d] = w * t[d] + u * t[3 + d] + v * t[6 + d];
				worst = fmax(worst, nearest(&g, b, p, cap, worst, &hint));
			}
	}
	free(g.start);
	free(g.item);
	return worst;
}

static int dist(const char *pa, const char *pb, double cap)
{
	struct plot_file *a = fmt_plot_read(pa, 3), *b = fmt_plot_read(pb, 3);
	if (a->nsets != b->nsets)
		die("%s has %d sets, %s %d", pa, a->nsets, pb, b->nsets);
	for (int k = 0; k < a->nsets; k++) {
		double t[9];
		for (int c = 0; c < a->sets[k].ncurves; c++)
			tri_of(&a->sets[k], c, pa, k, t);
		for (int c = 0; c < b->sets[k].ncurves; c++)
			tri_of(&b->sets[k], c, pb, k, t);
		printf("set %d ab %.6g ba %.6g\n", k + 1, one_side(&a->sets[k], &b->sets[k], cap),
		       one_side(&b->sets[k], &a->sets[k], cap));
	}
	fmt_plot_free(a);
	fmt_plot_free(b);
	return 0;
}

static int cmp3(const void *x, const void *y)
{
	const double *a = x, *b = y;
	for (int d = 0; d < 3; d++)
		if (a[d] != b[d])
			return a[d] < b[d] ? -1 : 1;
	return 0;
}

static int cmpd(const void *x, const void *y)
{
	double a = *(const double *)x, b = *(const double *)y;
	return a < b ? -1 : a > b;
}

static int nodes(const char *pa, const char *pb, double cap)
{
	struct plot_file *a = fmt_plot_read(pa, 3), *b = fmt_plot_read(pb, 3);
	if (a->nsets != b->nsets)
		die("%s has %d sets, %s %d", pa, a->nsets, pb, b->nsets);
	for (int k = 0; k < a->nsets; k++) {
		const struct plot_set *sa = &a->sets[k], *sb = &b->sets[k];
		double t[9];
		for (int c = 0; c < sb->ncurves; c++)
			tri_of(sb, c, pb, k, t);
		size_t n = 3 * (size_t)sa->ncurves, m = 0;
		double *v = xreallocarray(NULL, 3 * n + 1, sizeof *v);
		for (int c = 0; c < sa->ncurves; c++) {
			tri_of(sa, c, pa, k, t);
			memcpy(v + 9 * (size_t)c, t, sizeof t);
		}
		qsort(v, n, 3 * sizeof *v, cmp3);
		for (size_t i = 0; i < n; i++)
			if (m == 0 || cmp3(v + 3 * i, v + 3 * (m - 1)) != 0)
				memmove(v + 3 * m++, v + 3 * i, 3 * sizeof *v);
		struct grid g = {{0, 0, 0}, {0, 0, 0}, NULL, NULL};
		grid_build(&g, sb, cap);
		double *d = xreallocarray(NULL, m + 1, sizeof *d), sum = 0;
		size_t hint = 0;
		for (size_t i = 0; i < m; i++) {
			/* no triangle to be near: every point at cap */
			d[i] = sb->ncurves ? nearest(&g, sb, v + 3 * i, cap, -1, &hint) : cap;
			sum += d[i];
		}
		qsort(d, m, sizeof *d, cmpd);
		size_t r95 = m ? (size_t)ceil(0.95 * (double)m) - 1 : 0;
		printf("set %d nodes %zu mean %.6g p95 %.6g max %.6g\n", k + 1, m, m ? sum / (double)m : 0,
		       m ? d[r95] : 0, m ? d[m - 1] : 0);
		free(g.start);
		free(g.item);
		free(d);
		free(v);
	}
	fmt_plot_free(a);
	fmt_plot_free(b);
	return 0;
}

int main(int argc, char **argv)
{
	util_setprog("meshcheck");
	if (argc == 3 && strcmp(argv[1], "stat") == 0)
		return stat(argv[2]);
	if (argc == 5 && strcmp(argv[1], "dist") == 0)
		return dist(argv[2], argv[3], atof(argv[4]));
	if (argc == 5 && strcmp(argv[1], "nodes") == 0)
		return nodes(argv[2], argv[3], atof(argv[4]));
	die("usage: meshcheck stat FILE.plot | meshcheck dist|nodes A.plot B.plot CAP");
}
