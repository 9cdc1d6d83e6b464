/*
 * surf.h - a developed resist surface as a soup of triangles, and the
 * geometry metrology needs from it: which side of the surface a point lies
 * on, horizontal sections, vertical profiles, and crossings of the
 * surface with itself.
 *
 * The surface is what etch(1) writes (plot3d(5), one set per print time):
 * triangles with no required order, orientation or connectivity.  It
 * covers the box in x-y, with the remaining resist below it and developed
 * resist above.  A point is resist when a vertical ray from it upwards
 * crosses the surface an odd number of times; that rule needs no
 * connectivity and measures undercut and re-entrant walls right.
 *
 * Vertices "above" a height z0 are those with z >= z0 (everywhere: the
 * section, the ray test), so a section through a vertex or along a flat
 * face is consistent: the plane is taken infinitesimally below z0.
 * Points on a shared edge are counted for exactly one of its triangles
 * (half-open crossing rules, shared edges evaluated in one canonical
 * order so both triangles compute the same bits).
 */
#ifndef S3D_SURF_H
#define S3D_SURF_H

#include <stddef.h>

struct surf {
	size_t ntri;
	double *v;          /* 9 numbers per triangle: x y z of each vertex */
	size_t cap;
	double box[6];      /* xmin xmax ymin ymax zmin zmax */
	/* the x-y grid of the vertical-ray test (surf_index) */
	int gnx, gny;
	double gx0, gy0, ghx, ghy;
	size_t *gstart;     /* gnx*gny + 1 offsets into gtri */
	unsigned *gtri;
};

/* An empty surface in the box (6 numbers). */
struct surf *surf_new(const double *box);
void surf_add(struct surf *s, const double *tri9);
void surf_free(struct surf *s);

/* Builds the x-y grid used by surf_above (call after the last surf_add). */
void surf_index(struct surf *s);
/* The number of times the vertical ray from (x, y, z) upwards crosses the
 * surface: odd means the point is in resist. */
int surf_above(const struct surf *s, double x, double y, double z);

/* Horizontal section: the segments where the plane z = z0 cuts the
 * triangles (2D points x y, 4 numbers per segment). */
struct surf_section {
	double z;
	size_t nseg;
	double *seg;
};
void surf_section(const struct surf *s, double z, struct surf_section *sec);
void surf_section_free(struct surf_section *sec);

/* One stretch of a line in a section, between two crossings of the
 * section's curves, and which side it is on. */
struct surf_span {
	double lo, hi;
	int resist;         /* 1 resist, 0 developed */
};
/* The spans of the line in the section along axis (0: parallel to x,
 * through y = c; 1: parallel to y, through x = c), from the box edge lo
 * to hi, adjacent spans of one kind merged.  Returns the count; *spans is
 * reallocated (capacity *cap). */
size_t surf_line_spans(const struct surf *s, const struct surf_section *sec,
		       int axis, double c, struct surf_span **spans, size_t *cap);
/* The span of the line containing t (the coordinate along the line);
 * t must lie in the box. */
struct surf_span surf_span_at(const struct surf *s, const struct surf_section *sec,
			      int axis, double c, double t);

/* About how many triangle tests surf_region_area(s, sec, .., h, ..)
 * makes: its lines and their cuts (*stretches, each a span it may hold),
 * NSAMPLE ray tests each, every test looking at the triangles of one cell
 * of the index.  For an estimate before it (a self-crossing surface
 * measured anyway has cuts on every line). */
double surf_region_tests(const struct surf *s, const struct surf_section *sec, double h,
			 double *stretches);
/* The developed region of the section that contains (x, y): its area
 * (um2), from spans on lines parallel to x every h um (one of them
 * through y), joined where they overlap on neighbouring lines.  0 if
 * (x, y) is in resist.  *edge is set when the region touches the box
 * edge (its area is cut there). */
double surf_region_area(const struct surf *s, const struct surf_section *sec,
			double x, double y, double h, int *edge);
/* The same region with its x-y bounding box (the bands of its lines). */
struct surf_region_box {
	double area;        /* um2 */
	int edge;           /* touches the box edge */
	double bbox[4];     /* xmin xmax ymin ymax; (x, y) alone if in resist */
};
void surf_region_box(const struct surf *s, const struct surf_section *sec,
		     double x, double y, double h, struct surf_region_box *rg);

/* The highest point of the surface on the vertical plane through the
 * line (axis, c as above), over the stretch lo..hi along it: the top of
 * the resist there (the box bottom if nothing is found). */
double surf_top_along(const struct surf *s, int axis, double c, double lo, double hi);

/* Crossings: an edge of one triangle passing through the inside of another
 * that shares no vertex with it (a loop left in the mesh).  Counts them,
 * stopping at max; uses a uniform grid, time proportional to the size of
 * the surface. */
long surf_crossings(const struct surf *s, long max);

/* The open border: the edges that only one triangle has, other than on
 * the faces of the box (the gaps of the surface), 6 numbers each (its two
 * ends x y z), in an order that depends on the surface alone. */
struct surf_border {
	size_t n;
	double *e;
	double length;      /* their total length, um */
	double median_edge; /* the median length of the triangles' edges, um */
};
void surf_border_find(const struct surf *s, struct surf_border *b);
void surf_border_free(struct surf_border *b);
/* The total length (um) of the open border. */
double surf_open_border(const struct surf *s);

/* The gaps of a horizontal section.  Where the plane z cuts the surface,
 * the open edges that cross it (one end at or above z, the other below,
 * as surf_section takes a vertex on the plane) are free ends of the
 * section's curves; each free end and the free end nearest to it bound a
 * gap, the stretch of curve the surface is missing, taken as the straight
 * chord between them (a point, for a free end alone in the plane).  The
 * open edges above the plane are gaps of the section too, seen from
 * above: the vertical-ray test of a point of the section counts the
 * surface above it, and a ray through a hole in the surface counts wrong
 * (parts below the plane change nothing at z). */
struct surf_gap {
	size_t n;           /* gaps that meet the rectangle */
	double a[2], b[2];  /* of those, the ends of the one whose middle
			     * is nearest (px, py) */
};
/* The gaps of the section at z of the surface whose open border is b
 * that meet rect (xmin xmax ymin ymax); returns their count. */
size_t surf_border_at(const struct surf_border *b, double z, const double *rect,
		      double px, double py, struct surf_gap *g);

/* The squared distance from p to the closest point of triangle a b c,
 * um^2 (Ericson, Real-Time Collision Detection, 5.1.5). */
double surf_point_tri_dist2(const double p[3], const double *a, const double *b, const double *c);

#endif
