/*
 * poly.h - plane polygon geometry for masks: signed area, the simplicity
 * check, clipping to a rectangle, outlines of GDSII paths, point in
 * polygon, and the painted union of polygon layers as a list of boundary
 * pieces (the slab sweep behind the exact mask transform of splat).
 *
 * A polygon is n vertices x0 y0 x1 y1 ... (closed implicitly, either
 * orientation).  A set holds many polygons in one vertex array.
 */
#ifndef S3D_POLY_H
#define S3D_POLY_H

#include <stddef.h>

struct poly_set {
	int n;                  /* polygons */
	int *start;             /* n + 1 offsets into xy, in vertices */
	double *xy;             /* vertices, 2 doubles each */
	size_t cap_p, cap_v;
};

/* Appends a copy of polygon xy (nv vertices). */
void poly_set_add(struct poly_set *s, const double *xy, int nv);
void poly_set_free(struct poly_set *s);     /* frees the arrays, zeroes *s */
/* Vertex count and first vertex of polygon i. */
static inline int poly_set_nv(const struct poly_set *s, int i)
{
	return s->start[i + 1] - s->start[i];
}
static inline const double *poly_set_xy(const struct poly_set *s, int i)
{
	return s->xy + 2 * (size_t)s->start[i];
}

/* Signed area (counter-clockwise positive). */
double poly_area(const double *xy, int n);

/* 1 if the polygon is simple: no edge meets a non-adjacent edge, adjacent
 * edges meet only at their common vertex, and the area is not zero.
 * Otherwise 0, with the offending edges (edge i runs from vertex i to
 * vertex i+1) in *ei, *ej (equal for a zero area). */
int poly_simple(const double *xy, int n, int *ei, int *ej);

/* Removes repeated consecutive vertices (and a last vertex equal to the
 * first) in place; returns the new count. */
int poly_dedup(double *xy, int n);

/* Sutherland-Hodgman clip of a polygon to the rectangle [x0,x1]x[y0,y1]
 * (exact for a convex clip region; a concave polygon may come back with
 * zero-width bridges along the border, harmless to the sweep).  Writes a
 * malloc'd polygon to *out and returns its vertex count, 0 if nothing is
 * left (then *out is NULL). */
int poly_clip_rect(const double *xy, int n, double x0, double x1, double y0,
		   double y1, double **out);

/* Nonzero winding number of (x, y) about the polygon (points on the
 * boundary may go either way). */
int poly_winding(const double *xy, int n, double x, double y);

/* The outline of a path of centre line xy (n points), as polygons added
 * to out whose union is the path: one rectangle per segment of half-width
 * hw and one mitre wedge per bend (a 90-degree bend gets a square outer
 * corner), the start extended by ext0 and the end by ext1 along the path
 * (negative shortens).  round_tol > 0 adds round caps (circles of radius
 * hw at both ends: regular polygons of the circle's area whose outline
 * stays within round_tol of it).  Repeated points are skipped. */
void poly_path(struct poly_set *out, const double *xy, int n, double hw,
	       double ext0, double ext1, double round_tol);

/* Sides of an inscribed regular polygon approximating a circle of radius
 * r with sagitta at most tol (at least 8, at most 4096). */
int poly_circle_sides(double r, double tol);

/* The painted union of layers: layer k covers the union of its polygons
 * (each taken with its own orientation made positive, so overlaps count
 * once and keyhole polygons keep their holes); a point takes the highest
 * layer covering it, or -1.  The sweep cuts the plane into horizontal
 * slabs at every vertex and crossing; in a slab, each place where the
 * top layer changes along x is one piece: the segment from (x0, y0) to
 * (x1, y1), y0 < y1, with the top layer left and right of it.  Vertical
 * pieces of consecutive slabs are merged.  Horizontal edges make no
 * piece, and identical edges are grouped, so the result does not depend
 * on the order of the polygons.  Returns the piece count; *out is
 * malloc'd (NULL if none). */
struct poly_piece {
	double x0, y0, x1, y1;
	int left, right;
};
size_t poly_boundary(const struct poly_set *layers, int nlayers, struct poly_piece **out);

#endif
