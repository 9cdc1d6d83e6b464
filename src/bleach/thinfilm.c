/*
 * thinfilm.c - the standing waves in the resist (thesis 2.1, Figure 2.2):
 * a normally incident plane wave on the stack ambient / resist / layers /
 * substrate, solved with characteristic matrices (Berning's method, Born
 * and Wolf 1.6).  The resist is cut into nz - 1 thin sublayers because
 * its extinction changes with depth as it bleaches.
 *
 * Convention: fields go as exp(i(wt - k0 N z)) with N = n - ik, so that a
 * layer of index N and thickness d has phase delta = k0 N d and the matrix
 *     [ cos delta         i sin delta / N ]
 *     [ i N sin delta     cos delta       ]
 * taking the tangential (E, H) at its bottom to its top (H in units of
 * the free-space admittance).  We start below: in the substrate there is
 * only the transmitted wave, (E, H) = (1, N_sub), and climb, recording E
 * at every resist node.  At the top, E = E_i + E_r and H = n0 (E_i - E_r)
 * give the incident amplitude E_i = (E + H / n0) / 2.  The amplitudes are
 * linear in the (arbitrary) transmitted one, so the climb may rescale
 * them freely to avoid overflow in thick absorbing films.
 */
#include "bleach.h"

#include <complex.h>
#include <math.h>

void thinfilm_init(struct thinfilm *tf, const struct bleach_input *in, int nz)
{
	tf->lambda = in->wavelength;
	tf->n0 = in->ambient;
	tf->nr = in->index;
	tf->nz = nz;
	tf->dz = in->thick / (nz - 1);
	tf->nlayers = in->nlayers;
	tf->layers = in->layers;
	tf->sub_n = in->sub_n;
	tf->sub_k = in->sub_k;
}

/* Rescale when the field grows past this (far from DBL_MAX, so that one
 * more matrix step cannot overflow before the check). */
#define TF_RESCALE 1e100

/* (E, H) <- M (E, H) for a layer of index N and thickness d. */
static void climb(double complex *E, double complex *H, double complex N,
		  double k0d)
{
	double complex delta = k0d * N;
	double complex c = ccos(delta), s = csin(delta);
	double complex e = c * *E + I * s / N * *H;
	double complex h = I * N * s * *E + c * *H;
	*E = e;
	*H = h;
}

void thinfilm_intensity(const struct thinfilm *tf, const double *kr, double *irel)
{
	const double k0 = 2 * M_PI / tf->lambda;
	double complex E = 1, H = CMPLX(tf->sub_n, -tf->sub_k);
	for (int l = tf->nlayers - 1; l >= 0; l--) {
		const struct bleach_layer *ly = &tf->layers[l];
		climb(&E, &H, CMPLX(ly->n, -ly->k), k0 * ly->thick);
		double m = cabs(E) + cabs(H);
		if (m > TF_RESCALE || (m < 1 / TF_RESCALE && m > 0)) {
			E /= m;
			H /= m;
		}
	}
	/* irel holds |E|^2 while climbing, normalised at the end */
	int n = tf->nz;
	irel[n - 1] = creal(E * conj(E));
	for (int j = n - 2; j >= 0; j--) {
		climb(&E, &H, CMPLX(tf->nr, -kr[j]), k0 * tf->dz);
		double m = cabs(E) + cabs(H);
		if (m > TF_RESCALE) {
			/* deeper nodes shrink with the rest; they may underflow
			 * to 0, which is what their relative intensity is */
			E /= m;
			H /= m;
			for (int q = j + 1; q < n; q++)
				irel[q] /= m * m;
		}
		irel[j] = creal(E * conj(E));
	}
	double complex Ei = (E + H / tf->n0) / 2;
	double ei2 = creal(Ei * conj(Ei));
	double f = tf->nr / tf->n0 / ei2;
	for (int j = 0; j < n; j++)
		irel[j] *= f;
}
