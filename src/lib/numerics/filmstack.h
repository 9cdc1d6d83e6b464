/*
 * filmstack.h - a plane wave of any angle through the film stack
 * ambient / resist / layers / substrate, s and p separately, by
 * characteristic matrices (Born and Wolf 1.6; Macleod, Thin-film optical
 * filters, ch. 2).  bleach's thinfilm.c solves the same stack at normal
 * incidence with a resist whose extinction changes with depth; splat's
 * vector imaging needs every plane wave of the pupil at its own angle,
 * and bleach the normal-incidence factor of a stack splat wrote.
 *
 * Convention (that of thinfilm.c): fields go as exp(i(wt - k.r)), an
 * index is N = n - ik, z points down into the stack.  The invariant of a
 * plane wave is beta = n0 sin(theta0); in a layer
 *   q = sqrt(N^2 - beta^2),  Im q <= 0 (the wave decays downwards),
 * the tilted admittance is q for s and N^2 / q for p, and a layer of
 * thickness d has phase delta = k0 q d and the matrix
 *     [ cos delta            i sin delta / eta ]
 *     [ i eta sin delta      cos delta         ]
 * taking the tangential (E, H) at its bottom to its top.
 */
#ifndef S3D_FILMSTACK_H
#define S3D_FILMSTACK_H

#include <complex.h>

struct film_layer {
	double thick;           /* um */
	double n, k;            /* index n - ik */
};

struct filmstack {
	double lambda;          /* um */
	double n0;              /* ambient index, real (air, or the immersion liquid) */
	double nr, kr;          /* resist index nr - i kr */
	double thick;           /* resist thickness, um */
	int nlayers;
	const struct film_layer *layers;    /* under the resist, top first */
	double sub_n, sub_k;    /* substrate, semi-infinite */
};

enum film_pol { FILM_S, FILM_P };

/* The field in the resist at the nz depths z[j] (um below its top, each
 * in [0, thick], increasing) of a plane wave of unit amplitude incident
 * from the ambient with invariant beta (0 <= beta < n0):
 *   et[j]  the tangential component, along s_hat = z x u for s, along
 *          the plane of incidence's horizontal unit vector u for p;
 *   ez[j]  the z component (down), p only (NULL for s, or not wanted).
 * Down- and up-going waves included, every reflection and all absorption;
 * in the exp(i(wt - k.r)) convention above. */
void filmstack_field(const struct filmstack *fs, enum film_pol pol, double beta, int nz,
		     const double *z, double complex *et, double complex *ez);

/* Reflectance and transmittance (power, into the substrate) of the whole
 * stack for the plane wave of invariant beta; R + T = 1 when nothing
 * absorbs. */
void filmstack_rt(const struct filmstack *fs, enum film_pol pol, double beta, double *R,
		  double *T);

/* The normal-incidence relative intensity (nr / n0) |E(z)|^2 / |E_i|^2 at
 * the nz depths z[j], bleach's thin-film factor of an unbleached resist. */
void filmstack_normal(const struct filmstack *fs, int nz, const double *z, double *irel);

#endif
