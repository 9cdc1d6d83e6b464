/*
 * image.c - the tiles' aerial images joined into one contour-file
 * (stitch -image).  Every tile is on the output's grid (stitch -cut makes
 * it so): a point of the output is copied from the first tile, in the
 * order given, whose core holds it (a point on a seam is in two cores,
 * and the tiles agree there to their halo's accuracy).  Only the output
 * and one tile are held.
 */
#include "checked.h"
#include "fmt_contour.h"
#include "stitch.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Tiles on one grid have steps equal to this fraction. */
#define STEP_EPS 1e-9

static long idx(double v, double d, const char *what)
{
	return ck_long(nearbyint(v / d), -(long)CONTOUR_MAX_N, (long)CONTOUR_MAX_N, what);
}

void stitch_images(const struct tile *t, int n, const char *out)
{
	double u[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
	for (int k = 0; k < n; k++) {
		u[0] = fmin(u[0], t[k].core[0]), u[1] = fmax(u[1], t[k].core[1]);
		u[2] = fmin(u[2], t[k].core[2]), u[3] = fmax(u[3], t[k].core[3]);
	}
	struct contour *c = NULL, *o = NULL;
	char *filled = NULL;
	double d = 0;
	const char *cur = NULL;
	for (int k = 0; k < n; k++) {
		if (!cur || strcmp(cur, t[k].file) != 0) {
			fmt_contour_free(c);
			c = fmt_contour_read(t[k].file, 0);
			cur = t[k].file;
		}
		double dx = (c->xmax - c->xmin) / (c->nx - 1), dy = (c->ymax - c->ymin) / (c->ny - 1);
		if (!o) {
			d = dx;
			int nx = ck_int(nearbyint((u[1] - u[0]) / d) + 1, 2, CONTOUR_MAX_N, "the output's grid");
			int ny = ck_int(nearbyint((u[3] - u[2]) / d) + 1, 2, CONTOUR_MAX_N, "the output's grid");
			o = fmt_contour_new(u[0], u[1], u[2], u[3], nx, ny);
			o->labels = c->labels;
			filled = xcalloc(ck_mul((size_t)nx, (size_t)ny, "the output's grid"), 1);
		}
		if (fabs(dx - d) > STEP_EPS * d || fabs(dy - d) > STEP_EPS * d)
			die("%s: grid steps %g and %g um, not the first tile's %g", cur, dx, dy, d);
		long oi = idx(t[k].dx + c->xmin - u[0], d, "a tile's origin");
		long oj = idx(t[k].dy + c->ymin - u[2], d, "a tile's origin");
		long i0 = idx(t[k].core[0] - u[0], d, "a core"), i1 = idx(t[k].core[1] - u[0], d, "a core");
		long j0 = idx(t[k].core[2] - u[2], d, "a core"), j1 = idx(t[k].core[3] - u[2], d, "a core");
		if (i0 < oi || j0 < oj || i1 - oi >= c->nx || j1 - oj >= c->ny)
			die("%s: the image does not cover its core %g %g %g %g", cur, t[k].core[0],
			    t[k].core[1], t[k].core[2], t[k].core[3]);
		for (long j = j0; j <= j1; j++)
			for (long i = i0; i <= i1; i++) {
				size_t g = (size_t)j * (size_t)o->nx + (size_t)i;
				if (filled[g])
					continue;
				filled[g] = 1;
				o->z[g] = c->z[(size_t)(j - oj) * (size_t)c->nx + (size_t)(i - oi)];
			}
	}
	for (long j = 0; j < o->ny; j++)
		for (long i = 0; i < o->nx; i++)
			if (!filled[(size_t)j * (size_t)o->nx + (size_t)i])
				die("the tiles' cores leave the point x %g y %g uncovered",
				    fmt_contour_x(o, (int)i), fmt_contour_y(o, (int)j));
	fmt_contour_write(out, o);
	fmt_contour_free(c);
	fmt_contour_free(o);
	free(filled);
}
