/*
 * vector.c - checks splat's vector imaging (src/splat/vector.c) and the
 * film stack it passes through (src/lib/numerics/filmstack.c) against
 * results that do not come from them:
 *   1. two-beam interference in an index-matched resist (N_imm = n
 *      resist = n substrate, no absorption, coherent light on a 0/180
 *      phase grating, which sends the orders +-1 only): the fringe
 *      visibility 2 |A(2)| / A(0) of the image spectrum is 1 for TE (the
 *      field along the lines, polarization y), |cos 2 theta_r| for TM (x)
 *      and cos^2 theta_r unpolarised, sin theta_r = lambda / (p n), to
 *      1e-9 (rounding), without a film and through the film stack's
 *      matrices alike; te and tm at s = 0 are unpolarised (the same
 *      spectrum to 1e-15), and off axis (a thin x dipole) te is close to
 *      y and tm to x (2e-3: the poles' cells turn the Jones vector by up to
 *      r / c = 0.025 rad, sin^2 of which is 6e-4);
 *   2. a clear mask at normal incidence through an absorbing resist on
 *      silicon: every plane's intensity A(0) equals the single-film
 *      standing-wave formula summed from Fresnel coefficients (Airy;
 *      tests/bleach/thinfilm.c's closed form) to 1e-12;
 *   3. filmstack_field at oblique incidence, s and p, tangential and z
 *      components, equals the same Airy sum with tilted admittances (q for
 *      s, N^2 / q for p) and E_z = tan(theta) (E_up - E_down), to 1e-10,
 *      also through a film thick and absorbing enough to need rescaling;
 *   4. R + T = 1 in lossless stacks for every angle, s and p, a layer
 *      beyond its critical angle included (frustrated total reflection),
 *      to 1e-12; and R + T < 1 once the resist absorbs;
 *   5. the scalar limit: at NA 0.1 with N_imm = n resist, no reflections
 *      and reduction inf, every plane of the vector stack equals the
 *      scalar stack by the same source cells (abbe.c) within 2 (NA / n)^2
 *      = 8.9e-3 of the clear field, the bound of the polarisation terms
 *      (the z component and the TM loss of contrast both go as sin^2 of
 *      the widest angle); measured much smaller.  And the radiometric
 *      factor at reduction 4 changes the image (by more than 1e-6) while
 *      staying within its own bound (1 - cos theta)/2 of it;
 *   6. the two ways vector.c sums a source point, five (three) FFTs of
 *      the fields or the pairs of orders directly into the spectrum, give
 *      the same stack through a film, unpolarised and TE, to 1e-12 of
 *      the clear field (rounding).
 */
#include "filmstack.h"
#include "fmt_splat.h"
#include "splat.h"
#include "util.h"
#include "splattest.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOL_TWOBEAM 1e-9
#define TOL_CLOSED 1e-12
#define TOL_AIRY 1e-10
#define TOL_RT 1e-12

/* The larger of w and d, NaN if d is (fmax would drop it). */
static double worse(double w, double d)
{
	return d > w || d != d ? d : w;
}

static double complex spec(const struct spectrum *sp, int l, int dm, int dn)
{
	size_t wd = 4 * (size_t)sp->mmax + 1, ht = 4 * (size_t)sp->nmax + 1;
	return sp->a[(size_t)l * wd * ht + (size_t)(dn + 2 * sp->nmax) * wd +
		     (size_t)(dm + 2 * sp->mmax)];
}

/* A lossless, index-matched film of index n: no reflection anywhere. */
static void matched(struct vfilm *vf, double lambda, double n, double thick)
{
	memset(vf, 0, sizeof *vf);
	vf->have = 1;
	vf->fs.lambda = lambda;
	vf->fs.n0 = vf->fs.nr = vf->fs.sub_n = n;
	vf->fs.thick = thick;
}

