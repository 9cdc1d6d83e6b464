/*
 * fmt_contour.h - the contour-file of contour(L): a scalar on a regular
 * x-y grid (the aerial image from splat, any surface for contour).
 *
 *   xmin xmax ymin ymax
 *   nxpts nypts
 *   z ...            nxpts*nypts values, x varying fastest
 *
 * Grid points include both ends: x_i = xmin + i (xmax-xmin)/(nx-1).
 * The -old format is a 50x50 grid with first line "xmin ymin xlength
 * ylength" and no counts.  See man/man5/contour.5.  A file starting with
 * the word "stack" is an image stack (fmt_stack.h), which this reader
 * refuses by name.  '#' lines at the head are comments; one "# labels
 * ..." line carries the title and the x, y and value (z) labels
 * (fmt_labels.h).
 */
#ifndef S3D_FMT_CONTOUR_H
#define S3D_FMT_CONTOUR_H

#include "fmt_labels.h"

#include <stdio.h>

enum { CONTOUR_OLD_N = 50, CONTOUR_MAX_N = 100000 };

struct contour {
	double xmin, xmax, ymin, ymax;
	int nx, ny;
	double *z;          /* z[j*nx + i] at (x_i, y_j) */
	struct plot_labels labels;  /* fmt_contour_read/write only; "" unset */
};

struct contour *fmt_contour_new(double xmin, double xmax, double ymin,
				double ymax, int nx, int ny);
/* old != 0 reads the -old format. */
struct contour *fmt_contour_read(const char *path, int old);
void fmt_contour_write(const char *path, const struct contour *c);
void fmt_contour_write_old(const char *path, const struct contour *c);
void fmt_contour_free(struct contour *c);

/* For readers of formats that embed contour-files (fmt_stack.c): the
 * header and values from lx, whose first token (NULL at the end) the
 * caller has already taken; and the same written to an open stream. */
struct lex;
struct contour *fmt_contour_parse(struct lex *lx, const char *first, int old);
void fmt_contour_put(FILE *f, const struct contour *c);

double fmt_contour_x(const struct contour *c, int i);
double fmt_contour_y(const struct contour *c, int j);

#endif
