/*
 * filmstack.c - the characteristic-matrix solution of filmstack.h.
 *
 * As in bleach's thinfilm.c we start below: in the substrate there is
 * only the transmitted wave, (E, H) = (1, eta_sub), and climb, recording
 * (E, H) at every wanted depth of the resist.  At the top E = E_i + E_r
 * and H = eta_0 (E_i - E_r) give the incident tangential amplitude
 * E_i = (E + H / eta_0) / 2.  Everything is linear in the (arbitrary)
 * transmitted amplitude, so the climb rescales when the field grows, as
 * it does in thick absorbing films.
 *
 * Tangential and full amplitudes: for s the field is tangential; for p
 * the tangential component of a wave of amplitude A at angle theta is
 * A cos(theta), so a unit incident amplitude has E_i = cos(theta_0) =
 * q_0 / n_0.  The z component follows from the tangential H (Maxwell,
 * curl H = i w eps E, H in units of the free-space admittance):
 * E_z = -beta H / N^2, which is -tan(theta) E_t+ for the down-going wave
 * and +tan(theta) E_t- for the up-going one, as k.E = 0 demands.
 *
 * The matrix is written with sin(delta) / q (= k0 d at delta -> 0), so
 * that a grazing wave in a lossless layer (q = 0) needs no special case.
 */
#include "filmstack.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>

/* Rescale when |E| + |H| passes this (far from DBL_MAX, so one more step
 * cannot overflow before the check). */
#define FILM_RESCALE 1e100

/* n - ik (CMPLX is C11 but not in every compiler's headers, clang's
 * fuzzing build among them; the array layout of a complex is). */
static double complex film_index(double n, double k)
{
	double complex z;
	((double *)&z)[0] = n;
	((double *)&z)[1] = -k;
	return z;
}

static double complex film_q(double complex N, double beta)
{
	double complex q = csqrt(N * N - beta * beta);
	/* a lossless layer beyond its critical angle: the decaying root */
	return cimag(q) > 0 ? conj(q) : q;
}

static double complex film_eta(double complex N, double complex q, enum film_pol pol)
{
	return pol == FILM_S ? q : N * N / q;
}

/* One layer's matrix: (E, H) <- M (E, H). */
struct film_step {
	double complex c, m12, m21;
};

static struct film_step film_matrix(double complex N, double complex q, double k0d,
				    enum film_pol pol)
{
	double complex delta = k0d * q;
	double ad = fabs(creal(delta)) + fabs(cimag(delta));
	double complex sq = ad < 1e-8 ? k0d : csin(delta) / q;   /* sin(delta) / q */
	struct film_step st;
	st.c = ccos(delta);
	if (pol == FILM_S) {
		st.m12 = I * sq;
		st.m21 = I * q * q * sq;
	} else {
		st.m12 = I * q * q * sq / (N * N);
		st.m21 = I * N * N * sq;
	}
	return st;
}

static void film_apply(const struct film_step *st, double complex *E, double complex *H)
{
	double complex e = st->c * *E + st->m12 * *H;
	double complex h = st->m21 * *E + st->c * *H;
	*E = e;
	*H = h;
}

/* Rescales (E, H) when large; returns the factor divided out (1: none).
 * The size is the sum of the parts' magnitudes (cabs is a hypot, and this
 * runs at every step). */
static double film_rescale(double complex *E, double complex *H)
{
	double m = fabs(creal(*E)) + fabs(cimag(*E)) + fabs(creal(*H)) + fabs(cimag(*H));
	if (m > FILM_RESCALE || (m < 1 / FILM_RESCALE && m > 0)) {
		*E /= m;
		*H /= m;
		return m;
	}
	return 1;
}

/* Pieces a step of k0 d in a layer of q is cut into, so that no piece
 * grows or shrinks the field by more than e^FILM_PIECE (cos and sin of a
 * complex phase overflow near e^709). */
#define FILM_PIECE 50.0
static int film_pieces(double k0d, double complex q)
{
	double g = k0d * fabs(cimag(q));
	return g > FILM_PIECE ? (int)ceil(g / FILM_PIECE) : 1;
}

/* (E, H) at the resist's bottom, the log of the factors divided out in
 * *lscale. */
static void film_below(const struct filmstack *fs, enum film_pol pol, double beta,
		       double complex *E, double complex *H, double *lscale)
{
	double k0 = 2 * M_PI / fs->lambda;
	double complex Ns = film_index(fs->sub_n, fs->sub_k), qs = film_q(Ns, beta);
	if (qs == 0)
		qs = 1e-300;    /* grazing in a lossless substrate: no flux passes */
	*E = 1;
	*H = film_eta(Ns, qs, pol);
	*lscale = 0;
	for (int l = fs->nlayers - 1; l >= 0; l--) {
		const struct film_layer *ly = &fs->layers[l];
		double complex N = film_index(ly->n, ly->k), q = film_q(N, beta);
		int ns = film_pieces(k0 * ly->thick, q);
		struct film_step st = film_matrix(N, q, k0 * ly->thick / ns, pol);
		for (int i = 0; i < ns; i++) {
			film_apply(&st, E, H);
			*lscale += log(film_rescale(E, H));
		}
	}
}