static void two_beam(void)
{
	static const char *pols[] = {"y", "x", "unpolarized", "te", "tm"};
	const double lambda = 0.193, n = 1.44, p = 0.2;
	double s = lambda / (p * n);
	double want[3] = {1, fabs(1 - 2 * s * s), 1 - s * s};
	struct spectrum *ref = NULL;
	for (int film = 0; film < 2; film++)
		for (int k = 0; k < 5; k++) {
			char buf[512];
			snprintf(buf, sizeof buf, "wavelength 0.193\nimmersion 1.44\nna 1.35\n"
				 "sigma 0\nimaging vector\npolarization %s\nreduction inf\n"
				 "resist thickness 0.3 index 1.44 planes 4\nwindow 0 0.2 0 0.2\n"
				 "background clear\nrect 0 0 0.1 0.2 1 180\ngrid 11 3\n", pols[k]);
			struct splat_input *in = input(buf);
			struct vfilm vf;
			matched(&vf, lambda, n, 0.3);
			struct spectrum *sp = splat_spectrum_vector(in, film ? &vf : NULL, 0, NULL);
			for (int l = 0; l < sp->nplanes; l++) {
				double v = 2 * cabs(spec(sp, l, 2, 0)) / creal(spec(sp, l, 0, 0));
				if (k < 3) {
					CHECK(fabs(v - want[k]) <= TOL_TWOBEAM, "two beams, %s, film %d, "
					      "plane %d: visibility %.12g, want %.12g", pols[k], film, l,
					      v, want[k]);
				}
			}
			if (k == 2 && film == 0) {
				printf("two beams: sin theta_r %.4f: visibility TE 1, TM %.6f, "
				       "unpolarised %.6f\n", s, want[1], want[2]);
				ref = sp;
				fmt_splat_free(in);
				continue;
			}
			if (k >= 3 && film == 0) {
				/* te and tm at s = 0: unpolarised */
				size_t na = (4 * (size_t)sp->mmax + 1) * (4 * (size_t)sp->nmax + 1) *
					    (size_t)sp->nplanes;
				double d = 0;
				for (size_t i = 0; i < na; i++)
					d = worse(d, cabs(sp->a[i] - ref->a[i]));
				CHECK(d <= 1e-15, "%s at s = 0 is not unpolarised (%g)", pols[k], d);
			}
			spectrum_free(sp);
			fmt_splat_free(in);
		}
	spectrum_free(ref);
}

/* Every plane on the grid of in (np nx ny values). */
static double *image(const struct splat_input *in, struct spectrum *sp)
{
	size_t n = (size_t)in->nx * in->ny;
	double *z = xreallocarray(NULL, n * (size_t)sp->nplanes, sizeof *z);
	for (int l = 0; l < sp->nplanes; l++) {
		struct spectrum v = spectrum_plane(sp, l);
		image_grid(&v, in->mask.xmin, in->mask.xmax, in->mask.ymin, in->mask.ymax,
			   in->nx, in->ny, z + (size_t)l * n);
	}
	return z;
}

static double maxdiff(const double *a, const double *b, size_t n)
{
	double d = 0;
	for (size_t i = 0; i < n; i++)
		d = worse(d, fabs(a[i] - b[i]));
	return d;
}

/* te against y and tm against x off axis, through a thin x dipole. */
static void te_tm(void)
{
	static const char *pols[] = {"te", "y", "tm", "x"};
	double *z[4];
	size_t n = 0;
	for (int k = 0; k < 4; k++) {
		char buf[512];
		snprintf(buf, sizeof buf, "wavelength 0.193\nimmersion 1.44\nna 1.35\n"
			 "dipole 0.8 0.02\nimaging vector\npolarization %s\n"
			 "window 0 0.09 0 0.09\nbackground clear\nrect 0 0 0.045 0.09 0 0\n"
			 "grid 19 3\n", pols[k]);
		struct splat_input *in = input(buf);
		struct spectrum *sp = splat_spectrum_vector(in, NULL, 0, NULL);
		z[k] = image(in, sp);
		n = (size_t)in->nx * in->ny;
		spectrum_free(sp);
		fmt_splat_free(in);
	}
	double d1 = maxdiff(z[0], z[1], n), d2 = maxdiff(z[2], z[3], n), d3 = maxdiff(z[0], z[2], n);
	printf("x dipole: te - y %.3g, tm - x %.3g, te - tm %.3g\n", d1, d2, d3);
	CHECK(d1 <= 2e-3 && d2 <= 2e-3, "te is not y (%g) or tm not x (%g) on an x dipole", d1, d2);
	CHECK(d3 > 0.1, "te and tm images alike (%g)", d3);
	for (int k = 0; k < 4; k++)
		free(z[k]);
}

