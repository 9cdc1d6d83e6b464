/*
 * etch.h - etch, 3D development of a resist (thesis chapters 7 and 8):
 * the options and statistics every engine shares, and the engines' entry
 * points.  main.c parses the options and dispatches to one engine; each
 * engine's files carry its prefix:
 *
 *   ray_*.c      the ray-string engine (thesis 8.3): ray_start.c (initial
 *                surface), ray_advance.c (ray advance), ray_modify.c
 *                (cutting and merging), ray_clip.c (clipping), ray_output.c
 *                (plot files) and ray_run.c (the time loop of thesis 8.3),
 *                over the mesh of mesh.c
 *   deloop*.c    delooping the ray-string mesh (thesis 8.4.3; deloop.h)
 *   fmm*.c       the fast-marching engine (fmm.h), run by fmm_run.c
 *   cell_methods.c  the thesis' cell methods in 3D
 *
 * and beside them xcheck.c (the ray-string surface against fast
 * marching) and estimate.c (the cost of a run before it starts).
 */
#ifndef ETCH_ETCH_H
#define ETCH_ETCH_H

#include "fmt_rate.h"
#include "mesh.h"
#include "rfield.h"

/* Defaults (thesis values where the thesis gives one). */
#define ETCH_SMAX 1.2           /* S_max / S_ideal, thesis 7.5.1.1 and 8.4.1.3 */
#define ETCH_SMIN 0.2           /* S_min / S_ideal, thesis 8.4.1.2, Figure 8.7b */
#define ETCH_RL 0.1             /* recursive length, thesis 7.4.2 (about 4 degrees) */
#define ETCH_CLIP 10            /* clip every 10 steps, thesis 8.4.2 footnote */
#define ETCH_SEG_DIVISIONS 30   /* default S_ideal: the larger side of the box / 30
                                 * (the thesis' 2D runs used 30-100 segments) */
/* Default time step: the fraction of 1 / max|grad R| (thesis [7.4]) used.
 * [7.4] only keeps the rays from reflecting; a quarter of it keeps the
 * front within 1e-3 of the exact depth on 10:1 standing waves with the
 * fourth-order advance (tests/etch/040-zonly.sh). */
#define ETCH_DT_GRAD 0.25
/* The mesh is bounded by design: beyond ETCH_MESH_FACTOR times the
 * triangles of equilateral S_ideal triangles covering the box's six
 * faces, no segment is cut (a rate spike would otherwise grow the mesh
 * exponentially: 2.7 GB in 75 s from a 2x2x2 rate file). */
#define ETCH_MESH_FACTOR 4

enum method { METHOD_RAY, METHOD_FMM, METHOD_CELL, METHOD_HUYGENS };

/* Seed points accepted (-seed repeated; thesis Figure 8.13 uses two). */
enum { ETCH_MAX_SEEDS = 16 };

struct ratefile;

struct etch_opts {
	double et, pt, dt;      /* s; pt <= 0: only the end; dt <= 0: default */
	double seg;             /* S_ideal, um; <= 0: default */
	double smax, smin;      /* ratios to S_ideal */
	double rl;              /* recursive length */
	int linear;             /* linear instead of arc interpolation */
	int euler;              /* the thesis' first-order step [6.7] + [A.33] */
	long clip_every;
	int deloop;             /* deloop at every print time (thesis 8.4.3) */
	long deloop_every;      /* > 0: also every this many steps */
	const struct ratefile *rate;    /* the rate array, for deloop's classifier */
	int check;              /* run mesh_check after every step */
	int quiet;
	int seed;               /* number of seed points; 0: the resist top */
	double seedp[ETCH_MAX_SEEDS][3];
	int cut_axis;           /* -1 none, 0 x, 1 y */
	double cut_value;
	int cut_mid;            /* -cut x|y mid: the box's middle */
	enum method method;
	int refine[3];          /* -method fmm: cell subdivisions in x, y, z */
	int refine_auto;        /* -refine auto: z factor from the rate array */
	int xcheck;             /* report the distance to the fast-marching surface */
	const char *out3d, *out2d, *outcut;
	const char *outvtk;     /* -vtk: VTK XML PolyData, or NULL */
	int no2d;               /* -no2d: no curves.plot.2D */
	int last;               /* -last: only the final set is written */
	int dense;              /* -dense: fmm surfaces uncompacted */
	double tol;             /* -tol: fmm decimation bound, um (< 0: default) */
	int dryrun;             /* -n: check the command line only */
	int print_times;        /* -print-times: print the print times only */
	const char *input;
};

struct etch_stats {
	double dt;              /* step used, s */
	double dt_grad;         /* 1 / max|grad R| (s), 0 if the rate is uniform */
	double seg;             /* S_ideal used, um */
	long steps, substeps, halvings;
	long cuts, merges, refused, clips, clipped_tris, stopped;
	long max_nodes, max_tris;
	long capped;            /* cuts not made: the mesh at its bound */
	long max_live_tri;      /* that bound, triangles (ray_run.c) */
	long deloops, loops, looped_tris, crossings_left;   /* deloop.c */
	double deloop_s;        /* processor time spent delooping, s */
	double deloop_fmm_s;    /* of which building the classifier, s */
	long seam_joined;       /* seam segments joined (deloop_zip.c) */
	double open_cut, open_left;     /* open border (um) after the cuts of the
					 * last deloop, before joining, and after */
	double open_worst;      /* the most open border (um) of a set written */
};

/* cell_methods.c: -method cell and huygens, the thesis' cell methods in 3D
 * (3.6, 4.3); writes curves.plot and curves.plot.2D itself. */
void etch_run_cells(const struct rfield *f, const struct etch_opts *o);

/* ray_start.c: the flat resist top (a regular triangulation of z = zmax with
 * segments of length seg, rays (0, 0, -1)) or a seed point. */
void start_flat(struct mesh *m, const struct rfield *f, double seg);
void start_seed(struct mesh *m, const double p[3]);

/* ray_advance.c: moves every node by dt along its ray (thesis 8.3 [I]). */
void advance_mesh(struct mesh *m, const struct rfield *f, double dt,
		  const struct etch_opts *o, struct etch_stats *st);

/* ray_modify.c: the triangle-based mesh modification of thesis 8.4.1.3. */
void modify_mesh(struct mesh *m, const struct rfield *f, double seg,
		 const struct etch_opts *o, struct etch_stats *st);
/* The new node between nodes a and b: on the arc their rays define
 * (thesis Figure 7.6b) or, if linear, on the chord; its ray interpolated. */
void interp_node(const struct node *a, const struct node *b, int linear,
		 double p[3], double r[3]);

/* ray_clip.c: clipping against the six faces of the box (thesis 8.4.2). */
void clip_mesh(struct mesh *m, const struct rfield *f, struct etch_stats *st);

/* deloop.c: delooping (thesis 8.4.3); see deloop.h. */

/* ray_output.c */
struct etch_out;
struct etch_out *out_open(const struct etch_opts *o, const struct rfield *f);
void out_write(struct etch_out *w, const struct mesh *m);
void out_close(struct etch_out *w);
/* The profile where the plane (axis = value) cuts the mesh, as polylines
 * of (other horizontal coordinate, z) points; for tests too. */
struct plot_file;
void out_cut(const struct mesh *m, int axis, double value, struct plot_file *pf,
	     const double *bounds);

/* ray_run.c: the whole simulation; returns the final mesh. */
struct mesh *etch_run(const struct rfield *f, const struct etch_opts *o,
		      struct etch_stats *st);
/* The default time step and ideal segment length for f (thesis 7.4.1). */
double etch_default_dt(const struct rfield *f, double seg, double et);
double etch_default_seg(const struct rfield *f);

/* ray_run.c: the summary of a ray-string run on stderr (sizes, counts,
 * delooping). */
void etch_report(const struct etch_opts *o, const struct rfield *f,
		 const struct mesh *m, const struct etch_stats *st);

/* fmm_run.c: -method fmm, the fast-marching engine (fmm.h): arrival
 * times on the (refined) rate grid, isosurfaces at the print times, and
 * the same curves.cut as the ray-string engine.  Frees r's arrays once
 * the solve has its own rates (r and f's values are not to be read after). */
void etch_run_fmm(struct ratefile *r, const struct rfield *f, const struct etch_opts *o);
/* The refinement asked for with -refine, or its auto choice. */
void etch_fmm_refinement(const struct ratefile *r, const struct etch_opts *o, int refine[3]);

/* xcheck.c: -xcheck, after a ray-string run, the distances of its nodes
 * from the fast-marching surface at each print time, on stderr. */
void etch_xcheck(const struct ratefile *r, struct etch_opts *o);

/* estimate.c: the run's seconds and bytes, from the input alone, through
 * budget_check (dies if over the limits without -big). */
void etch_estimate(const struct ratefile *r, const struct rfield *f,
		   const struct etch_opts *o);

#endif
