/*
 * calibfit.h - the numerics of calib(1): the free numbers of a resist
 * file, the residuals of simulated against measured CDs, the
 * Levenberg-Marquardt step with a finite-difference Jacobian, and the
 * parameters' covariance.  calib (a shell driver) runs the simulations
 * through fem(1); calibfit is called between them and keeps no state.
 */
#ifndef CALIBFIT_H
#define CALIBFIT_H

#include "fmt_fem.h"

enum { CALIB_MAX_FREE = 16 };

/* One -free "STATEMENT K LO:HI". */
struct calib_free {
	const char *spec;       /* as given, for messages */
	char stmt[32];
	int k;                  /* the K-th number on the line, from 1 */
	double lo, hi;
};

/* The measured points and what one simulation gave at each. */
struct calib_points {
	int n;
	const struct fem_point *p;  /* measured (focus, dose, cd), sorted */
	double *cd;                 /* simulated cd (um); 0 where not cleared */
	int uncleared;              /* points absent or not cleared */
};

/* Reads a fem.dat and matches it to the measured points by (focus, dose):
 * a point absent from it (its simulation failed) or not cleared gets cd 0,
 * a large residual, and is counted in uncleared. */
void calib_match(const struct fem_table *meas, const char *fem_path, struct calib_points *s);
void calib_points_free(struct calib_points *s);
/* Sum of squared residuals, um2. */
double calib_ssr(const struct calib_points *s);

/* The finite-difference step of a free number at v: 1 % of |v| (1 % of
 * the range at 0), backwards when forwards would leave the range; the
 * probe value v + h rounded as calib_round rounds. */
double calib_probe_value(const struct calib_free *f, double v);
/* A trial value as written to the resist file: 8 significant digits. */
double calib_round(double v);

/* J (n x p, row-major): d cd / d v from the probes. */
void calib_jacobian(int p, const double *v, const double *vprobe,
		    const struct calib_points *base, const struct calib_points *probe, double *J);
/* The Levenberg-Marquardt trial point for damping lambda: solves
 * (J'J + lambda diag(J'J)) d = -J'r and clamps v + scale d into the
 * ranges (scale below 1: a shorter step along the same direction).
 * Returns 0 and leaves out = v when the step is negligible (every |d_j|
 * below CALIB_STEP_TOL, 0.01, of the finite-difference step). */
int calib_step(int p, const struct calib_free *f, const double *v, int n, const double *J,
	       const double *r, double lambda, double scale, double *out);
/* cov = s2 (J'J)^-1; returns 0 when J'J is singular (cov then infinite
 * on the diagonal of every parameter without effect). */
int calib_covariance(int p, int n, const double *J, double s2, double *cov);
/* Solves the p x p system A x = b in place (partial pivoting); returns 0
 * if singular. */
int calib_solve(int p, double *A, double *b);

#endif
