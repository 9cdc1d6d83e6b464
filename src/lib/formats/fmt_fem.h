/*
 * fmt_fem.h - the tables of a focus-exposure matrix (fem(1)):
 *
 *   fem.dat (fem(5)): one row per (focus, dose) point, focus outer and
 *   dose inner, both ascending, under one header line naming the columns:
 *
 *     # focus dose cd swa cleared resist_loss
 *     -0.3 70 0.912 86.1 1 0.012
 *
 *   swa and resist_loss may be "-" (measure did not report them);
 *   cleared is 1 or 0.
 *
 *   window.dat (fem(5)): the exposure-latitude / depth-of-focus curve,
 *
 *     # el dof focus_centre dose_centre
 *
 * A point's result enters fem.dat from measure(1)'s table (fmt_measure.h):
 * its first row, "# swa", "# resist_loss" and "# cleared".
 */
#ifndef S3D_FMT_FEM_H
#define S3D_FMT_FEM_H

/* The most rows a fem.dat may hold (a 1000 x 1000 matrix). */
enum { FEM_MAX_POINTS = 1000000 };

struct fem_point {
	double focus;   /* um, defocus of the resist top (splat -defocus) */
	double dose;    /* mJ/cm2 */
	double cd;      /* um, at measure's first height */
	double swa;     /* degrees; NAN if absent */
	int cleared;    /* 1 if the opening reached the substrate */
	double loss;    /* um, resist loss; NAN if absent */
};

struct fem_table {
	int n;
	struct fem_point *p;
};

/* Reads fem.dat; dies "prog: file:line: what" on a wrong header, a
 * malformed row, or rows out of (focus, dose) order or repeated. */
struct fem_table *fmt_fem_read(const char *path);
/* Writes t (rows must be in order; dies otherwise), atomically. */
void fmt_fem_write(const char *path, const struct fem_table *t);
void fmt_fem_free(struct fem_table *t);

/* Measured CDs (calib(1) -data, fem(5)): rows "focus dose cd", further
 * fields ignored (so a fem.dat is one), '#' lines and blank lines
 * skipped, any order, each (focus, dose) once, dose and cd positive.
 * Only focus, dose and cd are set (cleared 1, swa and loss NAN). */
struct fem_table *fmt_fem_read_cds(const char *path);

/* One row of window.dat. */
struct fem_window_row {
	double el;      /* exposure latitude, % of the centre dose */
	double dof;     /* um */
	double focus;   /* um, centre of the rectangle */
	double dose;    /* mJ/cm2, centre of the rectangle */
};
void fmt_fem_window_write(const char *path, const struct fem_window_row *r, int n);

/* One row of stoch.dat (fem(5); fem -seeds): a point's seeds,
 *
 *     # focus dose cd cd_3sigma failures seeds
 *
 * cd the mean over the seeds that printed, cd_3sigma three of their
 * sample standard deviations (0 with fewer than two), failures the seeds
 * where the feature was absent (cd 0) or did not clear, seeds the seeds
 * with a result. */
struct fem_stoch_row {
	double focus, dose, cd, cd3s;
	int failures, seeds;
};
void fmt_fem_stoch_write(const char *path, const struct fem_stoch_row *r, int n);

#endif
