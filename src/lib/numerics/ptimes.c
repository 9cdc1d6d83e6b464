/*
 * ptimes.c - the print times of a development (ptimes.h): the one rule
 * etch, etch2d and the sample3D driver share.
 */
#include "ptimes.h"

#include "util.h"

#include <limits.h>
#include <math.h>
#include <stddef.h>

double *ptimes_make(double et, double pt, int *n)
{
	double *times = NULL;
	size_t cap = 0;
	*n = 0;
	for (long k = 1;; k++) {
		double tp = pt > 0 ? k * pt : et;
		if (tp > et * (1 - PTIMES_TOL))
			tp = et;
		if (*n == INT_MAX)
			die("-pt %g against -et %g: too many print times", pt, et);
		xgrow(&times, &cap, (size_t)*n + 1, sizeof *times);
		times[(*n)++] = tp;
		if (tp >= et)
			break;
	}
	return times;
}

double ptimes_count(double et, double pt)
{
	return pt > 0 ? floor(et / pt * (1 + PTIMES_TOL)) : 1;
}
