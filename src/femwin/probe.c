/*
 * probe.c - the surface fem(1) runs measure on before a sweep, so that a
 * measure argument measure refuses (a height outside the resist, a point
 * outside the window, a malformed list) stops the sweep before anything
 * runs.  It is the resist before development, written as etch writes a
 * developed surface: one set whose box is the mask window (splat(5)) times
 * the resist thickness (bleach(5)), the flat top z = 0 as two triangles
 * whose normal points up, out of the resist (plot3d(5)).
 *
 * The grids the drivers' -accuracy refines are read off the same two
 * inputs here (femwin -resolution), by the library's readers.
 */
#include "femwin.h"
#include "fmt_bleach.h"
#include "fmt_plot.h"
#include "fmt_splat.h"
#include "util.h"

#include <stdio.h>

void femwin_probe(const char *splat_in, const char *bleach_in, const char *out)
{
	struct splat_input *si = fmt_splat_read(splat_in);
	struct bleach_input bi;
	fmt_bleach_read(bleach_in, &bi);
	double x0 = si->mask.xmin, x1 = si->mask.xmax, y0 = si->mask.ymin, y1 = si->mask.ymax;
	fmt_splat_free(si);
	double b[6] = {x0, x1, y0, y1, -bi.thick, 0};
	struct plot_file *pf = fmt_plot_new(3);
	struct plot_set *s = fmt_plot_add_set(pf, b);
	/* counter-clockwise seen from above: the developed side */
	double t1[12] = {x0, y0, 0, x1, y0, 0, x1, y1, 0, x0, y0, 0};
	double t2[12] = {x0, y0, 0, x1, y1, 0, x0, y1, 0, x0, y0, 0};
	fmt_plot_add_curve(pf, s, 4, t1);
	fmt_plot_add_curve(pf, s, 4, t2);
	fmt_plot_write(out, pf);
	fmt_plot_free(pf);
}

void femwin_resolution(const char *splat_in, const char *bleach_in)
{
	struct splat_input *si = fmt_splat_read(splat_in);
	int nx = si->nx, ny = si->ny;
	fmt_splat_free(si);
	struct bleach_input bi;
	fmt_bleach_read(bleach_in, &bi);
	if (bi.nx)
		die("%s:%ld: grid nx %d ny %d resamples the image on a grid of its own, which "
		    "-accuracy cannot refine: leave nx and ny out (the image's grid is used)",
		    bleach_in, bi.line_nz, bi.nx, bi.ny);
	printf("%d %d %d\n", nx, ny, bi.nz);
}
