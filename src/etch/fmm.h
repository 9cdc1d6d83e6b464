/*
 * fmm.h - the independent engine of etch: arrival times of the
 * development front by fast marching (Sethian, PNAS 93 (1996) 1591).
 *
 * The ray-string method of the thesis (chapter 7) moves a surface mesh;
 * where fronts converge it forms loops that must be removed (thesis
 * 7.5.3, 8.4.3).  The volumetric alternative solves, on a grid, the
 * eikonal equation
 *
 *     |grad T(x)| R(x) = 1,   T = 0 on the resist top (z = zmax),
 *
 * whose solution T is the time at which development reaches x (the
 * viscosity solution: the first arrival, so fronts that meet simply
 * stop, and there is nothing to deloop).  The developed surface at time
 * t is the isosurface T = t.  The grid is the rate grid, optionally
 * refined by an integer factor per axis.  Between rate-grid nodes the
 * rate is the smooth field the nodes sample, reconstructed along each
 * axis as linear plus the limited curvature of its neighbours (fmm.c;
 * the ray-string advance interpolates trilinearly, thesis 7.3): a
 * resist with standing waves needs several nodes per half-period in z
 * before the discretisation error falls under half a rate-grid cell.
 *
 * Units: micrometres, seconds, um/s.
 */
#ifndef S3D_FMM_H
#define S3D_FMM_H

#include "fmt_plot.h"
#include "fmt_rate.h"
#include "iso.h"

#include <stddef.h>

/* Arrival time of nodes the front never reaches (rate zero, or cut off
 * by zero-rate resist).  Finite, so that interpolation and isosurface
 * arithmetic stay finite; far beyond any etch time. */
#define FMM_UNREACHED 1e300

/* Rates below this (um/s) count as zero: at 1e-12 um/s a micrometre
 * takes 30000 years, and slownesses stay far from overflow when squared. */
#define FMM_RATE_FLOOR 1e-12

/* The largest refinement factor per axis accepted. */
enum { FMM_MAX_REFINE = 64 };

struct fmm {
	int n[3];               /* nodes of the (refined) grid per axis */
	double bounds[6];       /* xmin xmax ymin ymax zmin zmax: the rate box */
	double h[3];            /* node spacing per axis, um (0 if one node) */
	double *t;              /* arrival times, s: n[0]*n[1]*n[2], x fastest */
	double *rate;           /* the rate R per node, um/s (0 below the floor),
				 * as the solve sampled it: the surface is placed
				 * between nodes by it (iso_surface_speed) */
	long accepted;          /* nodes reached (for reports) */
	int refine[3];          /* the refinement the grid was solved with */
	struct fmm_march *march; /* a lazy solve's march so far (fmm_solve_lazy),
				  * else NULL */
	double march_s;         /* CPU seconds a lazy solve has marched */
};

/* Solves |grad T| R = 1 with T = 0 on the resist top.  refine[d] >= 1
 * (NULL: no refinement) multiplies the cells of axis d (x, y, z).
 * Between nodes the rate is the field the nodes sample, reconstructed
 * with its limited curvature (fmm.c).
 * Dies if the refined grid is too large (over 2^31 - 1 nodes). */
struct fmm *fmm_solve(const struct ratefile *r, const int refine[3]);

/* The same with the rate linear between nodes (trilinear at a refined
 * grid's nodes), as the ray-string engine interpolates it (thesis 7.3):
 * for comparisons with that engine (etch -xcheck), where the two must
 * differ by their discretisations alone, not by their rate models. */
struct fmm *fmm_solve_linear(const struct ratefile *r, const int refine[3]);

/* The same by the published scheme, the slowness taken at the node
 * being updated (Sethian & Vladimirsky): second order where R is smooth
 * on the grid scale, behind the front where it changes several-fold
 * within a cell.  An independent reference for tests (refined). */
struct fmm *fmm_solve_nodal(const struct ratefile *r, const int refine[3]);

/* The same from point sources instead of the top: T = 0 at each of the
 * npts points p (x y z triples, clamped into the box), exact
 * |x - p| / R near each point (thesis Figure 8.13's seeds). */
struct fmm *fmm_solve_points(const struct ratefile *r, const int refine[3],
			     const double *p, int npts);

