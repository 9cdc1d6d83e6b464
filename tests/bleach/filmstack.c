/*
 * filmstack.c - the library's film stack at normal incidence
 * (filmstack_normal, src/lib/numerics/filmstack.c: what bleach divides a
 * film image stack by, and what splat's vector imaging gives for a clear
 * mask at normal incidence) equals bleach's own thin-film solver
 * (thinfilm_intensity, the 1D factor of every plain run) on the same
 * stack: a bleaching resist unexposed (k = (A + B) lambda / (4 pi)) under
 * water, on two absorbing layers and silicon, and an i-line resist on
 * silicon in air; to 1e-12 (both are matrix products of about a hundred
 * steps, rounding ~1e-14).  fmt_bleach_film builds the stack from the
 * resist file's statements (wavelength, ambient, resist, layers,
 * substrate), so the check also holds the two programs to one reading of
 * the file.
 */
#include "bleach.h"
#include "filmstack.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define TOL 1e-12

static int failures;

static double compare(const char *text)
{
	struct bleach_input in;
	fmt_bleach_parse("t.in", text, &in);
	int nz = in.nz;
	struct film_layer layers[BLEACH_MAX_LAYERS];
	struct filmstack fs;
	fmt_bleach_film(&in, &fs, layers);
	struct thinfilm tf;
	thinfilm_init(&tf, &in, nz);
	double *kr = malloc((size_t)nz * sizeof *kr), *a = malloc((size_t)nz * sizeof *a);
	double *b = malloc((size_t)nz * sizeof *b), *z = malloc((size_t)nz * sizeof *z);
	for (int j = 0; j < nz; j++) {
		kr[j] = (in.A + in.B) * in.wavelength / (4 * M_PI);
		z[j] = j == nz - 1 ? in.thick : j * tf.dz;
	}
	thinfilm_intensity(&tf, kr, a);
	filmstack_normal(&fs, nz, z, b);
	double d = 0;
	for (int j = 0; j < nz; j++)
		d = fmax(d, fabs(a[j] - b[j]));
	free(kr);
	free(a);
	free(b);
	free(z);
	return d;
}

int main(void)
{
	double d1 = compare("wavelength 0.193\nambient 1.44\n"
			    "resist thickness 0.12 index 1.7 dill 0.6 0.6 0.05\n"
			    "layer 0.03 1.6 0.1\nlayer 0.08 1.82 0.34\nsubstrate 0.88 2.78\n"
			    "dose 30\ndevelop mack 0.1 0.0001 0.5 5\ngrid nz 97\n");
	double d2 = compare("wavelength 0.365\nresist thickness 1 index 1.7 dill 0.8 0.05 0.014\n"
			    "substrate 6.41 2.62\ndose 80\ndevelop mack 0.1 0.0001 0.5 5\n"
			    "grid nz 81\n");
	printf("filmstack_normal against thinfilm_intensity: ArF in water %.3g, i-line %.3g\n",
	       d1, d2);
	if (!(d1 <= TOL && d2 <= TOL)) {
		printf("FAIL: beyond %g\n", TOL);
		failures++;
	}
	return failures != 0;
}
