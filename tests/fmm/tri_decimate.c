/*
 * tri_decimate.c - the surface decimator (src/lib/tri_decimate.c) on
 * closed forms:
 *  - a plane: the unit square z = 0 as 20 x 20 cells of two triangles,
 *    in the box [0,1]^2 x [-1,1], tol 1e-3: at most 8 triangles remain,
 *    the same area (1e-12), every vertex at z = 0 exactly and every
 *    normal +z, the four corners kept;
 *  - a sphere of radius 1 (an icosahedron split four times, 5120
 *    triangles, its vertices on the sphere), no box, tol 0.03: fewer than
 *    a third of the triangles remain, every vertex an input vertex (|r| =
 *    1 to 1e-12), closed (every edge in two triangles, opposite ways),
 *    Euler characteristic 2, and every point on the 1/4 barycentric grid
 *    of every triangle within tol of the input mesh, which lies within
 *    its sag s = 1 - cos(half the longest edge's angle) inside the
 *    sphere: 1 - s - tol <= |r| <= 1 (1e-12); the volume within area x
 *    tol of the input's;
 *  - tol 0 only welds: the sphere comes back as it went in;
 *  - welded as it is made (tri_weld_add, triangle by triangle, its table
 *    growing from 16 slots through rehashes) and decimated from there
 *    (tri_decimate_welded, the kept triangles as vertices and indices),
 *    the sphere, its corners moved by up to 0.4 of the weld distance so
 *    that the weld decides (2562 vertices, the icosphere's), gives
 *    tri_decimate's triangles on its soup exactly, at tol 0.03 and at
 *    tol 0, and the welder is empty after.
 * Exact checks except where a tolerance is stated.
 */
#include "tri_decimate.h"
#include "tri_weld.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int nfail;

#define CHECK(c, ...) do { if (!(c)) { nfail++; fprintf(stderr, "tri_decimate: "); \
	fprintf(stderr, __VA_ARGS__); fputc('\n', stderr); } } while (0)

struct soup {
	double *v;
	size_t n, cap;
};

static void add(struct soup *s, const double *a, const double *b, const double *c)
{
	xgrow(&s->v, &s->cap, 9 * (s->n + 1), sizeof *s->v);
	double *t = s->v + 9 * s->n++;
	memcpy(t, a, 3 * sizeof *t);
	memcpy(t + 3, b, 3 * sizeof *t);
	memcpy(t + 6, c, 3 * sizeof *t);
}

static void area_vol(const struct soup *s, double *area, double *vol, double nmin[3])
{
	*area = *vol = 0;
	if (nmin)
		nmin[0] = nmin[1] = nmin[2] = INFINITY;
	for (size_t i = 0; i < s->n; i++) {
		const double *p = s->v + 9 * i;
		double u[3], w[3];
		for (int d = 0; d < 3; d++) {
			u[d] = p[3 + d] - p[d];
			w[d] = p[6 + d] - p[d];
		}
		double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
		double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		*area += 0.5 * l;
		*vol += (p[0] * (p[4] * p[8] - p[5] * p[7]) - p[1] * (p[3] * p[8] - p[5] * p[6]) +
			 p[2] * (p[3] * p[7] - p[4] * p[6])) / 6;
		if (nmin)
			for (int d = 0; d < 3; d++)
				nmin[d] = fmin(nmin[d], n[d] / l);
	}
}

static void plane(void)
{
	struct soup s = {NULL, 0, 0};
	enum { N = 20 };
	for (int j = 0; j < N; j++)
		for (int i = 0; i < N; i++) {
			double x0 = (double)i / N, x1 = (double)(i + 1) / N;
			double y0 = (double)j / N, y1 = (double)(j + 1) / N;
			double a[3] = {x0, y0, 0}, b[3] = {x1, y0, 0}, c[3] = {x1, y1, 0}, d[3] = {x0, y1, 0};
			add(&s, a, b, c);
			add(&s, a, c, d);
		}
	const double box[6] = {0, 1, 0, 1, -1, 1};
	struct tri_decimate_stats st;
	s.n = tri_decimate(s.v, s.n, 1e-3, 1e-12, box, 1e-12, NULL, &st);
	double area, vol, nmin[3];
	area_vol(&s, &area, &vol, nmin);
	CHECK(s.n <= 8 && s.n >= 2, "plane: %zu triangles, want 2 to 8", s.n);
	CHECK(fabs(area - 1) <= 1e-12, "plane: area %.17g, want 1", area);
	CHECK(nmin[2] == 1, "plane: a normal not +z (least z component %g)", nmin[2]);
	int corner[4] = {0, 0, 0, 0}, badz = 0;
	for (size_t i = 0; i < 3 * s.n; i++) {
		const double *p = s.v + 3 * i;
		badz += p[2] != 0;
		for (int k = 0; k < 4; k++)
			corner[k] |= p[0] == (k & 1) && p[1] == (k >> 1);
	}
	CHECK(badz == 0, "plane: %d vertices off z = 0", badz);
	CHECK(corner[0] && corner[1] && corner[2] && corner[3], "plane: a corner was moved");
	CHECK(st.in == 2 * N * N && st.vertices == (N + 1) * (N + 1) && st.boundary_edges == 4 * N,
	      "plane: welded %zu vertices, %zu triangles, %zu open edges", st.vertices, st.in,
	      st.boundary_edges);
	free(s.v);
}

