/*
 * solid.c - mxyz.solid.3D, the surface of constant M (thesis Figure 8.15,
 * "a contour map of constant M = 0.8"), for pdraw -h -nosort.
 *
 * The isosurface comes from the library's marching tetrahedra (iso.h),
 * closed off at the box faces so that the exposed region M < level is a
 * watertight solid.  Triangles are collected, then written into one pdraw
 * set as closed 4-point curves (the form conv -t writes), the text
 * formatted on the thread pool.
 */
#include "bleach.h"
#include "fmt_plot.h"
#include "iso.h"
#include "util.h"

#include <stdlib.h>
#include <string.h>

/* The triangles, kept in memory: one pass of the (costly) surface
 * extraction instead of one to count and one to write; they take less
 * room than the M array they come from (a surface against a volume). */
struct tris {
	double *p;                      /* 9 coordinates each */
	size_t n, cap;
};

static void keep_tri(void *ctx, const double tri[9])
{
	struct tris *t = ctx;
	xgrow(&t->p, &t->cap, (t->n + 1) * 9, sizeof *t->p);
	memcpy(t->p + t->n * 9, tri, 9 * sizeof *t->p);
	t->n++;
}

/* triangle i as a closed 4-point curve (the form conv -t writes) */
static void tri_curve(void *ctx, size_t i, double *p)
{
	const struct tris *t = ctx;
	memcpy(p, t->p + i * 9, 9 * sizeof *p);
	memcpy(p + 9, t->p + i * 9, 3 * sizeof *p);
}

long solid_write(const char *path, const double *f, int nx, int ny, int nz,
		 const double bounds[6], double level)
{
	struct tris t = {NULL, 0, 0};
	iso_surface(f, nx, ny, nz, bounds, level, 1, keep_tri, &t);
	struct plot_writer *w = fmt_plot_open(path, 3);
	fmt_plot_labels(w, fmt_labels_std(LABELS_PAC));
	fmt_plot_begin_set(w, bounds, (long)t.n);
	fmt_plot_curves(w, t.n, 4, tri_curve, &t);
	fmt_plot_close(w);
	free(t.p);
	return (long)t.n;
}