void filmstack_field(const struct filmstack *fs, enum film_pol pol, double beta, int nz,
		     const double *z, double complex *et, double complex *ez)
{
	double k0 = 2 * M_PI / fs->lambda;
	double complex E, H;
	double lscale;
	film_below(fs, pol, beta, &E, &H, &lscale);
	double complex Nr = film_index(fs->nr, fs->kr), qr = film_q(Nr, beta);
	int want_h = pol == FILM_P && ez;
	/* climb the resist from its bottom through the depths, upwards; equal
	 * steps (a stack's planes) share one matrix */
	double cur = fs->thick, dlast = -1;
	struct film_step st = {0, 0, 0};
	int ns = 1;
	/* the field grows at most as exp(k0 |Im q| d) through the resist
	 * (from |E| + |H| <= 1e100, film_below): only a film thicker than
	 * e^200 of it can approach overflow and needs the test every step */
	int guard = k0 * fabs(cimag(qr)) * fs->thick > 200;
	for (int j = nz; j >= 0; j--) {
		double to = j > 0 ? z[j - 1] : 0;
		double d = cur - to;
		if (d > 0) {
			/* the planes k T / (N - 1) differ in their steps by
			 * rounding alone: one matrix, a phase error of 1e-12 */
			if (!(fabs(d - dlast) <= 1e-12 * d)) {
				ns = film_pieces(k0 * d, qr);
				st = film_matrix(Nr, qr, k0 * d / ns, pol);
				dlast = d;
			}
			for (int i = 0; i < ns; i++) {
				film_apply(&st, &E, &H);
				double m = guard ? film_rescale(&E, &H) : 1;
				if (m != 1)
					for (int q = j; q < nz; q++) {
						et[q] /= m;
						if (want_h)
							ez[q] /= m;
					}
			}
		}
		cur = to;
		if (j > 0) {
			et[j - 1] = E;
			if (want_h)
				ez[j - 1] = H;
		}
	}
	double n0 = fs->n0, q0 = sqrt(n0 * n0 - beta * beta);
	double complex eta0 = pol == FILM_S ? q0 : n0 * n0 / q0;
	double complex Ei = (E + H / eta0) / 2;
	/* per unit incident amplitude: E_i is cos(theta_0) of it for p */
	double complex f = (pol == FILM_S ? 1 : q0 / n0) / Ei, fz = -beta * f / (Nr * Nr);
	for (int j = 0; j < nz; j++) {
		if (want_h)
			ez[j] *= fz;
		else if (ez)
			ez[j] = 0;
		et[j] *= f;
	}
}

void filmstack_rt(const struct filmstack *fs, enum film_pol pol, double beta, double *R,
		  double *T)
{
	double k0 = 2 * M_PI / fs->lambda;
	double complex E, H;
	double lscale;
	film_below(fs, pol, beta, &E, &H, &lscale);
	double complex Ns = film_index(fs->sub_n, fs->sub_k), qs = film_q(Ns, beta);
	double complex etas = qs == 0 ? 0 : film_eta(Ns, qs, pol);
	double complex Nr = film_index(fs->nr, fs->kr), qr = film_q(Nr, beta);
	int ns = film_pieces(k0 * fs->thick, qr);
	struct film_step st = film_matrix(Nr, qr, k0 * fs->thick / ns, pol);
	for (int i = 0; i < ns; i++) {
		film_apply(&st, &E, &H);
		lscale += log(film_rescale(&E, &H));
	}
	double n0 = fs->n0, q0 = sqrt(n0 * n0 - beta * beta);
	double eta0 = pol == FILM_S ? q0 : n0 * n0 / q0;
	double complex Ei = (E + H / eta0) / 2, Er = (E - H / eta0) / 2;
	double ei2 = creal(Ei * conj(Ei));
	*R = creal(Er * conj(Er)) / ei2;
	/* flux Re(E H*): Re(eta_sub) |E_sub|^2 below, eta0 |E_i|^2 incident */
	*T = creal(etas) / (eta0 * ei2) * exp(-2 * lscale);
}

void filmstack_normal(const struct filmstack *fs, int nz, const double *z, double *irel)
{
	double complex *et = xreallocarray(NULL, (size_t)(nz > 0 ? nz : 1), sizeof *et);
	filmstack_field(fs, FILM_S, 0, nz, z, et, NULL);
	for (int j = 0; j < nz; j++)
		irel[j] = fs->nr / fs->n0 * creal(et[j] * conj(et[j]));
	free(et);
}