/* The Airy sum for ambient N0 / film N1 (thickness T) / substrate N2:
 * the tangential field of the down- and up-going waves at depth z per
 * unit tangential incident field, with admittances eta. */
static void airy(double complex eta0, double complex eta1, double complex eta2,
		 double complex delta_per_um, double T, double z, double complex *down,
		 double complex *up)
{
	double complex r01 = (eta0 - eta1) / (eta0 + eta1), r12 = (eta1 - eta2) / (eta1 + eta2);
	double complex t01 = 2 * eta0 / (eta0 + eta1);
	double complex D = 1 + r01 * r12 * cexp(-2 * I * delta_per_um * T);
	*down = t01 * cexp(-I * delta_per_um * z) / D;
	*up = t01 * r12 * cexp(-I * delta_per_um * (2 * T - z)) / D;
}

static double complex qof(double complex N, double beta)
{
	double complex q = csqrt(N * N - beta * beta);
	return cimag(q) > 0 ? conj(q) : q;
}

static void closed_forms(void)
{
	/* an i-line novolac resist, 1 um on silicon (examples/contact-highna) */
	const double lambda = 0.365, n0 = 1, T = 1;
	struct filmstack fs = {lambda, n0, 1.7, (0.8 + 0.05) * lambda / (4 * M_PI), T, 0,
			       NULL, 6.41, 2.62};
	double complex N1 = CMPLX(fs.nr, -fs.kr), N2 = CMPLX(fs.sub_n, -fs.sub_k);
	double k0 = 2 * M_PI / lambda;
	/* 2: the clear mask at normal incidence through splat */
	struct splat_input *in = input("wavelength 0.365\nna 0.6\nsigma 0\nimaging vector\n"
				       "resist thickness 1 index 1.7 planes 21\n"
				       "window -0.5 0.5 -0.5 0.5\nbackground clear\ngrid 5 5\n");
	struct vfilm vf = {1, fs, NULL};
	struct spectrum *sp = splat_spectrum_vector(in, &vf, 0, NULL);
	double worst = 0;
	for (int l = 0; l < sp->nplanes; l++) {
		double z = l * T / (sp->nplanes - 1);
		double complex dn, up;
		airy(n0, N1, N2, k0 * N1, T, z, &dn, &up);
		double want = fs.nr / n0 * creal((dn + up) * conj(dn + up));
		double got = creal(spec(sp, l, 0, 0));
		worst = worse(worst, fabs(got - want));
	}
	printf("clear mask, normal incidence: vector stack against the Airy sum %.3g\n", worst);
	CHECK(worst <= TOL_CLOSED, "clear mask at normal incidence: %g from the Airy sum", worst);
	spectrum_free(sp);
	fmt_splat_free(in);
	/* 3: oblique s and p by the library against the Airy sum */
	enum { NZ = 11 };
	double zs[NZ];
	for (int j = 0; j < NZ; j++)
		zs[j] = j * T / (NZ - 1);
	worst = 0;
	for (int b = 0; b < 5; b++) {
		double beta = 0.2 * b * 0.99 * n0;
		double complex q0 = qof(n0, beta), q1 = qof(N1, beta), q2 = qof(N2, beta);
		for (int pol = 0; pol < 2; pol++) {
			double complex et[NZ], ez[NZ];
			filmstack_field(&fs, pol ? FILM_P : FILM_S, beta, NZ, zs, et, ez);
			double complex e0 = pol ? n0 * n0 / q0 : q0, e1 = pol ? N1 * N1 / q1 : q1;
			double complex e2 = pol ? N2 * N2 / q2 : q2;
			/* per unit amplitude: the tangential incident field is cos theta_0 of it for p */
			double complex c0 = pol ? q0 / n0 : 1;
			for (int j = 0; j < NZ; j++) {
				double complex dn, up;
				airy(e0, e1, e2, k0 * q1, T, zs[j], &dn, &up);
				double complex wt = c0 * (dn + up);
				double complex wz = pol ? c0 * beta / q1 * (up - dn) : 0;
				worst = worse(worse(worst, cabs(et[j] - wt)), cabs(ez[j] - wz));
			}
		}
	}
	printf("oblique s and p, tangential and z: filmstack against the Airy sum %.3g\n", worst);
	CHECK(worst <= TOL_AIRY, "oblique incidence: %g from the Airy sum", worst);
	/* a film so thick and absorbing (k0 k T = 860: e^860 overflows) that
	 * the climb must rescale: the field at its top and through it, 1e-10 */
	struct filmstack thick = {lambda, n0, 1.7, 1.0, 50, 0, NULL, 6.41, 2.62};
	double complex Nt = CMPLX(1.7, -1.0);
	double zt[5] = {0, 0.01, 0.1, 1, 50};
	worst = 0;
	for (int pol = 0; pol < 2; pol++) {
		double beta = 0.5, q0 = sqrt(1 - beta * beta);
		double complex q1 = qof(Nt, beta), q2 = qof(N2, beta);
		double complex e0 = pol ? 1 / q0 : q0, e1 = pol ? Nt * Nt / q1 : q1;
		double complex e2 = pol ? N2 * N2 / q2 : q2, et[5];
		filmstack_field(&thick, pol ? FILM_P : FILM_S, beta, 5, zt, et, NULL);
		for (int j = 0; j < 5; j++) {
			double complex dn, up;
			airy(e0, e1, e2, k0 * q1, 50, zt[j], &dn, &up);
			worst = worse(worst, cabs(et[j] - (pol ? q0 : 1) * (dn + up)));
		}
	}
	printf("a 50 um absorbing film (rescaled climb) against the Airy sum %.3g\n", worst);
	CHECK(worst <= TOL_AIRY, "thick absorbing film: %g from the Airy sum", worst);
}

