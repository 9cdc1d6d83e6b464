/*
 * surf_lines.h - many parallel lines across one horizontal section of a
 * surface (surf.h) at once, for metrology that needs a whole feature
 * rather than one line through it: the lines along which a feature's
 * edges are sampled (every mesh row when the surface has evenly spaced
 * rows, evenly spaced lines otherwise), the spans of all of them, and
 * every developed region of a section (the holes of an array).
 */
#ifndef S3D_SURF_LINES_H
#define S3D_SURF_LINES_H

#include "surf.h"

#include <stddef.h>

/* The spans of one line (surf_line_spans), adjacent spans of one kind
 * merged, from the box edge to the box edge. */
struct surf_line {
	struct surf_span *sp;
	size_t n;
};

/* The spans of the n lines along axis (0: parallel to x, through y = c[l];
 * 1: parallel to y, through x = c[l]) in section sec, exactly as
 * surf_line_spans gives them line by line.  c must be ascending.  Each
 * segment is only offered to the lines its extent spans, so the cost is
 * that of the crossings, not of lines times segments; the lines run on
 * the thread pool (par.h), and the result does not depend on the split.
 * Free with surf_lines_free. */
struct surf_line *surf_lines_spans(const struct surf *s, const struct surf_section *sec,
				   int axis, const double *c, size_t n);
void surf_lines_free(struct surf_line *l, size_t n);

/* Where to sample a feature that runs along coordinate fa (0 x, 1 y) of
 * the box: at least nmin lines, at most nmax, evenly spaced over the
 * whole box length along fa, the first at or after its low side and the
 * last before its high side (the box repeats, so the high side is the
 * low side again).
 *
 * When the surface's vertices lie on evenly spaced rows along fa (a
 * surface meshed on a grid; the rows need not reach the box sides, but a
 * whole number of them must fill its length), the lines are those rows,
 * each divided into the fewest equal parts that give nmin lines or more,
 * and a line on a row takes the row's own coordinate, so the edges are
 * read at the mesh's own vertices.  Otherwise (or when that would need
 * more than nmax lines) there are n lines at the middles of n equal
 * parts of the length, n = nmin (nmax when the rows were too many).
 * Returns the positions (ascending, *n of them); *rows is the number of
 * mesh rows found (0: none, the evenly spaced fallback). */
double *surf_sample_lines(const struct surf *s, int fa, size_t nmin, size_t nmax,
			  size_t *n, size_t *rows);

/* A developed region of a section: a connected set of developed spans on
 * lines parallel to x. */
struct surf_region {
	double area;            /* um2 */
	double cx, cy;          /* centroid, um */
	double xlo, xhi;        /* extent along x of its spans */
	double ylo, yhi;        /* the first and last lines holding it */
	int edge;               /* it touches the box edge (cut there) */
};

/* Every developed region of the section, from nl lines parallel to x at
 * the middles of nl equal bands of the box's y side: each span stands for
 * its band (the midpoint rule across the lines, exact along them), and
 * spans on neighbouring lines that overlap are one region.  A region
 * reaching the box's x sides or holding a span on the first or last
 * line is marked edge.  Regions are in order of their first span (by
 * line, then x).  Returns the count; *out is allocated. */
size_t surf_regions(const struct surf *s, const struct surf_section *sec, size_t nl,
		    struct surf_region **out);

#endif
