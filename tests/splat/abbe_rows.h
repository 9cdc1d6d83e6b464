/*
 * abbe_rows.h - the source integral that splat's C tests use for their
 * own Abbe images (hopkins.c, polygon.c, stack.c), independent of
 * splat's TCC and source code.
 *
 * The source is the disc of radius rs (1/um) about the origin; the
 * pupil passes the order at f_k for source points inside the circle of
 * radius R about -f_k.  The integrand is smooth between those circles,
 * so the disc is cut into rows at every top, bottom and crossing of two
 * circles, each row into pieces at every pupil edge, and each piece
 * gets Gauss-Legendre of order ng (nodes gu, weights gw on [-1, 1]).
 * In y a row is mapped by y = mid + half sin(pi t / 2), which smooths
 * the square-root ends of the disc.  point(ctx, sx, sy, w) is called
 * at every node with its weight; the weights sum to the disc's area.
 */
#ifndef ABBE_ROWS_H
#define ABBE_ROWS_H

#include "util.h"

#include <math.h>
#include <stdlib.h>

static int abbe_rows_cmp(const void *x, const void *y)
{
	double u = *(const double *)x, v = *(const double *)y;
	return (u > v) - (u < v);
}

/* The row's pieces at height y, between the disc's edges -hs and hs and
 * cut at every pupil edge inside; returns their count + 1 in xb. */
static inline int abbe_rows_cuts(int nc, const double *cx, const double *cy,
				 const double *rr, double y, double hs, double *xb)
{
	int nx = 0;
	xb[nx++] = -hs;
	xb[nx++] = hs;
	for (int i = 1; i < nc; i++) {
		double e = rr[i] * rr[i] - (y - cy[i]) * (y - cy[i]);
		if (e <= 0)
			continue;
		double hw = sqrt(e);
		if (cx[i] - hw > -hs && cx[i] - hw < hs) xb[nx++] = cx[i] - hw;
		if (cx[i] + hw > -hs && cx[i] + hw < hs) xb[nx++] = cx[i] + hw;
	}
	qsort(xb, (size_t)nx, sizeof *xb, abbe_rows_cmp);
	return nx;
}

static inline void abbe_rows(int n, const double *fx, const double *fy, double R, double rs,
			     int ng, const double *gu, const double *gw,
			     void (*point)(void *ctx, double sx, double sy, double w), void *ctx)
{
	/* circle 0 is the source, circle k + 1 the pupil of order k */
	int nc = n + 1;
	double *cx = xcalloc((size_t)nc, sizeof *cx), *cy = xcalloc((size_t)nc, sizeof *cy);
	double *rr = xcalloc((size_t)nc, sizeof *rr);
	rr[0] = rs;
	for (int k = 0; k < n; k++) {
		cx[k + 1] = -fx[k];
		cy[k + 1] = -fy[k];
		rr[k + 1] = R;
	}
	size_t cap = 2 + 2 * (size_t)nc + (size_t)nc * nc, nb = 0;
	double *bp = xcalloc(cap, sizeof *bp);
	bp[nb++] = -rs;
	bp[nb++] = rs;
	for (int i = 0; i < nc; i++) {
		bp[nb++] = cy[i] + rr[i];
		bp[nb++] = cy[i] - rr[i];
		for (int j = i + 1; j < nc; j++) {
			double dx = cx[j] - cx[i], dy = cy[j] - cy[i], d = hypot(dx, dy);
			if (d == 0 || d >= rr[i] + rr[j] || d <= fabs(rr[i] - rr[j]))
				continue;
			double l = (rr[i] * rr[i] - rr[j] * rr[j] + d * d) / (2 * d);
			double h = sqrt(fmax(0, rr[i] * rr[i] - l * l));
			bp[nb++] = cy[i] + l * dy / d + h * dx / d;
			bp[nb++] = cy[i] + l * dy / d - h * dx / d;
		}
	}
	qsort(bp, nb, sizeof *bp, abbe_rows_cmp);
	double *xb = xcalloc(2 * (size_t)nc + 2, sizeof *xb);
	for (size_t k = 0; k + 1 < nb; k++) {
		double y0 = fmax(bp[k], -rs), y1 = fmin(bp[k + 1], rs);
		if (!(y1 - y0 > 1e-14))
			continue;
		for (int io = 0; io < ng; io++) {
			double t = gu[io] * M_PI / 2;
			double y = 0.5 * (y0 + y1) + 0.5 * (y1 - y0) * sin(t);
			double wy = gw[io] * M_PI / 2 * 0.5 * (y1 - y0) * cos(t);
			double hs = sqrt(fmax(0, rs * rs - y * y));
			int nx = abbe_rows_cuts(nc, cx, cy, rr, y, hs, xb);
			for (int s = 0; s + 1 < nx; s++) {
				double a0 = xb[s], a1 = xb[s + 1];
				if (!(a1 > a0))
					continue;
				for (int ii = 0; ii < ng; ii++) {
					double x = 0.5 * (a0 + a1) + 0.5 * (a1 - a0) * gu[ii];
					point(ctx, x, y, wy * gw[ii] * 0.5 * (a1 - a0));
				}
			}
		}
	}
	free(cx);
	free(cy);
	free(rr);
	free(bp);
	free(xb);
}

#endif
