/*
 * etch2d.h - 2D development of a resist cross-section (a rate array with
 * ny = 1) by the five etching algorithms the thesis compared (chapters
 * 3, 4, 6 and 7, Table 10.1) and a fast-marching reference:
 *
 *   cell.c       Dill's cell removal (3.2), fastest boundary cell first
 *   huygens.c    the modified (Huygens) cell method (4.3), constant step
 *   string.c     the string (6.2): nodes along the bisector normal
 *   ray.c        the ray (6.3): independent rays, joined in order
 *   raystring.c  the ray-string (7.3-7.5): rays joined by a cut, merged,
 *                clipped, flattened and delooped string
 *   fmm2d.c      second-order fast marching on a node grid: the reference
 *   front.c      what the surface methods share (strings of nodes: the ray
 *                advance, clipping, delooping, cutting and merging)
 *   profile.c    polylines from segments (staircases of cells, contours
 *                of arrival times), print times, the plot sets
 *
 * Coordinates: x across, z up, z = zmax the resist top, zmin the
 * substrate; um, s, um/s.  The rate is the library's rfield (bilinear in
 * x-z for a 2D array) at y = ymin.
 */
#ifndef ETCH2D_H
#define ETCH2D_H

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

/* Methods: each runs to e->o.et and emits one set per print time. */
void run_cell(struct e2 *e);
void run_huygens(struct e2 *e);
void run_string(struct e2 *e);
void run_ray(struct e2 *e);
void run_raystring(struct e2 *e);
void run_fmm(struct e2 *e);

/* Runs the method of e->o (fills e->pf and e->st). */
void e2_run(struct e2 *e);
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

/* Dies if et / dt steps is more than a run may take. */
void e2_check_steps(const struct e2 *e, double dt);
/* Default cell counts: cells[] from o, else 200 along the longer side. */
void e2_cells(const struct e2 *e, int *nx, int *nz);

/* front.c: strings of nodes for the surface methods */
enum { ON_LEFT = 1, ON_RIGHT = 2, ON_TOP = 4, END = 16 };
struct fnode {
	double p[2], s[2];      /* position; unit direction (rays) */
	unsigned flags;
};
struct front {
	size_t n, cap;
	struct fnode *v;        /* in order, left end to right end; the
				 * material on the right of the walk */
};
void front_push(struct front *fr, double x, double z, double sx, double sz, unsigned flags);
/* Wall flags of a node from its position. */
unsigned front_walls(const struct e2 *e, const double p[2]);
/* Boundary flattening (7.5.2.2): a node on a side wall whose direction
 * points into the resist loses the normal component; an end of the string
 * on the top (from a seed) keeps only its component along the top.  0 if
 * nothing is left. */
int front_flatten(const struct e2 *e, unsigned flags, double s[2]);
/* Advances one node by dt along its ray (ray equation, recursive vector
 * checking with length rl, flattening at the walls).  The substrate is a
 * wall too, handled as the bottom face's rate continued below it (R(x,
 * zmin), dR/dz = 0: any path below has its projection onto the substrate
 * as fast), so nodes go on below it and front_emit draws the cleared
 * substrate where the string runs under it. */
void front_advance_ray(struct e2 *e, struct fnode *n, double dt, int depth);
/* Cuts the string where it leaves the box through a side wall (and the top
 * when seeded), 7.5.2.1. */
void front_clip(struct e2 *e, struct front *fr);
/* Cuts segments longer than smax (arc: on the arc the end directions
 * define, 7.5.1.1; else linear) and merges those shorter than smin. */
void front_remesh(struct e2 *e, struct front *fr, double smax, double smin, int arc);
/* 2D delooping (7.5.3.3): removes the loops of the string; returns how
 * many. */
long front_deloop(struct e2 *e, struct front *fr);
/* 1 if segments p1-p2 and q1-q2 cross properly (not at their ends, not
 * parallel), with the crossing's parameter *u along p (front.c). */
int e2_crossing(const double *p1, const double *p2, const double *q1, const double *q2,
		double *u);
void front_emit(struct e2 *e, const struct front *fr);
/* Marks the first and last nodes END (and no other). */
void front_ends(struct e2 *e, struct front *fr);
/* The start: from the resist top, nodes spaced at most seg along it
 * pointing down; from a seed (on the top), nseed nodes at the seed with
 * directions spread evenly over the half circle below the top, the
 * first and last along the top; from a -start profile,
 * front_start_profile with fans of rays pi / (nseed - 1) apart. */
void front_start(struct e2 *e, struct front *fr, double seg, long nseed);
/* Default node spacing (width / 50, the thesis' 50 segments) and step. */
/* The start from a -start profile: a node at each vertex and at most seg
 * apart between, pointing along the normal into the resist (the bisector
 * at a vertex); at a diverging corner (the profile turning away from the
 * resist) with fan > 0 a fan of nodes at the vertex whose directions turn
 * from the one face's normal to the other's at most fan radians apart. */
void front_start_profile(struct e2 *e, struct front *fr, double seg, double fan);
double front_seg(const struct e2 *e);
double front_dt(const struct e2 *e);
void front_free(struct front *fr);

#endif
