/*
 * plot_bsp.h - the hidden-line painter of pdraw -h: polygons (and the
 * segments of open curves) in view coordinates, painted far to near in
 * the order of a BSP partition (Fuchs, Kedem and Naylor 1980).
 */
#ifndef S3D_PLOT_BSP_H
#define S3D_PLOT_BSP_H

#include <stddef.h>

/* A polygon or segment, or a piece of one after splits. */
struct plot_frag {
	int n;              /* vertices (2 for a segment) */
	int curve;          /* the curve it comes from (its line style) */
	unsigned char seg;  /* an open-curve segment: never a splitter */
	unsigned char hasplane;
	double gray;        /* fill: 1 white (the surface), less for walls */
	double pl[4];       /* plane n.p + d = 0, |n| = 1 (view coordinates) */
	unsigned char *orig;/* edge i (i -> i+1) is part of an original edge */
	double p[];         /* 3n view coordinates; orig follows them */
};

/* A fragment of n vertices (coordinates to be filled in), white, no
 * plane, no original edges; one allocation. */
struct plot_frag *plot_frag_new(int n, int curve, int seg);
void plot_frag_free(struct plot_frag *f);
/* Sets f's plane from its vertices (Newell's normal); a segment or a
 * degenerate polygon has none. */
void plot_frag_plane(struct plot_frag *f);

struct plot_frag_list { struct plot_frag **f; size_t n, cap; };

void plot_frag_list_add(struct plot_frag_list *l, struct plot_frag *f);

/* Called for each fragment in painting order, far first. */
typedef void (*plot_bsp_paint_fn)(void *ctx, const struct plot_frag *f);

/* Partitions all (taking it over: every fragment is freed) and calls
 * paint for the pieces back to front, the eye looking down the view's
 * z axis.  The partition runs on an explicit stack. */
void plot_bsp_paint(struct plot_frag_list all, plot_bsp_paint_fn paint, void *ctx);

#endif