/* The solve of fmm_solve_linear (npts 0) or fmm_solve_points with the
 * rate linear between nodes, marched only as far as queries need: T is
 * read by fmm_time_at_settled alone, which marches on until the nodes
 * it interpolates between are accepted.  The march is the same, node by
 * node in the same order, so every T read is the one the full solve
 * gives (deloop's classifier: a mesh's nodes need T only near the front
 * at the print times, often a small part of the grid; the rate model is
 * the ray-string's, so that the classifier sees the mesh's own front).
 * f->rate stays NULL. */
struct fmm *fmm_solve_lazy(const struct ratefile *r, const int refine[3],
			   const double *p, int npts);

/* fmm_time_at for any solve, a lazy one marched on as far as p needs
 * (its CPU time added to f->march_s). */
double fmm_time_at_settled(struct fmm *f, const double p[3]);

void fmm_free(struct fmm *f);

/* A refinement factor in z for resists with standing waves: the least
 * that brings the largest change of ln R between z neighbours under
 * FMM_AUTO_LNSTEP per refined cell, at most FMM_AUTO_MAX.  On the
 * thesis' contact (Olin Hunt 6512, no bake, 300 points) it gives 4.
 * (With the slowness integrated over the cells, fmm.c, a column alone is
 * exact on the plain grid; the refinement serves the fronts that cross
 * the standing waves obliquely.)  etch -method fmm uses it by default. */
#define FMM_AUTO_LNSTEP 0.1
enum { FMM_AUTO_MAX = 16 };
int fmm_auto_refine(const struct ratefile *r);

/* The grid cell holding p (clamped to the box): its lower corner lo and
 * p's fractions w along it (lo 0, w 0 on an axis of one node), the
 * corners and weights fmm_time_at interpolates with. */
void fmm_cell(const struct fmm *f, const double p[3], int lo[3], double w[3]);
/* T at any point, by trilinear interpolation; p is clamped into the box. */
double fmm_time_at(const struct fmm *f, const double p[3]);

/* The rate the solve used at any point, likewise (0 without f->rate). */
double fmm_rate_at(const struct fmm *f, const double p[3]);

/* Distance (um) from p to the developed surface at time t: a first-order
 * estimate |T(p) - t| / |grad T(p)|, refined by a bracketed search along
 * grad T for the crossing T = t; where p lies in developed resist above
 * the substrate, the substrate (z = zmin, where T < t) counts as surface
 * too.  Returns FMM_UNREACHED if T is flat or unreached at p. */
double fmm_distance(const struct fmm *f, const double p[3], double t);

/* fmm_distance of n points (x y z triples) into d[0..n-1], the same
 * values to the last bit, the cells the surface cuts found once for all
 * points; the points shared among the threads (par.h). */
void fmm_distance_many(const struct fmm *f, const double *p, size_t n, double t, double *d);

/* The median and 95th percentile (nearest rank) of fmm_distance over n
 * points (x y z triples), found by fmm_distance_many: the cross-check
 * statistic of etch's two engines.  n = 0 gives 0 and 0. */
void fmm_distance_stats(const struct fmm *f, const double *p, size_t n, double t,
			double *median, double *p95);

/* Emits the triangles of the developed surface at time t: the isosurface
 * T = t (marching tetrahedra, iso.h), placed between nodes by their rates
 * (iso_surface_speed, with f->rate), normals towards undeveloped resist,
 * plus the substrate where the resist is developed through (where the
 * ray-string nodes stop, thesis 7.3), but not the box's top and side
 * faces.  For t <= 0 it is the flat resist top.  Returns the count. */
long fmm_surface(const struct fmm *f, double t, iso_emit emit, void *ctx);

/* Writes one set per time: the surfaces are extracted on the rate grid
 * (every refine[d]-th node of the solution), so refinement sharpens the
 * arrival times at the rate-grid nodes without multiplying the triangles
 * written (on the thesis' contact at z x5: 83 MB and 18 s otherwise).
 * path3d in curves.plot form (plot3d(5), every
 * triangle a closed 4-point curve p1 p2 p3 p1, bounds the rate box),
 * path2d in curves.plot.2D form (the same triangles projected on x-y).
 * Either path may be NULL.  Files are committed atomically.  Unless
 * dense, each set is decimated with the bound tol, um, in tiles
 * (fmm_decimate_tile; tol < 0: fmm_default_tol), or with tol 0 only its exactly flat regions
 * are written as large triangles (fmm_compact); the sets are extracted
 * in parallel (par.h), byte-identical for any thread count.  Decimated
 * sets are extracted and decimated tile by tile (one job per set and
 * tile, only the decimated triangles kept), and a tile whose nodes all
 * developed before the previous set's time is copied from that set.  A
 * decimated set is extracted on the z levels of fmm_levels (a share of
 * tol; the decimator gets the rest). */