static void split(struct soup *s, const double *a, const double *b, const double *c, int level)
{
	if (level == 0) {
		add(s, a, b, c);
		return;
	}
	double m[3][3];
	const double *e[3][2] = {{a, b}, {b, c}, {c, a}};
	for (int k = 0; k < 3; k++) {
		double l = 0;
		for (int d = 0; d < 3; d++) {
			m[k][d] = e[k][0][d] + e[k][1][d];
			l += m[k][d] * m[k][d];
		}
		l = sqrt(l);
		for (int d = 0; d < 3; d++)
			m[k][d] /= l;
	}
	split(s, a, m[0], m[2], level - 1);
	split(s, m[0], b, m[1], level - 1);
	split(s, m[2], m[1], c, level - 1);
	split(s, m[0], m[1], m[2], level - 1);
}

static struct soup sphere(void)
{
	const double g = (1 + sqrt(5.0)) / 2;
	double v[12][3] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
			   {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
	static const int f[20][3] = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
				     {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
				     {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
				     {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
	for (int i = 0; i < 12; i++) {
		double l = sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
		for (int d = 0; d < 3; d++)
			v[i][d] /= l;
	}
	struct soup s = {NULL, 0, 0};
	for (int k = 0; k < 20; k++)
		split(&s, v[f[k][0]], v[f[k][1]], v[f[k][2]], 4);
	return s;
}

struct edge {
	double a[3], b[3];
	int dir;
};

static int vcmp(const double *a, const double *b)
{
	for (int d = 0; d < 3; d++)
		if (a[d] != b[d])
			return a[d] < b[d] ? -1 : 1;
	return 0;
}

static int ecmp(const void *x, const void *y)
{
	const struct edge *e = x, *f = y;
	int c = vcmp(e->a, f->a);
	return c ? c : vcmp(e->b, f->b);
}

/* edges not in exactly two triangles of opposite directions; V - E + F */
static long closedness(const struct soup *s, long *euler)
{
	struct edge *e = xreallocarray(NULL, 3 * s->n, sizeof *e);
	double (*vx)[3] = xreallocarray(NULL, 3 * s->n, sizeof *vx);
	for (size_t i = 0; i < 3 * s->n; i++) {
		const double *a = s->v + 3 * i, *b = s->v + 9 * (i / 3) + 3 * ((i + 1) % 3);
		int dir = vcmp(a, b) < 0;
		memcpy(e[i].a, dir ? a : b, sizeof e[i].a);
		memcpy(e[i].b, dir ? b : a, sizeof e[i].b);
		e[i].dir = dir;
		memcpy(vx[i], a, sizeof vx[i]);
	}
	qsort(e, 3 * s->n, sizeof *e, ecmp);
	qsort(vx, 3 * s->n, sizeof *vx, (int (*)(const void *, const void *))vcmp);
	long bad = 0, ne = 0, nv = 0;
	for (size_t i = 0; i < 3 * s->n;) {
		size_t j = i + 1;
		while (j < 3 * s->n && ecmp(&e[i], &e[j]) == 0)
			j++;
		bad += j - i != 2 || e[i].dir == e[i + 1].dir;
		ne++;
		i = j;
	}
	for (size_t i = 0; i < 3 * s->n; i++)
		nv += i == 0 || vcmp(vx[i], vx[i - 1]) != 0;
	*euler = nv - ne + (long)s->n;
	free(e);
	free(vx);
	return bad;
}

static void spheres(void)
{
	struct soup in = sphere(), s = sphere();
	const double tol = 0.03;
	double emax = 0;        /* the longest input edge's angle */
	for (size_t i = 0; i < 3 * in.n; i++) {
		const double *a = in.v + 3 * i, *b = in.v + 9 * (i / 3) + 3 * ((i + 1) % 3);
		emax = fmax(emax, acos(fmin(1, a[0] * b[0] + a[1] * b[1] + a[2] * b[2])));
	}
	double sag = 1 - cos(emax / 2), a0, v0, a1, v1;
	area_vol(&in, &a0, &v0, NULL);
	struct tri_decimate_stats st;
	s.n = tri_decimate(s.v, s.n, tol, 1e-12, NULL, 0, NULL, &st);
	printf("sphere: welded %zu vertices, %zu open edges, %zu locked\n", st.vertices, st.boundary_edges, st.locked);
	area_vol(&s, &a1, &v1, NULL);
	CHECK(3 * s.n < in.n, "sphere: %zu of %zu triangles remain", s.n, in.n);
	long euler, bad = closedness(&s, &euler);
	CHECK(bad == 0 && euler == 2, "sphere: %ld bad edges, Euler characteristic %ld", bad, euler);
	double rlo = INFINITY, rhi = 0, vlo = INFINITY, vhi = 0;
	for (size_t i = 0; i < s.n; i++) {
		const double *t = s.v + 9 * i;
		for (int p = 0; p <= 4; p++)
			for (int q = 0; p + q <= 4; q++) {
				double x[3], u = p / 4.0, w = q / 4.0;
				for (int d = 0; d < 3; d++)
					x[d] = (1 - u - w) * t[d] + u * t[3 + d] + w * t[6 + d];
				double r = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
				rlo = fmin(rlo, r);
				rhi = fmax(rhi, r);
				if ((p == 0 && q == 0) || p == 4 || q == 4) {
					vlo = fmin(vlo, r);
					vhi = fmax(vhi, r);
				}
			}
	}
	CHECK(fabs(vlo - 1) <= 1e-12 && fabs(vhi - 1) <= 1e-12, "sphere: a vertex at radius %.17g or %.17g",
	      vlo, vhi);
	CHECK(rlo >= 1 - sag - tol - 1e-12 && rhi <= 1 + 1e-12,
	      "sphere: points at radius %.9g to %.9g, want %.9g to 1", rlo, rhi, 1 - sag - tol);
	CHECK(fabs(v1 - v0) <= a0 * tol, "sphere: volume %.9g, input %.9g", v1, v0);
	printf("sphere: %zu -> %zu triangles, radius %.6f to %.6f (input sag %.6f), volume %.6f -> %.6f\n",
	       in.n, s.n, rlo, rhi, sag, v0, v1);
	free(s.v);
	/* tol 0: welding only */
	s = sphere();
	s.n = tri_decimate(s.v, s.n, 0, 1e-12, NULL, 0, NULL, NULL);
	CHECK(s.n == in.n && memcmp(s.v, in.v, 9 * in.n * sizeof *s.v) == 0, "sphere, tol 0: changed");
	free(s.v);
	free(in.v);
}

/* the triangles of m as a soup */
static struct soup mesh_soup(const struct tri_mesh *m)
{
	struct soup s = {NULL, 0, 0};
	for (size_t t = 0; t < m->nt; t++) {
		const int *a = m->tv + 3 * t;
		add(&s, m->p + 3 * (size_t)a[0], m->p + 3 * (size_t)a[1], m->p + 3 * (size_t)a[2]);
	}
	return s;
}

static void welded(void)
{
	const double weld = 1e-9;
	struct soup in = sphere();
	/* each corner moved by its own small amount: equal points are
	 * one vertex only by the weld */
	for (size_t i = 0; i < 9 * in.n; i++)
		in.v[i] += 0.4 * weld * ((double)((i * 7919) % 11) - 5) / 5;
	for (int k = 0; k < 2; k++) {
		double tol = k == 0 ? 0.03 : 0;
		struct soup s = {xreallocarray(NULL, 9 * in.n, sizeof *s.v), in.n, 9 * in.n};
		memcpy(s.v, in.v, 9 * in.n * sizeof *s.v);
		struct tri_decimate_stats st;
		s.n = tri_decimate(s.v, s.n, tol, weld, NULL, 0, NULL, &st);
		CHECK(st.vertices == 2562, "welded: %zu vertices, want the icosphere's 2562", st.vertices);
		struct tri_weld w = {0};
		w.eps = weld;
		for (size_t t = 0; t < in.n; t++)
			tri_weld_add(&w, in.v + 9 * t);
		struct tri_mesh m = {0};
		size_t n = tri_decimate_welded(&w, tol, NULL, 0, NULL, NULL, &m);
		struct soup o = mesh_soup(&m);
		CHECK(n == s.n && o.n == s.n && memcmp(o.v, s.v, 9 * s.n * sizeof *s.v) == 0,
		      "welded, tol %g: %zu triangles, tri_decimate %zu, or others", tol, n, s.n);
		CHECK(w.nv == 0 && w.nt == 0, "welded, tol %g: the welder holds %zu vertices after", tol, w.nv);
		printf("welded: tol %g, %zu -> %zu triangles\n", tol, in.n, n);
		tri_mesh_free(&m);
		tri_weld_free(&w);
		free(o.v);
		free(s.v);
	}
	free(in.v);
}

int main(void)
{
	util_setprog("tri_decimate");
	plane();
	spheres();
	welded();
	if (nfail)
		fprintf(stderr, "tri_decimate: %d checks failed\n", nfail);
	return nfail != 0;
}
