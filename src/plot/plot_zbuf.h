/*
 * plot_zbuf.h - a depth-buffered grey picture for pdraw -h when its
 * polygons are smaller than the pixels that show them: each triangle is
 * scan-converted at the pixel centres it covers and kept where it is
 * nearest the eye, so the cost is one pass over the triangles plus the
 * pixels, and the picture (draw_image) is the same size for any mesh.
 */
#ifndef S3D_PLOT_ZBUF_H
#define S3D_PLOT_ZBUF_H

#include "draw.h"

struct plot_zbuf {
	int cols, rows;
	double x0, y0, ppp;     /* page position of the bottom left, pixels per point */
	float *depth;           /* towards the eye; -inf where nothing is drawn */
	unsigned char *gray;    /* row 0 at the top */
};

/* A buffer over the page rectangle x0 y0 x1 y1 at ppp pixels per point. */
void plot_zbuf_init(struct plot_zbuf *z, double x0, double y0, double x1, double y1,
		    double ppp);
/* A triangle of page points (x, y) with depth d (larger is nearer), of
 * grey g (0 black .. 1 white).  A pixel keeps the first of equal depths,
 * so the picture depends only on the order of the calls. */
void plot_zbuf_tri(struct plot_zbuf *z, const double x[3], const double y[3],
		   const double d[3], double g);
/* Adds the picture to the page and frees the buffer. */
void plot_zbuf_draw(struct plot_zbuf *z, struct draw *d);

#endif