void fmm_write_curves(const struct fmm *f, const double *times, int ntimes,
		      const char *path3d, const char *path2d, int dense, double tol);

/* The z levels the surface at time t is extracted on for decimation
 * (fmm_levels.c): a subset of f's z nodes, the same for every column,
 * such that in the cells the surface crosses each node skipped has, by
 * the coarser grid's interpolation, a value within err um of distance
 * (|T - T'| R) of its own, and the cells' tetrahedra move it by no more
 * (their mixed differences), values after tmax clamped to it.  Returns
 * the grid on those levels, its z axis counting levels (bounds 0 ..
 * nk-1, spacing 1; fmm_free frees it), and in *zl (allocated) their z,
 * um; fmm_level_z maps a level coordinate u of its surface to z, affine
 * in each layer.  *used is the largest estimate of the levels kept, um
 * (at most err). */
struct fmm *fmm_levels(const struct fmm *f, double t, double tmax, double err, double **zl,
		       double *used);
double fmm_level_z(const double *zl, int nk, double u);

/* The share of the decimation bound that the z levels may take, and the
 * margin on their estimate: the decimator is left tol less
 * FMM_LEVEL_MARGIN times the largest estimate of the levels kept (on
 * examples/contact without bake the distances measured exceeded the
 * estimate by up to 30 %), so that the written surface stays within tol
 * of the one extracted on every node.  The larger share is taken where it
 * keeps at most a third of the z nodes (the smooth walls of a baked
 * resist, whose slivers it removes), the smaller elsewhere (standing
 * waves keep most levels, and the decimator needs the tol), if that
 * keeps at most a third; else the set is extracted on every node with
 * the whole tol for the decimator. */
#define FMM_LEVEL_FRACTION 0.5
#define FMM_LEVEL_FRACTION_LOW 0.25
#define FMM_LEVEL_MARGIN 1.5

/* The default decimation bound of fmm_write_curves (tol < 0, FMM_TOL_AUTO):
 * FMM_TOL_FRACTION of the rate grid's finer x-y spacing, um. */
#define FMM_TOL_AUTO (-1.0)
#define FMM_TOL_FRACTION 0.02
double fmm_default_tol(const struct fmm *f);

/* Each set is decimated in x-y tiles of at most FMM_TILE_CELLS rate-grid
 * cells a side (in parallel, and in memory bounded by the tile; the
 * vertices on the seams stay): examples/contact (50 cells) is one tile,
 * a 20 um window at 0.05 um 16. */
enum { FMM_TILE_CELLS = 128 };

/* Decimates the triangles of one tile of a set welded in w (tri_weld.h,
 * with the distance fmm_weld_eps) with the bound tol (um), the vertices
 * kept on the box faces as the grid f places them, and those on the
 * planes keep (x0 x1 y0 y1; infinite: none) kept: the triangles kept go
 * to *out (tri_decimate.h, its arrays allocated), w is emptied.  A tile
 * whose decimated triangles cross themselves is decimated again at a
 * quarter of tol, and written as extracted if that crosses too.  Returns
 * the count. */
struct tri_weld;
struct tri_mesh;
double fmm_weld_eps(const struct fmm *f);
size_t fmm_decimate_tile(const struct fmm *f, struct tri_weld *w, double tol, const double keep[4],
			 struct tri_mesh *out);

/* Replaces, in the n triangles *v (9 doubles each, *cap allocated, as
 * xgrow), every rectangle of grid columns whose surface is one exactly
 * horizontal plane by a fan of large triangles over the same vertices on
 * its perimeter (no T-junctions; same area and volume); the other
 * triangles keep their order.  Returns the new count.  See fmm_compact.c. */
size_t fmm_compact(const struct fmm *f, double **v, size_t n, size_t *cap);

/* Appends to pf (dim 2) one set, with the given bounds (4 values), of the
 * profile where the plane x = value (axis 0) or y = value (axis 1) cuts
 * the developed surface at time t: polylines of (y, z) or (x, z), open
 * chains first then closed loops, as etch's curves.cut (ray_output.c).  The
 * substrate where T < t is part of the profile, as in fmm_surface; for
 * t <= 0 it is the resist top. */
void fmm_cut(const struct fmm *f, double t, int axis, double value,
	     struct plot_file *pf, const double bounds[4]);

#endif
