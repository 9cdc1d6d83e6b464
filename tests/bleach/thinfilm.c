/*
 * thinfilm.c - the characteristic-matrix solver (src/bleach/thinfilm.c)
 * against an independent closed form.
 *
 * 1. An unbleached (uniform k) resist film on a substrate: the relative
 *    intensity (n/n0)|E(z)|^2 / |E_i|^2 must equal the single-film
 *    standing-wave formula written out here from Fresnel coefficients
 *    (Mack's form, summing the multiple reflections as a geometric series):
 *      E(z) = t01 (e^{-i b z} + r12 e^{-i b (2T - z)}) / (1 + r01 r12 e^{-2 i b T}),
 *      b = 2 pi N1 / lambda, r_ij = (N_i - N_j)/(N_i + N_j), t01 = 2 N0/(N0 + N1),
 *    with N = n - ik; tolerance 1e-9 (rounding of ~1000 complex matrix
 *    products is ~1e-13).  Olin Hunt 6512 on Si (Table 9.1) and a second
 *    stack with a non-unit ambient index.
 * 2. A transparent resist: the intensity repeats with the standing-wave
 *    period lambda / (2 n) to 1e-9, and the swing is not trivial (> 0.5).
 * 3. A zero-thickness layer changes nothing (1e-12), and a layer with the
 *    resist's own index equals a thicker resist (1e-9).
 */
#include "bleach.h"

#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOL_CLOSED 1e-9
#define TOL_PERIOD 1e-9

static int failures;

static void check(int ok, const char *what, double got, double want)
{
	if (!ok) {
		printf("FAIL %s: got %.12g want %.12g\n", what, got, want);
		failures++;
	}
}

static void stack(struct bleach_input *in, double lambda, double n0, double T,
		  double n, double sn, double sk)
{
	memset(in, 0, sizeof *in);
	in->wavelength = lambda;
	in->ambient = n0;
	in->thick = T;
	in->index = n;
	in->sub_n = sn;
	in->sub_k = sk;
	in->standing = 1;
}

static double closed_form(const struct bleach_input *in, double k, double z)
{
	double complex N0 = in->ambient, N1 = CMPLX(in->index, -k);
	double complex N2 = CMPLX(in->sub_n, -in->sub_k);
	double complex r01 = (N0 - N1) / (N0 + N1), r12 = (N1 - N2) / (N1 + N2);
	double complex t01 = 2 * N0 / (N0 + N1);
	double complex b = 2 * M_PI * N1 / in->wavelength;
	double T = in->thick;
	double complex E = t01 * (cexp(-I * b * z) + r12 * cexp(-I * b * (2 * T - z))) /
			   (1 + r01 * r12 * cexp(-2 * I * b * T));
	return in->index / in->ambient * creal(E * conj(E));
}

static void film(double lambda, double n0, double T, double n, double k,
		 double sn, double sk, int nz, const char *name)
{
	struct bleach_input in;
	stack(&in, lambda, n0, T, n, sn, sk);
	struct thinfilm tf;
	thinfilm_init(&tf, &in, nz);
	double *kr = malloc(nz * sizeof *kr), *ir = malloc(nz * sizeof *ir);
	for (int j = 0; j < nz; j++)
		kr[j] = k;
	thinfilm_intensity(&tf, kr, ir);
	double worst = 0;
	for (int j = 0; j < nz; j++) {
		double want = closed_form(&in, k, j * tf.dz);
		double d = fabs(ir[j] - want);
		if (d > worst)
			worst = d;
		check(d <= TOL_CLOSED, name, ir[j], want);
		if (d > TOL_CLOSED)
			break;
	}
	printf("%s: max |I - closed form| = %.3g\n", name, worst);
	free(kr);
	free(ir);
}

int main(void)
{
	/* Olin Hunt 6512, unbleached: alpha = A + B = 0.68 /um */
	double lam = 0.436, k = 0.68 * lam / (4 * M_PI);
	film(lam, 1.0, 0.70, 1.68, k, 4.73, 0.14, 300, "Olin Hunt on Si");
	film(0.248, 1.2, 1.0, 1.76, 0.03, 1.57, 3.57, 501, "DUV film, ambient 1.2");

	/* transparent resist: period lambda / (2n), 40 nodes a period */
	{
		struct bleach_input in;
		double n = 1.68, per = lam / (2 * n);
		stack(&in, lam, 1.0, 5 * per, n, 4.73, 0.14);
		int nz = 5 * 40 + 1;
		struct thinfilm tf;
		thinfilm_init(&tf, &in, nz);
		double kr[201] = {0}, ir[201];
		thinfilm_intensity(&tf, kr, ir);
		double lo = 1e9, hi = -1e9, worst = 0;
		for (int j = 0; j + 40 < nz; j++) {
			double d = fabs(ir[j] - ir[j + 40]);
			if (d > worst)
				worst = d;
			if (ir[j] < lo) lo = ir[j];
			if (ir[j] > hi) hi = ir[j];
		}
		printf("transparent: period error %.3g, swing %.4f..%.4f\n", worst, lo, hi);
		check(worst <= TOL_PERIOD, "standing-wave period lambda/(2n)", worst, 0);
		check(hi - lo > 0.5, "standing-wave swing", hi - lo, 0.5);
	}

	/* layers: zero thickness is nothing; a layer of resist is resist */
	{
		struct bleach_input a, b;
		stack(&a, lam, 1.0, 0.5, 1.68, 4.73, 0.14);
		stack(&b, lam, 1.0, 0.5, 1.68, 4.73, 0.14);
		b.nlayers = 1;
		b.layers[0] = (struct bleach_layer){0.0, 1.47, 0.0};
		struct thinfilm ta, tb;
		thinfilm_init(&ta, &a, 101);
		thinfilm_init(&tb, &b, 101);
		double kr[101], ia[101], ib[101];
		for (int j = 0; j < 101; j++)
			kr[j] = 0.02;
		thinfilm_intensity(&ta, kr, ia);
		thinfilm_intensity(&tb, kr, ib);
		for (int j = 0; j < 101; j++)
			check(fabs(ia[j] - ib[j]) <= 1e-12, "zero-thickness layer", ib[j], ia[j]);
		/* 0.5 um resist + 0.25 um layer of the same index and k equals
		 * the top 101 nodes of a 0.75 um resist */
		struct bleach_input c;
		stack(&c, lam, 1.0, 0.75, 1.68, 4.73, 0.14);
		b.layers[0] = (struct bleach_layer){0.25, 1.68, 0.02};
		struct thinfilm tc;
		thinfilm_init(&tc, &c, 151);
		thinfilm_init(&tb, &b, 101);
		double kc[151], ic[151];
		for (int j = 0; j < 151; j++)
			kc[j] = 0.02;
		thinfilm_intensity(&tc, kc, ic);
		thinfilm_intensity(&tb, kr, ib);
		for (int j = 0; j < 101; j++)
			check(fabs(ic[j] - ib[j]) <= 1e-9, "layer of resist index", ib[j], ic[j]);
	}
	if (failures)
		printf("%d failures\n", failures);
	return failures != 0;
}
