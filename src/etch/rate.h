/*
 * rate.h - the etch-rate field R(x, y, z) seen by the ray advance: the
 * rate array of bleach, interpolated trilinearly, with the gradient of
 * that same interpolant (thesis 7.3: the ray equation needs R and grad R
 * anywhere, the array gives them only at grid points).
 */
#ifndef ETCH_RATE_H
#define ETCH_RATE_H

#include "fmt_rate.h"

struct rfield {
	int n[3];               /* grid points per axis (each >= 2) */
	double lo[3], hi[3];    /* box, um */
	double h[3];            /* spacing, um */
	const double *v;        /* rates, um/s, x fastest */
	double rmax;            /* largest rate, um/s */
	double gmax;            /* largest |grad R| of the interpolant, 1/s */
};

/* Sets up f over r's rate array (not copied: r must outlive f).  Dies
 * ("file:1: ...") if the grid is degenerate or a rate is negative. */
void rfield_init(struct rfield *f, const struct ratefile *r, const char *name);

/* R and grad R at p.  Outside the box the rate is not defined (thesis
 * 7.5.2.1); p is clamped into the box, so a node that has left it keeps
 * moving with the rate of the nearest face until it is clipped. */
double rfield_eval(const struct rfield *f, const double p[3], double g[3]);

#endif
