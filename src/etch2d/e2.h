/*
 * e2.h - what every etch2d algorithm shares, below them all: the options
 * and statistics, the box and rate of the 2D array (e2_rate), the print
 * times and limits (common.c), the -start profile (start.c) and the
 * output of plot sets (profile.c).  Nothing here calls an algorithm.
 *
 * Coordinates: x across, z up, z = zmax the resist top, zmin the
 * substrate; um, s, um/s.  The rate is the library's rfield (bilinear in
 * x-z for a 2D array) at y = ymin.
 */
#ifndef ETCH2D_E2_H
#define ETCH2D_E2_H

#include "fmt_plot.h"
#include "fmt_rate.h"
#include "rfield.h"

#include <stddef.h>

enum method { M_RAYSTRING, M_STRING, M_RAY, M_CELL, M_HUYGENS, M_FMM };

struct e2opts {
	double et, pt;          /* etch time, print interval (0: end only) */
	int method;
	int seeded;
	double seed[2];         /* x, z */
	long cells[2];          /* nx, nz; 0: default */
	double seg;             /* node or ray spacing, um; 0: default */
	double dt;              /* time step, s; 0: default */
	double rl;              /* recursive length of vector checking */
	const double *start;    /* -start: nstart points x z, the profile at
				 * t = 0 (NULL: the flat top or the seed) */
	int nstart;
	const char *startfile;  /* its file, for messages */
	int stats;
	const char *out, *input;
};

struct e2stats {
	double cpu;             /* s */
	size_t bytes;           /* peak bytes of the method's own data */
	long items;             /* peak nodes, rays or boundary cells */
	long total;             /* cells in the grid (cell methods), else 0 */
	long steps;             /* steps (cell removals for cell) */
	long loops;             /* loops removed */
};

struct e2 {
	const struct rfield *f;
	double x0, x1, z0, z1, y;   /* the box, and the row's y */
	struct e2opts o;
	double *tp;             /* print times, ascending, the last = et */
	int ntp;
	struct plot_file *pf;   /* one set per print time */
	struct plot_set *set;   /* the set being filled */
	double *sp;             /* the start profile (nsp points, left to
				 * right), or NULL */
	int nsp;
	struct e2stats st;
};

/* R (um/s) at (x, z), and dR/dx, dR/dz in g (if not NULL). */
double e2_rate(const struct e2 *e, double x, double z, double g[2]);

/* Sets up e over f (print times from o), and sets f->flat_outside (the
 * substrate seen as its face's rate continued below); e2_free releases
 * what e holds (not f). */
void e2_init(struct e2 *e, struct rfield *f, const struct e2opts *o);
void e2_free(struct e2 *e);

/* start.c: the start profile of -start.  e2_start_init checks and orders
 * o.start into e->sp (dies on a bad one); e2_start_etched: 1 if (x, z) is
 * above the profile (etched at t = 0); e2_start_dist: the distance to it,
 * and the nearest point in foot (if not NULL). */
void e2_start_init(struct e2 *e);
int e2_start_etched(const struct e2 *e, double x, double z);
double e2_start_dist(const struct e2 *e, double x, double z, double foot[2]);

/* profile.c: the output */
void e2_begin_set(struct e2 *e);
void e2_curve(struct e2 *e, int n, const double *xz);
/* Segments keyed by integer end points, chained into polylines and
 * emitted as curves of the current set.  Ends with equal keys are one
 * point (keys make the chaining exact, not a matter of float equality). */
struct segsoup {
	size_t n, cap;
	struct seg { long ka, kb; double a[2], b[2]; } *s;
};
void soup_add(struct segsoup *sp, long ka, const double a[2], long kb, const double b[2]);
void soup_emit(struct e2 *e, struct segsoup *sp);
void soup_free(struct segsoup *sp);

/* The etched cells' boundary (cell methods): etched[k * nx + i], k = 0 the
 * bottom row; open_top: the developer stands above the top row. */
void cells_emit(struct e2 *e, const unsigned char *etched, int nx, int nz, int open_top);
/* The contour T = t of node values T[k * nx + i] (fmm). */
void contour_emit(struct e2 *e, const double *T, int nx, int nz, double t);

/* 1 if segments p1-p2 and q1-q2 cross properly (not at their ends, not
 * parallel), with the crossing's parameter *u along p (start.c: the
 * start profile's check and 2D delooping use it). */
int e2_crossing(const double *p1, const double *p2, const double *q1, const double *q2,
		double *u);
/* Dies if et / dt steps is more than a run may take. */
void e2_check_steps(const struct e2 *e, double dt);
/* Default cell counts: cells[] from o, else 200 along the longer side. */
void e2_cells(const struct e2 *e, int *nx, int *nz);

#endif
