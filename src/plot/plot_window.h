/*
 * plot_window.h - 3D plot sets cut to an x-y window (pdraw -window).
 */
#ifndef S3D_PLOT_WINDOW_H
#define S3D_PLOT_WINDOW_H

#include "fmt_plot.h"

/* The sets cut to the window w = x0 x1 y0 y1 (um), one set for each:
 * polygons (closed curves) clipped to it, open curves kept in their runs
 * of points inside it; a set's x and y bounds become the window (within
 * its own bounds).  The caller frees it with fmt_plot_free. */
struct plot_file *plot_window_sets(const struct plot_set *const *sets, int nsets,
				   const double *w);

#endif
