/*
 * rough.h - measure's metrology of a whole feature at one height: the
 * roughness of the two edges of a space or line (roughness.c) and the
 * local CD uniformity of an array of holes (lcdu.c).  See measure(1),
 * ROUGHNESS and LCDU.
 */
#ifndef S3D_ROUGH_H
#define S3D_ROUGH_H

#include "fmt_measure.h"
#include "measure.h"

#include <stddef.h>
#include <stdio.h>

/* The edges of a space or line, sampled on n lines along the feature. */
struct roughness {
	size_t n;               /* lines */
	size_t rows;            /* mesh rows read (0: evenly spaced lines) */
	double step;            /* um between lines */
	double *edge[2];        /* the edges' positions along the cut, um:
				 * [0] the lower (left), [1] the higher */
	double ler[2];          /* 3 sigma (population) of each edge, um */
	double lwr;             /* 3 sigma of the width, um */
	double corr[2];         /* first 1/e crossing of each edge's
				 * autocorrelation, um; < 0: none */
	double *psd[2];         /* one-sided PSD of each edge at the
				 * frequencies k / length, k = 1 .. n/2 */
};

/* Samples the edges of the space or line of o through the row r0 (the
 * table's row at height z, um) and computes its figures.  Returns 0, or
 * -1 with what is wrong in err (nothing left allocated). */
int roughness_measure(const struct surf *s, const struct options *o, double z,
		      const struct row *r0, struct roughness *r, char *err, size_t errsz);
/* The PSD of both edges as a 2D plot file (plot2d(5)). */
void roughness_psd(const char *path, const struct roughness *r);
void roughness_free(struct roughness *r);

struct lcdu {
	struct measure_hole *holes;     /* in rows of increasing y, each by x;
					 * cd: the diameter of the circle of
					 * the section's area */
	size_t n;
	double lcdu;            /* 3 x sample sigma of cd (n - 1), um;
				 * < 0 with fewer than two holes */
};

/* Every hole of the section at height z (um) that the box edge does not
 * cut. */
void lcdu_measure(const struct surf *s, double z, struct lcdu *l);
void lcdu_free(struct lcdu *l);

#endif
