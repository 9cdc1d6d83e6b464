/*
 * fmt_plot.h - the plot files of pdraw(L) (3D) and drawplot(L) (2D, the
 * SAMPLE plot format).  A file holds one or more sets (one graph each):
 *
 *   xmin xmax ymin ymax [zmin zmax]
 *   ncurves
 *   npts                 per curve, then npts lines "x y [z]"
 *
 * Sets follow each other, separated by a blank line when written.  Counts
 * may be written as "4.0"; commas may separate numbers (image.cont of
 * contour -c writes "xmin, xmax, ymin, ymax").  See man/man5/plot3d.5
 * and plot2d.5.  '#' lines at the head of the file are comments; one
 * "# labels ..." line carries the title and axis labels (fmt_labels.h).
 *
 * Two ways to write: build a struct plot_file and call fmt_plot_write,
 * or stream large outputs (etch) set by set with fmt_plot_open.
 */
#ifndef S3D_FMT_PLOT_H
#define S3D_FMT_PLOT_H

#include "fmt_labels.h"

#include <stddef.h>

enum { PLOT_MAX_COUNT = 2000000000 };

struct plot_curve {
	int npts;
	double *p;          /* npts * dim coordinates, point after point */
};

struct plot_set {
	double bounds[6];   /* xmin xmax ymin ymax [zmin zmax] */
	int ncurves;
	struct plot_curve *curves;
	size_t cap;         /* allocated curves */
	double *pool;       /* fmt_plot_read: the points of the first npooled
			     * curves, one block their p point into; curves
			     * added later (fmt_plot_add_curve) own theirs */
	int npooled;
};

struct plot_file {
	int dim;            /* 2 or 3 */
	int nsets;
	struct plot_set *sets;
	size_t cap;
	struct plot_labels labels;  /* from the head of the file; "" unset */
	long first_line;            /* fmt_plot_read: the line of the first
				     * number (1 without comment lines) */
};

struct plot_file *fmt_plot_new(int dim);
/* Appends an empty set with the given bounds (dim*2 values). */
struct plot_set *fmt_plot_add_set(struct plot_file *pf, const double *bounds);
/* Appends a curve of npts points (copied from p, npts*dim values). */
void fmt_plot_add_curve(struct plot_file *pf, struct plot_set *s, int npts,
			const double *p);
/* The size of a plot file before it is read, for a reader's estimate of
 * its memory and time (budget.h): *text the bytes of its text, *numbers
 * the numbers it holds, from the density of its first PLOT_SAMPLE bytes;
 * a compressed file is inflated and counted through (held nowhere), up
 * to the memory limit past which it is refused anyway.
 * Returns 0 (and zeros) when the size is unknown: stdin, a pipe. */
#define PLOT_SAMPLE 65536
int fmt_plot_size(const char *path, double *text, double *numbers);
/* Reads a 2D (dim 2) or 3D (dim 3) plot file. */
struct plot_file *fmt_plot_read(const char *path, int dim);
void fmt_plot_write(const char *path, const struct plot_file *pf);
void fmt_plot_free(struct plot_file *pf);

/* Streaming writer. */
struct plot_writer;
struct plot_writer *fmt_plot_open(const char *path, int dim);
/* Writes the labels line (nothing if w or l is NULL or l is empty; a 2D
 * file drops a z label); only before the first set. */
void fmt_plot_labels(struct plot_writer *w, const struct plot_labels *l);
/* Starts a set: its bounds and how many curves will follow. */
void fmt_plot_begin_set(struct plot_writer *w, const double *bounds, long ncurves);
void fmt_plot_curve(struct plot_writer *w, int npts, const double *p);
/* n curves of npts points each, the same bytes as n fmt_plot_curve calls;
 * get(ctx, i, p) fills the npts * dim coordinates of curve i.  Formatting
 * runs on the thread pool (par.h), so get must be safe to call from
 * several threads at once; the text is written in order. */
void fmt_plot_curves(struct plot_writer *w, size_t n, int npts,
		     void (*get)(void *ctx, size_t i, double *p), void *ctx);
/* Checks the counts promised, commits the file (atomic rename). */
void fmt_plot_close(struct plot_writer *w);

/* The triangles (surf.h) of one set of a plot3d file: every curve must be a
 * triangle (a closed curve of 4 points, the first repeated) and the
 * bounds a box.  Otherwise returns NULL with what is wrong in err
 * ("curve M: ..."), having allocated nothing. */
struct surf;
struct surf *surf_from_plot_set(const struct plot_set *set, char *err, size_t errsz);

#endif