static void energy(void)
{
	/* water / lossless resist / two lossless layers (one of index 1.3,
	 * beyond its critical angle for the widest waves) / glass */
	struct film_layer ly[2] = {{0.05, 1.3, 0}, {0.08, 2.1, 0}};
	struct filmstack fs = {0.193, 1.44, 1.7, 0, 0.15, 2, ly, 1.56, 0};
	double worst = 0;
	for (int b = 0; b <= 40; b++) {
		double beta = b / 40.0 * 0.999 * fs.n0;
		for (int pol = 0; pol < 2; pol++) {
			double R, T;
			filmstack_rt(&fs, pol ? FILM_P : FILM_S, beta, &R, &T);
			worst = worse(worst, fabs(R + T - 1));
		}
	}
	printf("lossless stack: |R + T - 1| at most %.3g over 41 angles, s and p\n", worst);
	CHECK(worst <= TOL_RT, "R + T - 1 = %g in a lossless stack", worst);
	fs.kr = 0.01;
	double R, T;
	filmstack_rt(&fs, FILM_S, 0.5, &R, &T);
	CHECK(R + T < 1 - 1e-3, "an absorbing resist absorbs nothing (R + T = %g)", R + T);
}

static void scalar_limit(void)
{
	const char *text = "wavelength 0.365\nimmersion 1.5\nna 0.1\nsigma 0.5\n"
			   "imaging vector\nreduction inf\nresist thickness 2 index 1.5 planes 5\n"
			   "window -4 4 -4 4\nbackground dark\nrect -1.5 -1.5 1.5 1.5\n"
			   "rect 2 -3 3 3 1 180\ngrid 33 33\n";
	struct splat_input *in = input(text);
	struct spectrum *sv = splat_spectrum_vector(in, NULL, 0, NULL);
	struct vfilm vf;
	matched(&vf, 0.365, 1.5, 2);
	struct spectrum *sf = splat_spectrum_vector(in, &vf, 0, NULL);
	in->vector = 0;
	struct spectrum *ss = splat_spectrum_method(in, SPLAT_ABBE, 0, 0, NULL);
	double *zv = image(in, sv), *zf = image(in, sf), *zs = image(in, ss);
	size_t n = (size_t)in->nx * in->ny * 5;
	double d = maxdiff(zv, zs, n), df = maxdiff(zf, zs, n);
	double bound = 2 * (0.1 / 1.5) * (0.1 / 1.5);
	printf("scalar limit, NA 0.1: vector - scalar stack %.3g, through the matched film "
	       "%.3g (bound %.3g)\n", d, df, bound);
	CHECK(d <= bound && df <= bound, "scalar limit: %g, %g from today's stack", d, df);
	/* the radiometric factor at reduction 4: sqrt(cos_o / cos_i) - 1 is
	 * at most (1 - cos theta_i) / 2 of the amplitude at NA 0.1 */
	in->vector = 1;
	in->reduction = 4;
	struct spectrum *sr = splat_spectrum_vector(in, NULL, 0, NULL);
	double *zr = image(in, sr);
	double dr = maxdiff(zr, zv, n), ci = sqrt(1 - (0.1 / 1.5) * (0.1 / 1.5));
	printf("reduction 4 against inf: %.3g\n", dr);
	CHECK(dr > 1e-6 && dr <= 2 * (1 - ci) * 2, "reduction 4 changes the image by %g", dr);
	free(zv);
	free(zf);
	free(zs);
	free(zr);
	spectrum_free(sv);
	spectrum_free(sf);
	spectrum_free(ss);
	spectrum_free(sr);
	fmt_splat_free(in);
}

