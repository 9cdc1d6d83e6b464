/*
 * plot_zbuf.c - the depth buffer of plot_zbuf.h.  A pixel (i, j) is the
 * page square whose centre is (x0 + (i + 0.5) / ppp, y1 - (j + 0.5) / ppp);
 * a triangle covers it when the centre is inside or on an edge (edge
 * functions of the three sides, the same sign as the triangle's area),
 * and its depth there is the linear interpolation of the corners'.
 */
#include "plot_zbuf.h"
#include "checked.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void plot_zbuf_init(struct plot_zbuf *z, double x0, double y0, double x1, double y1,
		    double ppp)
{
	memset(z, 0, sizeof *z);
	z->ppp = ppp;
	z->x0 = x0;
	z->y0 = y0;
	z->cols = ck_int(ceil((x1 - x0) * ppp), 1, 1 << 15, "picture width");
	z->rows = ck_int(ceil((y1 - y0) * ppp), 1, 1 << 15, "picture height");
	if (z->cols < 1)
		z->cols = 1;
	if (z->rows < 1)
		z->rows = 1;
	size_t n = (size_t)z->cols * (size_t)z->rows;
	z->depth = xreallocarray(NULL, n, sizeof *z->depth);
	z->gray = xmalloc(n);
	for (size_t i = 0; i < n; i++)
		z->depth[i] = -INFINITY;
	memset(z->gray, 255, n);
}

void plot_zbuf_tri(struct plot_zbuf *z, const double x[3], const double y[3],
		   const double d[3], double g)
{
	/* pixel coordinates: u right, v down from the top row */
	double u[3], v[3], top = z->y0 + z->rows / z->ppp;
	for (int k = 0; k < 3; k++) {
		u[k] = (x[k] - z->x0) * z->ppp;
		v[k] = (top - y[k]) * z->ppp;
	}
	double area = (u[1] - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (v[1] - v[0]);
	if (!(fabs(area) > 0))
		return;
	double umin = fmin(u[0], fmin(u[1], u[2])), umax = fmax(u[0], fmax(u[1], u[2]));
	double vmin = fmin(v[0], fmin(v[1], v[2])), vmax = fmax(v[0], fmax(v[1], v[2]));
	int i0 = (int)fmax(0, ceil(umin - 0.5)), i1 = (int)fmin(z->cols - 1, floor(umax - 0.5));
	int j0 = (int)fmax(0, ceil(vmin - 0.5)), j1 = (int)fmin(z->rows - 1, floor(vmax - 0.5));
	unsigned char gb = (unsigned char)lround(255 * (g < 0 ? 0 : g > 1 ? 1 : g));
	double s = area > 0 ? 1 : -1;
	for (int j = j0; j <= j1; j++) {
		double pv = j + 0.5;
		for (int i = i0; i <= i1; i++) {
			double pu = i + 0.5, w[3];
			for (int k = 0; k < 3; k++) {
				int a = (k + 1) % 3, b = (k + 2) % 3;
				w[k] = s * ((u[b] - u[a]) * (pv - v[a]) - (pu - u[a]) * (v[b] - v[a]));
			}
			if (w[0] < 0 || w[1] < 0 || w[2] < 0)
				continue;
			double dep = (w[0] * d[0] + w[1] * d[1] + w[2] * d[2]) / fabs(area);
			size_t at = (size_t)j * (size_t)z->cols + (size_t)i;
			if ((float)dep > z->depth[at]) {
				z->depth[at] = (float)dep;
				z->gray[at] = gb;
			}
		}
	}
}

void plot_zbuf_draw(struct plot_zbuf *z, struct draw *d)
{
	draw_image(d, z->x0, z->y0, z->x0 + z->cols / z->ppp, z->y0 + z->rows / z->ppp,
		   z->cols, z->rows, z->gray);
	free(z->depth);
	free(z->gray);
	memset(z, 0, sizeof *z);
}
