/*
 * tests/measure/surf.c - the library's surf module against independent
 * methods:
 *   - surf_crossings (uniform grid) against a test of every pair of
 *     triangles with the Moller-Trumbore segment-triangle test, on 2000
 *     random small triangles in a box (a few hundred crossing pairs) and
 *     on the same set with large triangles mixed in; the counts must be
 *     equal (random triangles are never within the touching tolerance);
 *   - surf_above (the ray test through the x-y grid) against counting
 *     every triangle above random points, on the same sets;
 *   - surf_region_area on a square hole with a square island in it (an
 *     annulus: the island's area is not the hole's; exact within 1e-3),
 *     and on two holes joined by a thin channel (one region: the same
 *     area from either hole, both holes and the channel within 2e-3).
 */
#include "surf.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int failures;
#define CHECK(c, ...) do { if (!(c)) { printf("FAIL: " __VA_ARGS__); printf("\n"); failures++; } } while (0)

static unsigned long long rng = 88172645463325252ULL;
static double urand(void)
{
	rng ^= rng << 13;
	rng ^= rng >> 7;
	rng ^= rng << 17;
	return (double)(rng >> 11) / 9007199254740992.0;
}

static void sub(const double *a, const double *b, double *r)
{
	for (int k = 0; k < 3; k++)
		r[k] = a[k] - b[k];
}

/* Moller-Trumbore: does segment p-q pass through triangle t's inside? */
static int mt_segment(const double *p, const double *q, const double *t)
{
	double d[3], e1[3], e2[3], h[3], sv[3], qv[3];
	sub(q, p, d);
	sub(t + 3, t, e1);
	sub(t + 6, t, e2);
	h[0] = d[1] * e2[2] - d[2] * e2[1];
	h[1] = d[2] * e2[0] - d[0] * e2[2];
	h[2] = d[0] * e2[1] - d[1] * e2[0];
	double a = e1[0] * h[0] + e1[1] * h[1] + e1[2] * h[2];
	if (fabs(a) < 1e-300)
		return 0;
	double f = 1 / a;
	sub(p, t, sv);
	double u = f * (sv[0] * h[0] + sv[1] * h[1] + sv[2] * h[2]);
	if (u <= 0 || u >= 1)
		return 0;
	qv[0] = sv[1] * e1[2] - sv[2] * e1[1];
	qv[1] = sv[2] * e1[0] - sv[0] * e1[2];
	qv[2] = sv[0] * e1[1] - sv[1] * e1[0];
	double v = f * (d[0] * qv[0] + d[1] * qv[1] + d[2] * qv[2]);
	if (v <= 0 || u + v >= 1)
		return 0;
	double s = f * (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]);
	return s > 0 && s < 1;
}

static int mt_pair(const double *a, const double *b)
{
	for (int k = 0; k < 3; k++)
		if (mt_segment(a + 3 * k, a + 3 * ((k + 1) % 3), b) ||
		    mt_segment(b + 3 * k, b + 3 * ((k + 1) % 3), a))
			return 1;
	return 0;
}

static struct surf *random_set(int n, int nbig)
{
	double box[6] = {0, 4, 0, 3, -1, 0};
	struct surf *s = surf_new(box);
	for (int i = 0; i < n + nbig; i++) {
		double size = i < n ? 0.2 : 1.5, c[3], t[9];
		c[0] = box[0] + urand() * (box[1] - box[0]);
		c[1] = box[2] + urand() * (box[3] - box[2]);
		c[2] = box[4] + urand() * (box[5] - box[4]);
		for (int k = 0; k < 9; k++)
			t[k] = c[k % 3] + size * (urand() - 0.5);
		surf_add(s, t);
	}
	return s;
}

static void check_set(struct surf *s, const char *name)
{
	long brute = 0;
	for (size_t i = 0; i < s->ntri; i++)
		for (size_t j = i + 1; j < s->ntri; j++)
			brute += mt_pair(s->v + 9 * i, s->v + 9 * j);
	long grid = surf_crossings(s, 1000000);
	printf("%s: %zu triangles, %ld crossing pairs (every pair), %ld (grid)\n",
	       name, s->ntri, brute, grid);
	CHECK(brute > 50, "%s: too few crossings to test (%ld)", name, brute);
	CHECK(grid == brute, "%s: grid %ld, every pair %ld", name, grid, brute);
	CHECK(surf_crossings(s, 7) == 7, "%s: the count does not stop at max", name);

	surf_index(s);
	int bad = 0;
	for (int i = 0; i < 1000; i++) {
		double x = 4 * urand(), y = 3 * urand(), z = -urand();
		int n = 0;
		for (size_t t = 0; t < s->ntri; t++) {
			/* the vertical ray as a long segment */
			double p[3] = {x, y, z}, q[3] = {x, y, 100};
			n += mt_segment(p, q, s->v + 9 * t);
		}
		bad += n != surf_above(s, x, y, z);
	}
	CHECK(bad == 0, "%s: the ray test differs from every triangle at %d of 1000 points", name, bad);
}

