/*
 * solid.c - mxyz.solid.3D, the surface of constant M (thesis Figure 8.15,
 * "a contour map of constant M = 0.8"), for pdraw -h -nosort.
 *
 * The isosurface comes from the library's marching tetrahedra (iso.h),
 * closed off at the box faces so that the exposed region M < level is a
 * watertight solid.  Triangles are streamed into one pdraw set as closed
 * 4-point curves (the form conv -t writes), counted first so that the set
 * header can promise the count.
 */
#include "bleach.h"
#include "fmt_plot.h"
#include "iso.h"

#include <string.h>

static void count_tri(void *ctx, const double tri[9])
{
	(void)tri;
	++*(long *)ctx;
}

static void put_tri(void *ctx, const double tri[9])
{
	double p[12];
	memcpy(p, tri, 9 * sizeof *p);
	memcpy(p + 9, tri, 3 * sizeof *p);
	fmt_plot_curve(ctx, 4, p);
}

long solid_write(const char *path, const double *f, int nx, int ny, int nz,
		 const double bounds[6], double level)
{
	long n = 0;
	iso_surface(f, nx, ny, nz, bounds, level, 1, count_tri, &n);
	struct plot_writer *w = fmt_plot_open(path, 3);
	fmt_plot_begin_set(w, bounds, n);
	iso_surface(f, nx, ny, nz, bounds, level, 1, put_tri, w);
	fmt_plot_close(w);
	return n;
}
