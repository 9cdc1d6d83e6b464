/*
 * surf_stitch.h - one developed surface from the surfaces of tiles.
 *
 * A tile is simulated on its core (the part of the layout it answers for)
 * plus a halo; its surface (a triangle soup, surf.h) is trusted only in
 * the core.  stitch_clip cuts a tile's triangles to its core rectangle,
 * and keeps the edges the cut leaves on the core's sides inside the
 * output box (the seams).  Two tiles that meet at a seam cut nearly the
 * same surface with the same plane, so the two seam curves lie within
 * the tiles' disagreement of each other, but their vertices differ:
 * stitch_weld joins each curve of one side to the curve of the other
 * side whose ends are nearest, by a strip of triangles in the seam plane
 * (the two curves walked together by arc length), and closes what is
 * left where four tiles meet (the strip ends on the vertical line
 * through the corner) by triangles along that line.  The result has no
 * open border at the seams (surf_border_find) when every curve found its
 * partner; a curve with none (the tiles disagree in topology there) is
 * left open and counted.
 *
 * Points are compared by their bits: a cut point is computed from the
 * two ends of its edge in a fixed order, so the two triangles that share
 * an edge cut it at the same point.
 */
#ifndef S3D_SURF_STITCH_H
#define S3D_SURF_STITCH_H

#include <stddef.h>

/* Ends of two seam curves farther apart than this (um, in the seam
 * plane) are not joined: the tiles disagree by more than the bake,
 * development and discretisation differences a halo leaves (nanometres
 * for a halo of a few optical radii, docs in stitch(1)). */
#define STITCH_MATCH_UM 0.05

/* The seams are moved this far (um) in +x and +y from the cores' sides,
 * so that they lie on no plane of the tiles' grids: marching tetrahedra
 * put whole edges and faces of the surface on a grid plane, and a face on
 * the seam belongs to neither side.  An irrational multiple of any grid
 * step in practice (0.618 nm), far under a CD's tolerance. */
#define STITCH_SEAM_OFFSET_UM 6.18034e-4

struct stitch_edge {
	int axis;           /* 0: the plane x = c, 1: y = c */
	int side;           /* 0: the tile is below c, 1: above */
	int tile;
	double c;
	double p[3], q[3];
};

struct stitch {
	double box[6];      /* the output box: xmin xmax ymin ymax zmin zmax */
	struct stitch_edge *e;
	size_t n, cap;
	size_t unmatched;   /* stitch_weld: seam curves left without a partner */
	size_t corners_open;/* stitch_weld: corner ends left open */
};

typedef void stitch_emit_fn(void *ctx, const double *tri9);

void stitch_init(struct stitch *st, const double *box);
void stitch_free(struct stitch *st);
/* Clips triangle tri9 (output coordinates) to core (xmin xmax ymin ymax)
 * (its sides inside the output box moved by STITCH_SEAM_OFFSET_UM) and
 * calls emit for each triangle of the part inside (none, one or a
 * fan); returns how many.  The edges on the core's sides that are not on
 * a face of the output box are kept as seams of tile. */
int stitch_clip(struct stitch *st, int tile, const double *core, const double *tri9,
		stitch_emit_fn *emit, void *ctx);
/* Joins the seams kept so far; calls emit for each joining triangle and
 * returns how many. */
size_t stitch_weld(struct stitch *st, stitch_emit_fn *emit, void *ctx);

#endif