/* Quads of a height field z(x, y) on an n x n grid over the box, z from f. */
static struct surf *height_field(int n, double (*f)(double, double))
{
	double box[6] = {-1, 1, -1, 1, -1, 0};
	struct surf *s = surf_new(box);
	double h = 2.0 / n;
	for (int i = 0; i < n; i++)
		for (int j = 0; j < n; j++) {
			/* shared vertices computed the same way: a watertight mesh */
			double x0 = -1 + i * h, y0 = -1 + j * h;
			double x1 = -1 + (i + 1) * h, y1 = -1 + (j + 1) * h;
			double a[3] = {x0, y0, f(x0, y0)}, b[3] = {x1, y0, f(x1, y0)};
			double c[3] = {x1, y1, f(x1, y1)}, d[3] = {x0, y1, f(x0, y1)};
			double t1[9] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]};
			double t2[9] = {a[0], a[1], a[2], c[0], c[1], c[2], d[0], d[1], d[2]};
			surf_add(s, t1);
			surf_add(s, t2);
		}
	surf_index(s);
	return s;
}

/* A square hole down to -1 with a square island standing in it, on a
 * 40 x 40 grid: nodes with max(|x|, |y|) from 0.25 to 0.45 are at -1, the
 * rest at 0.  The walls are one cell (0.05) wide, so at z = -0.5 they
 * are at 0.475 and 0.225; the diagonals cut two corners of each square by
 * the same triangle, so the area between is 0.95^2 - 0.45^2 = 0.7. */
static double annulus(double x, double y)
{
	double m = fmax(fabs(x), fabs(y));
	return (m < 0.22 || m > 0.48) ? 0 : -1;
}

/* Two square holes (0.35 wide at mid-wall, centred at x = -0.5 and 0.5)
 * joined by a channel 0.15 wide at mid-wall along y = 0. */
static double channel(double x, double y)
{
	int in = (fabs(x + 0.5) < 0.17 && fabs(y) < 0.17) || (fabs(x - 0.5) < 0.17 && fabs(y) < 0.17) ||
		 (fabs(x) < 0.5 && fabs(y) < 0.07);
	return in ? -1 : 0;
}

int main(void)
{
	util_setprog("surf");
	struct surf *s = random_set(2000, 0);
	check_set(s, "small triangles");
	surf_free(s);
	s = random_set(2000, 40);
	check_set(s, "small and large triangles");
	surf_free(s);

	/* region areas: the section at z = -0.5 lies half way down the walls */
	s = height_field(40, annulus);
	struct surf_section sec;
	surf_section(s, -0.5, &sec);
	int edge;
	double a = surf_region_area(s, &sec, 0.35, 0.01, 0.001, &edge);
	double want = 0.95 * 0.95 - 0.45 * 0.45;
	printf("annulus: area %.6f, exact %.6f\n", a, want);
	CHECK(fabs(a - want) < 1e-3, "annulus area %g, exact %g", a, want);
	CHECK(!edge, "annulus: reaches the box edge");
	a = surf_region_area(s, &sec, 0, 0, 0.001, &edge);
	CHECK(a == 0, "the island is resist, area %g", a);
	surf_section_free(&sec);
	surf_free(s);

	s = height_field(40, channel);
	surf_section(s, -0.5, &sec);
	a = surf_region_area(s, &sec, -0.5, 0, 0.001, &edge);
	double b = surf_region_area(s, &sec, 0.52, 0.03, 0.001, &edge);
	/* each hole 0.35 wide, the channel 0.15 wide over the 0.65 between */
	want = 2 * 0.35 * 0.35 + 0.15 * 0.65;
	printf("channel: area %.6f from one hole, %.6f from the other, about %.6f\n", a, b, want);
	CHECK(fabs(a - want) < 2e-3, "two holes and a channel: area %g, about %g", a, want);
	CHECK(fabs(a - b) < 1e-3, "two holes and a channel: %g from one hole, %g from the other", a, b);
	surf_section_free(&sec);
	surf_free(s);

	if (failures)
		printf("%d failures\n", failures);
	return failures != 0;
}
