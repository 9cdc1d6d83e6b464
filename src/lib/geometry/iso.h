/*
 * iso.h - isosurfaces of a scalar on a regular 3D grid, by marching
 * tetrahedra.  Used for bleach's mxyz.solid.3D (surfaces of constant M,
 * thesis Figure 8.15) and the fast-marching engine's developed surface
 * T = t.
 *
 * Each grid cell is split into six tetrahedra around its (0,0,0)-(1,1,1)
 * diagonal (the Kuhn split); neighbouring cells then share their face
 * triangulations, so the surface has no cracks, and unlike marching cubes
 * there are no ambiguous cases.
 */
#ifndef S3D_ISO_H
#define S3D_ISO_H

typedef void (*iso_emit)(void *ctx, const double tri[9]);

/* f: nx*ny*nz values, x fastest, then y, then z, on the grid spanning
 * bounds (xmin xmax ymin ymax zmin zmax, both ends included).  Calls emit
 * for every triangle of f = level (vertices p0 p1 p2 as x y z triples),
 * oriented so that (p1-p0) x (p2-p0) points towards f > level.  A value
 * equal to level counts as above it.  With closed != 0 the region
 * f < level is also closed off by the box faces, so the surface is
 * watertight.  Degenerate (zero-area) triangles are not emitted.  Order
 * is deterministic.  Returns the number of triangles. */
long iso_surface(const double *f, int nx, int ny, int nz, const double bounds[6],
		 double level, int closed, iso_emit emit, void *ctx);

/* The same with a speed w > 0 per grid point (same layout as f) when f
 * is an arrival time: along each edge the crossing is placed as if the
 * front crossed it at a fixed angle with w linear along it (f growing
 * as the integral of 1/w), not as if f were linear.  Where the speed
 * changes several-fold within a cell (a resist's rate at the edge of an
 * image) linear interpolation puts the surface up to a fifth of a cell
 * behind the front.  A point with w <= 0 gives linear crossings on its
 * edges.  w NULL is iso_surface. */
long iso_surface_speed(const double *f, const double *w, int nx, int ny, int nz,
		       const double bounds[6], double level, int closed, iso_emit emit, void *ctx);

/* The same over the cells c0[d] <= i < c1[d] only (cell i spans grid
 * points i and i + 1; with closed, cells -1 and n - 1 are the pad's
 * layers outside the faces), in the same order as the whole grid: the
 * cells of a partition of the grid together give iso_surface_speed's
 * triangles.  A cell whose eight values all lie on one side of level is
 * skipped before its tetrahedra are split. */
long iso_surface_window(const double *f, const double *w, int nx, int ny, int nz,
			const double bounds[6], double level, int closed, const int c0[3],
			const int c1[3], iso_emit emit, void *ctx);

/* The fraction of the way from a to b at which f = level on an edge
 * whose ends have values fa, fb and speeds wa, wb, as iso_surface_speed
 * places it (linear in f where a speed is not positive). */
double iso_crossing(double fa, double wa, double fb, double wb, double level);

/* The inverse of iso_crossing: the value at fraction s of the way from a
 * to b by the same edge model (linear without speeds, else the integral
 * of 1/w), so that iso_crossing(fa, wa, fb, wb, iso_value_at(..., s)) is s
 * up to rounding. */
double iso_value_at(double fa, double wa, double fb, double wb, double s);

#endif
