/*
 * iso.c - tests of iso_surface (src/lib/iso.c), marching tetrahedra.
 *
 * Against exact answers:
 *  1. f = |r|^2 on [-1,1]^3, level 0.25: a sphere of radius 0.5.  The
 *     surface must be watertight and consistently oriented (every
 *     directed edge matched by its reverse exactly once), every vertex at
 *     radius 0.5 within 1% (linear interpolation of a quadratic on a
 *     0.05 grid), the enclosed volume (divergence theorem) within 1% of
 *     4/3 pi 0.5^3, and the normals point outwards (towards f > level).
 *  2. The same field at level 1.5 with closed = 1: the ball of radius
 *     sqrt(1.5) cut by the box.  Watertight, and its volume equals the
 *     volume of box ∩ ball counted independently on a fine lattice within
 *     1%.
 *  3. level above every value, closed = 1: the box itself, volume 8 to
 *     1e-9, area 24 to 1e-9.
 *  4. closed = 0 on case 2: the caps are missing, so the surface is open
 *     (unmatched edges exist): the option really changes something.
 *  5. The sphere at level 0.25 + 1e-8, a hair above the value at the grid
 *     points (+-0.5, 0, 0) and the like: the triangles around them have
 *     edges of about 1e-8 and must all be there, watertight as in 1 (a
 *     threshold on their area once left a hole there, which measure
 *     refuses as a gap of the surface).
 *  6. iso_value_at inverts iso_crossing (both edge models, either order of
 *     the ends): the crossing of the value at s is s within 1e-12.
 */
#include "iso.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct acc {
	double *t;
	size_t n, cap;
};

static void keep(void *ctx, const double tri[9])
{
	struct acc *a = ctx;
	xgrow(&a->t, &a->cap, (a->n + 1) * 9, sizeof(double));
	memcpy(a->t + a->n * 9, tri, 9 * sizeof(double));
	a->n++;
}

struct edge { long a[3], b[3]; };

static int cmp_pt(const long *p, const long *q)
{
	for (int d = 0; d < 3; d++)
		if (p[d] != q[d])
			return p[d] < q[d] ? -1 : 1;
	return 0;
}

static int cmp_edge(const void *x, const void *y)
{
	const struct edge *e = x, *f = y;
	int c = cmp_pt(e->a, f->a);
	return c ? c : cmp_pt(e->b, f->b);
}

/* counts directed edges without their reverse, and duplicated ones */
static long open_edges(const struct acc *a)
{
	size_t n = a->n * 3;
	struct edge *e = xcalloc(n, sizeof *e);
	for (size_t t = 0; t < a->n; t++)
		for (int k = 0; k < 3; k++) {
			const double *p = a->t + t * 9 + 3 * k, *q = a->t + t * 9 + 3 * ((k + 1) % 3);
			for (int d = 0; d < 3; d++) {
				e[t * 3 + k].a[d] = lround(p[d] * 1e9);
				e[t * 3 + k].b[d] = lround(q[d] * 1e9);
			}
		}
	qsort(e, n, sizeof *e, cmp_edge);
	long bad = 0;
	for (size_t i = 0; i < n; i++) {
		struct edge r;
		memcpy(r.a, e[i].b, sizeof r.a);
		memcpy(r.b, e[i].a, sizeof r.b);
		if (!bsearch(&r, e, n, sizeof *e, cmp_edge))
			bad++;
		if (i + 1 < n && cmp_edge(&e[i], &e[i + 1]) == 0)
			bad++;
	}
	free(e);
	return bad;
}

static double volume(const struct acc *a, double *area)
{
	double v = 0;
	*area = 0;
	for (size_t t = 0; t < a->n; t++) {
		const double *p = a->t + t * 9;
		double u[3], w[3], c[3];
		for (int d = 0; d < 3; d++)
			u[d] = p[3 + d] - p[d], w[d] = p[6 + d] - p[d];
		c[0] = u[1] * w[2] - u[2] * w[1];
		c[1] = u[2] * w[0] - u[0] * w[2];
		c[2] = u[0] * w[1] - u[1] * w[0];
		*area += 0.5 * sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
		/* outward normals: the region f < level is inside */
		v += (p[0] * c[0] + p[1] * c[1] + p[2] * c[2]) / 6.0;
	}
	return v;
}

static int failures;
#define CHECK(c, ...) do { if (!(c)) { printf("FAIL: " __VA_ARGS__); printf("\n"); failures++; } } while (0)

