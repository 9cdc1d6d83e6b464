/*
 * rfield.h - the etch-rate field R(x, y, z) seen by the ray advance of
 * etch and etch2d: the rate array of bleach, interpolated trilinearly,
 * with the gradient of that same interpolant (thesis 7.3: the ray
 * equation needs R and grad R anywhere, the array gives them only at grid
 * points).  A 2D array (ny = 1) is bilinear in x and z, the same at every
 * y, with dR/dy = 0, so a ray started in the x-z plane stays in it.
 *
 * raystep_* advance one ray of the ray equation (thesis [6.3], 7.3) by
 * one time step: shared by etch's and etch2d's ray advance.
 */
#ifndef S3D_RFIELD_H
#define S3D_RFIELD_H

struct rfield {
	int n[3];               /* grid points per axis (each >= 2) */
	double lo[3], hi[3];    /* box, um */
	double h[3];            /* spacing, um */
	const double *v;        /* rates, um/s, x fastest */
	double rmax;            /* largest rate, um/s */
	double gmax;            /* largest |grad R| of the interpolant, 1/s */
	int flat_outside;       /* 0 (rfield_init): outside the box, grad R of
				 * the nearest cell; 1: its component normal to
				 * the face crossed is 0, as for the clamped rate
				 * (etch2d's substrate, a wall seen as the face's
				 * rate continued below it) */
};

/* Sets up f over the rate array v (n[0] x n[1] x n[2] values, x fastest,
 * over the box lo..hi; not copied: v must outlive f).  name is the file
 * the array came from, for messages.  Dies ("name:1: ...") if the grid is
 * degenerate (fewer than 2 points along x or z, or along y when n[1] > 1)
 * or a rate is negative.  fmt_rate_field (fmt_rate.h) calls it on a rate
 * file's array. */
void rfield_init(struct rfield *f, const int n[3], const double lo[3], const double hi[3],
		 const double *v, const char *name);

/* R and grad R at p.  Outside the box the rate is not defined (thesis
 * 7.5.2.1); p is clamped into the box, so a node that has left it keeps
 * moving with the rate of the nearest face until it is clipped. */
double rfield_eval(const struct rfield *f, const double p[3], double g[3]);

/* One step dt (s) of the ray equation from (p, s) (s a unit vector) to
 * (p2, s2): the classical fourth-order Runge-Kutta rule on
 * dP/dt = R s, ds/dt = -(grad R - (s . grad R) s), or the thesis' Euler
 * step [6.7] + [6.6]/[A.33].  s2 is normalised. */
void raystep_rk4(const struct rfield *f, const double p[3], const double s[3],
		 double dt, double p2[3], double s2[3]);
void raystep_euler(const struct rfield *f, const double p[3], const double s[3],
		   double dt, double p2[3], double s2[3]);

#endif
