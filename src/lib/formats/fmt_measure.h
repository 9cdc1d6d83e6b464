/*
 * fmt_measure.h - measure(1)'s table (measure(5)): a '#' line naming the
 * columns, one row per height, then '#' lines with the figures of the
 * whole feature:
 *
 *   # z cd area dx dy          a hole: area in um2, extents in um
 *   # z cd lo hi               a space or a line: the stretch's ends
 *   -0.63 0.81 0.515 0.81 0.81 one row per height, um
 *   # swa 86.2                 degrees, with two heights or more ("-":
 *                              the feature is absent at an end)
 *   # resist_loss 0.012        um
 *   # cleared yes              yes or no
 *   # ler left 0.002 right 0.003   -ler: 3 sigma of each edge, um
 *   # lwr 0.004                    3 sigma of the width, um
 *   # corr_length 0.02             um ("-": no 1/e crossing)
 *
 * and the hole-array table of -lcdu -holes:
 *
 *   # x y cd                   one row per hole: centroid, cd, um
 *   0.5 0.5 0.101
 *   # lcdu 0.004               3 sample sigma of the cds ("-": < 2 holes)
 *   # holes 49
 *
 * With measure -accuracy (and the drivers' -accuracy) a last column
 * "err" follows: the estimated discretisation error of cd, um.
 *
 * measure writes it; femwin -collect (fem) reads it for fem.dat.  The
 * reader takes any further column names after "z cd" (a table another
 * tool wrote), and skips '#' lines it does not know.
 */
#ifndef S3D_FMT_MEASURE_H
#define S3D_FMT_MEASURE_H

#include <stddef.h>

/* The most value columns after z and cd that a row keeps (a hole's
 * area, dx, dy); further ones are checked and dropped. */
enum { MEASURE_MAX_EXTRA = 3 };

struct measure_row {
	double z, cd;                   /* um */
	double v[MEASURE_MAX_EXTRA];    /* area dx dy, or lo hi */
	double err;                     /* um, with have_err */
};

struct measure_table {
	int hole;               /* columns z cd area dx dy; else z cd lo hi */
	int have_err;           /* a last column err (optional) */
	int ncols;              /* read: columns the header names, err included */
	int nrows;
	struct measure_row *rows;
	int have_swa;           /* a "# swa" line */
	double swa;             /* degrees; NAN for "-" or without the line */
	double resist_loss;     /* um; NAN without the line (read) */
	int cleared;
	int have_rough;         /* the roughness lines (-ler) */
	double ler[2];          /* um: the edge at the lower, the higher coordinate */
	double lwr;             /* um */
	double corr_length;     /* um; NAN for "-" */
};

/* One hole of an array (-lcdu -holes). */
struct measure_hole {
	double x, y;            /* centroid of its section, um */
	double cd;              /* um */
};

/* Writes t atomically: lengths rounded to 1e-6 um, areas to 1e-9 um2,
 * angles to 1e-3 degree, each printed in the shortest form that reads
 * back, so that the same surface gives the same bytes on any machine. */
void fmt_measure_write(const char *path, const struct measure_table *t);
/* Reads a table into t (rows allocated; fmt_measure_free); dies
 * "prog: file:line: what" if it is not one: no "# z cd ..." header, a
 * row with another number of fields than the header names, a field that
 * is not a number, no row, no "# cleared yes|no" line. */
void fmt_measure_read(const char *path, struct measure_table *t);
void fmt_measure_free(struct measure_table *t);

/* Writes the hole-array table atomically, with the rounding of
 * fmt_measure_write; lcdu NAN prints "-". */
void fmt_measure_write_holes(const char *path, const struct measure_hole *h, size_t n,
			     double lcdu);

#endif