static void two_paths(void)
{
	static const char *pols[] = {"unpolarized", "te"};
	struct film_layer ly[1] = {{0.078, 1.82, 0.34}};
	struct filmstack fs = {0.193, 1.44, 1.7, 0.02, 0.1, 1, ly, 0.88, 2.78};
	struct vfilm vf = {1, fs, NULL};
	for (int k = 0; k < 2; k++) {
		char buf[512];
		snprintf(buf, sizeof buf, "wavelength 0.193\nimmersion 1.44\nna 1.2\n"
			 "quadrupole 0.6 0.2\nimaging vector\npolarization %s\n"
			 "resist thickness 0.1 index 1.7 planes 4\nwindow -0.2 0.2 -0.15 0.15\n"
			 "background dark\nrect -0.03 -0.03 0.03 0.03\ngrid 21 17\n", pols[k]);
		struct splat_input *in = input(buf);
		double keep = vector_pair_fft;
		vector_pair_fft = 0;
		struct spectrum *sa = splat_spectrum_vector(in, &vf, 0, NULL);
		vector_pair_fft = INFINITY;
		struct spectrum *sb = splat_spectrum_vector(in, &vf, 0, NULL);
		vector_pair_fft = keep;
		double *za = image(in, sa), *zb = image(in, sb);
		double d = maxdiff(za, zb, (size_t)in->nx * in->ny * 4);
		printf("%s: the FFT and the direct pair sums differ by %.3g\n", pols[k], d);
		CHECK(d <= 1e-12, "%s: FFT and direct sums differ by %g", pols[k], d);
		free(za);
		free(zb);
		spectrum_free(sa);
		spectrum_free(sb);
		fmt_splat_free(in);
	}
}

int main(void)
{
	two_beam();
	te_tm();
	closed_forms();
	energy();
	scalar_limit();
	two_paths();
	if (failures)
		printf("%d failures\n", failures);
	return failures != 0;
}
