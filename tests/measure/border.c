/*
 * tests/measure/border.c - the library's gaps of a section (surf_border_find,
 * surf_border_at) against closed forms, on a vertical wall x = 0 (y from
 * -1 to 1, z from -0.7 to 0, in squares of 0.1 um cut into two triangles
 * each) with a window left out for |y| < 0.2, -0.4 < z < -0.3:
 *   - the open border is the window's rim, 2 (0.4 + 0.1) = 1 um (exact
 *     within 1e-12), the median edge 0.1 um (within 1e-12);
 *   - at z = -0.35 the section's free ends are (0, -0.2) and (0, 0.2),
 *     one gap whose chord is between them (within 1e-12); with the four
 *     edges of the rim above the plane, 5 gaps meet a rectangle around
 *     (0, 0), the chord the nearest; a thin rectangle across the chord
 *     at y from 0.12 to 0.13, its corners all beyond it, meets the chord
 *     and one rim edge (2), one at x from 0.5 to 0.6 none;
 *   - at z = -0.5 no edge crosses the plane but the rim above it, seen
 *     from above, meets the rectangle around (0, 0);
 *   - at z = -0.2 the window is below the plane: no gap;
 *   - the closed wall has no open border and no gap at any height.
 */
#include "surf.h"
#include "util.h"

#include <math.h>
#include <stdio.h>

static int failures;
#define CHECK(c, ...) do { if (!(c)) { printf("FAIL: " __VA_ARGS__); printf("\n"); failures++; } } while (0)

/* The wall, with the window left out if window is set. */
static struct surf *wall(int window)
{
	double box[6] = {-1, 1, -1, 1, -0.7, 0};
	struct surf *s = surf_new(box);
	for (int i = 0; i < 20; i++)
		for (int k = 0; k < 7; k++) {
			double y0 = -1 + 0.1 * i, y1 = -1 + 0.1 * (i + 1);
			double z0 = -0.7 + 0.1 * k, z1 = -0.7 + 0.1 * (k + 1);
			if (k == 6)
				z1 = 0;
			/* the window: squares 8..11 in y, 3 in z */
			if (window && i >= 8 && i <= 11 && k == 3)
				continue;
			double t1[9] = {0, y0, z0, 0, y1, z0, 0, y1, z1};
			double t2[9] = {0, y0, z0, 0, y1, z1, 0, y0, z1};
			surf_add(s, t1);
			surf_add(s, t2);
		}
	return s;
}

int main(void)
{
	util_setprog("border");
	struct surf *s = wall(1);
	struct surf_border b;
	surf_border_find(s, &b);
	printf("window: %zu open edges, %.15g um, median edge %.15g um\n", b.n, b.length, b.median_edge);
	CHECK(fabs(b.length - 1) < 1e-12, "open border %.15g um, expected 1", b.length);
	CHECK(fabs(b.median_edge - 0.1) < 1e-12, "median edge %.15g, expected 0.1", b.median_edge);

	struct surf_gap g;
	double around[4] = {-0.15, 0.15, -0.15, 0.15};
	size_t n = surf_border_at(&b, -0.35, around, 0, 0, &g);
	double lo = fmin(g.a[1], g.b[1]), hi = fmax(g.a[1], g.b[1]);
	printf("z = -0.35: %zu gaps, nearest from (%g, %g) to (%g, %g)\n", n, g.a[0], g.a[1], g.b[0], g.b[1]);
	CHECK(n == 5, "z = -0.35: %zu gaps, expected 5", n);
	CHECK(fabs(g.a[0]) < 1e-12 && fabs(g.b[0]) < 1e-12 && fabs(lo + 0.2) < 1e-12 && fabs(hi - 0.2) < 1e-12,
	      "z = -0.35: the chord is (%g, %g)-(%g, %g), expected (0, -0.2)-(0, 0.2)",
	      g.a[0], g.a[1], g.b[0], g.b[1]);
	double thin[4] = {-0.01, 0.01, 0.12, 0.13};
	n = surf_border_at(&b, -0.35, thin, 0, 0, &g);
	CHECK(n == 2, "z = -0.35: %zu gaps across a thin rectangle, expected 2 (the chord, a rim edge)", n);
	double away[4] = {0.5, 0.6, -0.15, 0.15};
	CHECK(surf_border_at(&b, -0.35, away, 0, 0, &g) == 0, "z = -0.35: a gap 0.5 um from the window");
	CHECK(surf_border_at(&b, -0.5, around, 0, 0, &g) > 0, "z = -0.5: the window above is not seen");
	CHECK(surf_border_at(&b, -0.2, around, 0, 0, &g) == 0, "z = -0.2: the window below counts");
	surf_border_free(&b);
	surf_free(s);

	s = wall(0);
	surf_border_find(s, &b);
	CHECK(b.n == 0 && b.length == 0, "closed wall: %zu open edges", b.n);
	for (int k = 0; k <= 14; k++)
		CHECK(surf_border_at(&b, -0.7 + 0.05 * k, around, 0, 0, &g) == 0, "closed wall: a gap at z = %g",
		      -0.7 + 0.05 * k);
	surf_border_free(&b);
	surf_free(s);
	if (failures)
		printf("%d failures\n", failures);
	return failures != 0;
}
