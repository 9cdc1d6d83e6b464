/*
 * calibfit_report.h - calib.dat and the pictures' plot files (report.c).
 */
#ifndef CALIBFIT_REPORT_H
#define CALIBFIT_REPORT_H

#include "calibfit.h"

struct calib_report_in {
	int p;
	const struct calib_free *free;
	const double *v;                /* the fitted values */
	const struct calib_points *fit; /* the measured points, simulated at v */
	const double *J;                /* the Jacobian at v (n x p) */
	const struct calib_points *val; /* validation points at v, or NULL */
	int iterations;
	const char *dir;                /* calib.dat, bossung.2D/.tpl, residuals.2D/.tpl */
};

/* Writes DIR/calib.dat and the plot files, warns (one line each) about
 * correlations above 0.999 and errors above 10 % of the value, and dies
 * when a measured or validation point does not clear at v. */
void calib_report(const struct calib_report_in *in);

#endif