int main(void)
{
	enum { N = 41 };
	const double b[6] = {-1, 1, -1, 1, -1, 1};
	double *f = xmalloc(sizeof(double) * N * N * N);
	for (int k = 0; k < N; k++)
		for (int j = 0; j < N; j++)
			for (int i = 0; i < N; i++) {
				double x = -1 + 2.0 * i / (N - 1), y = -1 + 2.0 * j / (N - 1), z = -1 + 2.0 * k / (N - 1);
				f[(k * N + j) * N + i] = x * x + y * y + z * z;
			}

	struct acc a = {0};
	double area;
	iso_surface(f, N, N, N, b, 0.25, 0, keep, &a);
	CHECK(a.n > 100, "sphere: only %zu triangles", a.n);
	CHECK(open_edges(&a) == 0, "sphere: %ld unmatched edges", open_edges(&a));
	double maxerr = 0;
	for (size_t i = 0; i < a.n * 3; i++) {
		const double *p = a.t + 3 * i;
		maxerr = fmax(maxerr, fabs(sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 0.5));
	}
	CHECK(maxerr < 0.005, "sphere: vertex radius error %g > 0.005", maxerr);
	double v = volume(&a, &area), vex = 4.0 / 3.0 * M_PI * 0.125;
	CHECK(fabs(v - vex) < 0.01 * vex, "sphere: volume %g, expected %g (1%%)", v, vex);
	printf("sphere: %zu triangles, radius error %.2e, volume %.6f (exact %.6f)\n", a.n, maxerr, v, vex);

	a.n = 0;
	iso_surface(f, N, N, N, b, 1.5, 1, keep, &a);
	CHECK(open_edges(&a) == 0, "cut ball: %ld unmatched edges", open_edges(&a));
	v = volume(&a, &area);
	/* independent volume: midpoint lattice of 200^3 points */
	long inside = 0;
	const int M = 200;
	for (int k = 0; k < M; k++)
		for (int j = 0; j < M; j++)
			for (int i = 0; i < M; i++) {
				double x = -1 + (i + 0.5) * 2.0 / M, y = -1 + (j + 0.5) * 2.0 / M, z = -1 + (k + 0.5) * 2.0 / M;
				inside += x * x + y * y + z * z < 1.5;
			}
	vex = 8.0 * inside / ((double)M * M * M);
	CHECK(fabs(v - vex) < 0.01 * vex, "cut ball: volume %g, lattice %g (1%%)", v, vex);
	printf("cut ball: %zu triangles, volume %.6f (lattice %.6f)\n", a.n, v, vex);

	a.n = 0;
	iso_surface(f, N, N, N, b, 1.5, 0, keep, &a);
	CHECK(open_edges(&a) > 0, "open cut ball: expected unmatched edges");

	a.n = 0;
	iso_surface(f, N, N, N, b, 10, 1, keep, &a);
	v = volume(&a, &area);
	CHECK(open_edges(&a) == 0, "box: %ld unmatched edges", open_edges(&a));
	CHECK(fabs(v - 8) < 1e-9 && fabs(area - 24) < 1e-9, "box: volume %.12g area %.12g, expected 8 and 24", v, area);
	printf("box: %zu triangles, volume %.12g, area %.12g\n", a.n, v, area);

	a.n = 0;
	iso_surface(f, N, N, N, b, 0.25 + 1e-8, 0, keep, &a);
	CHECK(open_edges(&a) == 0, "sphere a hair above grid points: %ld unmatched edges", open_edges(&a));
	printf("sphere at 0.25 + 1e-8: %zu triangles, %ld unmatched edges\n", a.n, open_edges(&a));

	double worst = 0;
	const double ends[4][4] = {{1, 0, 2, 0}, {2, 0, 1, 0}, {1, 0.5, 3, 2}, {3, 2, 1, 0.5}};
	for (int e = 0; e < 4; e++)
		for (int k = 0; k <= 10; k++) {
			const double s = k / 10.0, *q = ends[e];
			double c = iso_crossing(q[0], q[1], q[2], q[3], iso_value_at(q[0], q[1], q[2], q[3], s));
			worst = fmax(worst, fabs(c - s));
		}
	CHECK(worst < 1e-12, "iso_value_at: its crossing is off by %g", worst);

	free(a.t);
	free(f);
	return failures != 0;
}
