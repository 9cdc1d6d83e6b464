/*
 * tri_decimate.h - surface decimation with a stated error bound: a
 * triangle soup (9 doubles per triangle, as iso.h emits them) is welded
 * into a mesh and simplified by half-edge collapses (a vertex moved onto
 * a neighbour) in order of a quadric error (Garland & Heckbert, SIGGRAPH
 * 1997, unweighted plane sums).  Every output vertex is an input vertex,
 * and each lies within tol / sqrt(2) of the plane of every input
 * triangle it absorbed (the sum of its squared distances to those
 * planes, and to the planes through boundary edges normal to their
 * triangle, is at most tol^2 / 2).  Topology is kept (link condition),
 * no triangle flips, none is made thinner than TRI_DECIMATE_QMIN unless
 * it got fatter, and a vertex on a face of the given box only moves
 * within that face (or edge of the box; corners stay), so a boundary on
 * the box stays on it.
 * Each collapse is also checked against the input: every input vertex
 * stays within tol of the output (each is tracked to the triangle that
 * took it over), and so do the points of the output triangles on the
 * barycentric grid of step 1/TRI_DECIMATE_SAMPLES (against the input
 * triangles around them; a sampled check).  Deterministic: ties broken
 * by cost, then vertex index.
 */
#ifndef S3D_TRI_DECIMATE_H
#define S3D_TRI_DECIMATE_H

#include <stddef.h>

/* The least quality 4 sqrt(3) area / (sum of squared edge lengths) (1 for
 * an equilateral triangle) a collapse may create, unless the triangle it
 * replaces was thinner still: a grid 40 times finer in z than in x (the
 * fast-marching walls) makes triangles of quality 0.04. */
#define TRI_DECIMATE_QMIN 0.1

/* The written triangles are checked within tol of the input triangles
 * at the points of their barycentric grid of this step's inverse (1/4:
 * 12 points besides the corners). */
#define TRI_DECIMATE_SAMPLES 4

struct tri_decimate_stats {
	size_t vertices;        /* after welding */
	size_t in, out;         /* triangles (in: after welding drops degenerate ones) */
	size_t boundary_edges;  /* edges of one triangle */
	size_t locked;          /* vertices on a non-manifold edge or a crack off the box */
};

/* Decimates the n triangles in v (9 doubles each) in place and returns
 * the new count (at most n).  Vertices closer than weld (um; per
 * coordinate) are one vertex; box (xmin xmax ymin ymax zmin zmax, NULL:
 * none) with box_eps the distance within which a vertex is on a face.
 * Vertices on the planes x = keep[0], x = keep[1], y = keep[2] or y =
 * keep[3] (within box_eps; keep NULL: none) stay where they are and take
 * in no other: a surface cut into tiles along such planes and decimated
 * tile by tile joins up again.  tol <= 0 only welds and drops the
 * triangles that welding makes degenerate.  Triangles keep their
 * orientation and their relative order.  st may be NULL. */
size_t tri_decimate(double *v, size_t n, double tol, double weld, const double box[6],
		    double box_eps, const double keep[4], struct tri_decimate_stats *st);

/* A decimated surface as vertices and triangles, a third of its soup's
 * memory: the vertices the triangles use, in the order of first use. */
struct tri_mesh {
	double *p;              /* 3 per vertex */
	int *tv;                /* 3 vertex numbers per triangle */
	size_t nv, nt;
};
void tri_mesh_free(struct tri_mesh *m);

/* The same on the triangles welded so far by w (tri_weld.h; its weld
 * distance is the welding's), so that their soup is never held: the
 * kept triangles, as tri_decimate keeps them, go to *out (its arrays
 * allocated, the caller's to free), the count is returned, and w is
 * empty again. */
struct tri_weld;
size_t tri_decimate_welded(struct tri_weld *w, double tol, const double box[6], double box_eps,
			   const double keep[4], struct tri_decimate_stats *st, struct tri_mesh *out);
/* The same on a copy of a welded mesh (in is left as it is), for a
 * caller that may decimate it again with another bound. */
size_t tri_decimate_mesh(const struct tri_mesh *in, double tol, const double box[6], double box_eps,
			 const double keep[4], struct tri_decimate_stats *st, struct tri_mesh *out);

#endif
