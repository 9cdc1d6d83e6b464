/*
 * hopkins.c - checks the Hopkins image of splat against results that do
 * not come from its own TCC code:
 *   1. clear field gives 1 and dark field 0 everywhere (exact, 1e-9);
 *   2. coherent (sigma 0) equal line/space grating of period 2 um whose
 *      +-1 orders alone pass the pupil, with and without defocus: the
 *      analytic three-beam image |1/2 + (2/pi) e^{i phi} cos(2 pi x/p)|^2
 *      (1e-6);
 *   3. an Abbe summation written here - its own mask coefficients, its
 *      own pupil written with angles, its own source integration (rows
 *      cut at every pupil edge) - against the Hopkins result for a
 *      partially coherent, defocused, comatic, phase-shifted mask (1e-6);
 *   4. symmetries: a centred square gives a 4-fold image, coma along x
 *      breaks only the x mirror, astigmatism gives a 2-fold image, +d and
 *      -d defocus give the same image (1e-9 for mirrors, 1e-6 for the
 *      x-y transpose, which the row quadrature keeps only to its error;
 *      broken symmetries must differ by more than 1e-3);
 *   5. the source integral is converged: four times the quadrature
 *      orders moves the image by less than 1e-4 (the man page's figure;
 *      printed).
 */
#include "fmt_splat.h"
#include "splat.h"
#include "util.h"
#include "splattest.h"
#include "abbe_rows.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Image on the input's grid with quadrature orders (0: defaults). */
static double *grid(const struct splat_input *in, int no, int ni)
{
	struct spectrum *sp = splat_spectrum(in, no, ni, NULL);
	if (!sp)
		die("no light");
	double *z = xreallocarray(NULL, (size_t)in->nx * in->ny, sizeof *z);
	const struct splat_mask *m = &in->mask;
	image_grid(sp, m->xmin, m->xmax, m->ymin, m->ymax, in->nx, in->ny, z);
	spectrum_free(sp);
	return z;
}

static double maxdiff(const double *a, const double *b, size_t n)
{
	double d = 0;
	for (size_t i = 0; i < n; i++)
		if (fabs(a[i] - b[i]) > d)
			d = fabs(a[i] - b[i]);
	return d;
}

/* ---- 1. clear and dark fields ---- */
static void test_fields(void)
{
	/* exact: the zero order alone, TCC(0,0)/norm = 1 */
	const double TOL = 1e-9;
	static const char *srcs[] = {"sigma 0.5", "sigma 0", "annular 0.3 0.7",
				     "quadrupole 0.6 0.2", "sigma 1.3"};
	for (int k = 0; k < 5; k++) {
		char buf[512];
		snprintf(buf, sizeof buf, "%s\ndefocus 1.5\ncoma 0.3 field 1 0\n"
			 "window 0 3 0 2\nbackground clear\ngrid 9 7\n", srcs[k]);
		struct splat_input *in = input(buf);
		double *z = grid(in, 0, 0);
		for (int i = 0; i < 63; i++)
			CHECK(fabs(z[i] - 1) <= TOL, "clear field (%s) gives %.17g", srcs[k], z[i]);
		free(z);
		in->mask.bg_t = 0;
		z = grid(in, 0, 0);
		for (int i = 0; i < 63; i++)
			CHECK(fabs(z[i]) <= TOL, "dark field (%s) gives %.17g", srcs[k], z[i]);
		free(z);
		fmt_splat_free(in);
	}
}

/* ---- 2. coherent three-beam grating ---- */
static void test_three_beam(void)
{
	const double TOL = 1e-6;      /* the accuracy asked; rounding gives ~1e-15 */
	const double p = 2.0, lambda = 0.436;
	/* orders +-1 at 0.5/um pass NA/lambda = 0.642/um, +-3 at 1.5/um do
	 * not, even orders of an equal line/space vanish; y orders at 1/um
	 * (window height 1) are outside too */
	for (int k = 0; k < 2; k++) {
		double d = k ? 0.8 : 0;
		char buf[512];
		snprintf(buf, sizeof buf, "sigma 0\ndefocus %g\nwindow -1 1 0 1\n"
			 "rect -0.5 0 0.5 1\ngrid 41 3\n", d);
		struct splat_input *in = input(buf);
		double *z = grid(in, 0, 0);
		double phi = 2 * M_PI * d / lambda * (sqrt(1 - lambda * lambda / (p * p)) - 1);
		double worst = 0;
		for (int j = 0; j < 3; j++)
			for (int i = 0; i < 41; i++) {
				double x = -1 + 2.0 * i / 40;
				double a = 2 / M_PI * cos(2 * M_PI * x / p);
				double want = 0.25 + a * cos(phi) + a * a;
				double e = fabs(z[j * 41 + i] - want);
				if (e > worst)
					worst = e;
			}
		printf("three-beam (defocus %g): max error %.3g\n", d, worst);
		CHECK(worst <= TOL, "three-beam image off by %g (defocus %g)", worst, d);
		free(z);
		fmt_splat_free(in);
	}
}

/* ---- 3. Abbe summation, independent of the TCC code ---- */

/* The mask: non-overlapping rects on a dark background. */
struct arect { double x1, y1, x2, y2, t, deg; };
static const struct arect AR[] = {
	{-0.6, -0.9, 0.4, 0.7, 1, 0},
	{0.55, -0.3, 0.95, 0.3, 1, 180},
	{-0.9, 1.0, 0.9, 1.3, 0.5, 90},
};
enum { NAR = 3 };
static const double ALX = 2, ALY = 3;          /* window (-1,1) x (-1.5,1.5) */
static const double ALAMBDA = 0.436, ANA = 0.28, ASIGMA = 0.5;
static const double ADEF = 0.7, ACOMA = 0.4, AHX = 0.8, AHY = 0.6;

static double complex abbe_coef(int m, int n)
{
	double complex c = 0;
	for (int k = 0; k < NAR; k++) {
		const struct arect *r = &AR[k];
		double complex cx, cy;
		/* (1/L) integral of exp(-2 pi i q x / L) over [a, b], by the
		 * antiderivative rather than the sinc form used by mask.c */
		if (m == 0)
			cx = (r->x2 - r->x1) / ALX;
		else
			cx = (cexp(-2 * M_PI * I * m * r->x2 / ALX) -
			      cexp(-2 * M_PI * I * m * r->x1 / ALX)) / (-2 * M_PI * I * m);
		if (n == 0)
			cy = (r->y2 - r->y1) / ALY;
		else
			cy = (cexp(-2 * M_PI * I * n * r->y2 / ALY) -
			      cexp(-2 * M_PI * I * n * r->y1 / ALY)) / (-2 * M_PI * I * n);
		c += r->t * cexp(I * r->deg * M_PI / 180) * cx * cy;
	}
	return c;
}

/* The pupil with angles: W = c h rho^3 cos(theta - theta_h). */
static double complex abbe_pupil(double gx, double gy)
{
	double R = ANA / ALAMBDA, g = hypot(gx, gy);
	if (g > R)
		return 0;
	double rho = g / R, th = atan2(gy, gx), thh = atan2(AHY, AHX), h = hypot(AHX, AHY);
	double w = ACOMA * h * rho * rho * rho * cos(th - thh);
	w += ADEF / ALAMBDA * (sqrt(1 - ALAMBDA * ALAMBDA * g * g) - 1);
	return cexp(2 * M_PI * I * w);
}

enum { AMAXO = 64, ANPT = 5 };
struct abbe {
	int n;
	double fx[AMAXO], fy[AMAXO];
	double complex c[AMAXO];
	double px[ANPT * ANPT], py[ANPT * ANPT];
	double sum[ANPT * ANPT];
	double norm;
	double gu[16], gw[16];
	int ng;
};

/* Adds the integrand at source point s with weight w. */
static void abbe_point(struct abbe *a, double sx, double sy, double w)
{
	double complex amp[AMAXO];
	for (int k = 0; k < a->n; k++)
		amp[k] = a->c[k] * abbe_pupil(a->fx[k] + sx, a->fy[k] + sy);
	for (int p = 0; p < ANPT * ANPT; p++) {
		double complex e = 0;
		for (int k = 0; k < a->n; k++)
			e += amp[k] * cexp(2 * M_PI * I * (a->fx[k] * a->px[p] + a->fy[k] * a->py[p]));
		a->sum[p] += w * creal(e * conj(e));
	}
	a->norm += w;       /* |P(s)|^2 = 1 on the source (sigma < 1) */
}

/* abbe_rows calls this at every source node. */
static void abbe_node(void *ctx, double sx, double sy, double w)
{
	abbe_point(ctx, sx, sy, w);
}

static void abbe_image(struct abbe *a)
{
	double R = ANA / ALAMBDA;
	abbe_rows(a->n, a->fx, a->fy, R, ASIGMA * R, a->ng, a->gu, a->gw, abbe_node, a);
}

static void test_abbe(void)
{
	const double TOL = 1e-6;      /* the accuracy asked */
	struct abbe a;
	memset(&a, 0, sizeof a);
	a.ng = 14;
	quad_gauss(a.ng, a.gu, a.gw);
	double R = ANA / ALAMBDA, fmax = R * (1 + ASIGMA);
	for (int n = -4; n <= 4; n++)
		for (int m = -4; m <= 4; m++)
			if (hypot(m / ALX, n / ALY) < fmax && a.n < AMAXO) {
				a.fx[a.n] = m / ALX;
				a.fy[a.n] = n / ALY;
				a.c[a.n] = abbe_coef(m, n);
				a.n++;
			}
	for (int j = 0; j < ANPT; j++)
		for (int i = 0; i < ANPT; i++) {
			a.px[j * ANPT + i] = -1 + 2.0 * i / (ANPT - 1) + 0.013;
			a.py[j * ANPT + i] = -1.5 + 3.0 * j / (ANPT - 1) - 0.029;
		}
	abbe_image(&a);

	char buf[1024];
	int len = snprintf(buf, sizeof buf, "wavelength %g\nna %g\nsigma %g\ndefocus %g\n"
			   "coma %g field %g %g\nwindow -1 1 -1.5 1.5\n",
			   ALAMBDA, ANA, ASIGMA, ADEF, ACOMA, AHX, AHY);
	for (int k = 0; k < NAR; k++)
		len += snprintf(buf + len, sizeof buf - (size_t)len, "rect %g %g %g %g %g %g\n",
				AR[k].x1, AR[k].y1, AR[k].x2, AR[k].y2, AR[k].t, AR[k].deg);
	struct splat_input *in = input(buf);
	struct spectrum *sp = splat_spectrum(in, 0, 0, NULL);
	double worst = 0, peak = 0;
	for (int p = 0; p < ANPT * ANPT; p++) {
		double ab = a.sum[p] / a.norm;
		double ho = image_at(sp, a.px[p], a.py[p]);
		if (fabs(ab - ho) > worst)
			worst = fabs(ab - ho);
		if (ab > peak)
			peak = ab;
	}
	printf("Abbe vs Hopkins (%d orders, peak %.3f): max difference %.3g\n",
	       a.n, peak, worst);
	CHECK(worst <= TOL, "Abbe and Hopkins differ by %g", worst);
	CHECK(peak > 0.1, "the Abbe test image is nearly dark (peak %g): a weak test", peak);
	spectrum_free(sp);
	fmt_splat_free(in);
}

/* ---- 4. symmetries ---- */
static const char SQUARE[] = "window -3 3 -3 3\nrect -0.625 -0.625 0.625 0.625\n"
	"grid 31 31\nsigma 0.5\n";

static double mirror_x(const double *z, int n)
{
	double d = 0;
	for (int j = 0; j < n; j++)
		for (int i = 0; i < n; i++)
			d = fmax(d, fabs(z[j * n + i] - z[j * n + (n - 1 - i)]));
	return d;
}

static double mirror_y(const double *z, int n)
{
	double d = 0;
	for (int j = 0; j < n; j++)
		for (int i = 0; i < n; i++)
			d = fmax(d, fabs(z[j * n + i] - z[(n - 1 - j) * n + i]));
	return d;
}

static double transpose(const double *z, int n)
{
	double d = 0;
	for (int j = 0; j < n; j++)
		for (int i = 0; i < n; i++)
			d = fmax(d, fabs(z[j * n + i] - z[i * n + j]));
	return d;
}

static double *square(const char *extra)
{
	char buf[512];
	snprintf(buf, sizeof buf, "%s%s\n", SQUARE, extra);
	struct splat_input *in = input(buf);
	double *z = grid(in, 0, 0);
	fmt_splat_free(in);
	return z;
}

static void test_symmetry(void)
{
	const double EXACT = 1e-9;    /* symmetric integrals, rounding only */
	/* the source rows run along x, so the x-y transpose is exact only to
	 * the quadrature error (measured ~2e-8; test 5 bounds it) */
	const double QUAD = 1e-6;
	const double BROKEN = 1e-3;   /* a 0.4-wave aberration moves the image far more */
	double *z = square("");
	CHECK(mirror_x(z, 31) <= EXACT && mirror_y(z, 31) <= EXACT && transpose(z, 31) <= QUAD,
	      "square: not 4-fold symmetric (%g %g %g)", mirror_x(z, 31), mirror_y(z, 31),
	      transpose(z, 31));
	free(z);

	z = square("coma 0.4 field 1 0");
	CHECK(mirror_y(z, 31) <= EXACT, "coma along x breaks the y mirror (%g)", mirror_y(z, 31));
	CHECK(mirror_x(z, 31) > BROKEN, "coma along x keeps the x mirror (%g)", mirror_x(z, 31));
	/* thesis 9.3.3, Fig 9.27: the intensity builds up towards -x */
	double left = z[15 * 31 + 11], right = z[15 * 31 + 19];
	CHECK(left > right, "coma (1,0): intensity at -x %g is not above +x %g", left, right);
	free(z);

	z = square("astigmatism 0.4 field 1 0");
	CHECK(mirror_x(z, 31) <= EXACT && mirror_y(z, 31) <= EXACT,
	      "astigmatism: mirrors broken (%g %g)", mirror_x(z, 31), mirror_y(z, 31));
	CHECK(transpose(z, 31) > BROKEN, "astigmatism: image still 4-fold (%g)",
	      transpose(z, 31));
	free(z);

	double *zp = square("defocus 1.2"), *zm = square("defocus -1.2"), *z0 = square("");
	double d = maxdiff(zp, zm, 31 * 31);
	CHECK(d <= EXACT, "defocus +d and -d differ by %g", d);
	CHECK(maxdiff(zp, z0, 31 * 31) > BROKEN, "defocus 1.2 um changes nothing");
	free(zp);
	free(zm);
	free(z0);
}

/* ---- 5. convergence of the source integral ---- */
static void test_convergence(void)
{
	const double TOL = 1e-4;      /* the accuracy asked, quoted in splat.5 */
	static const char *cases[] = {
		"sigma 0.5\n",
		"sigma 0.3\ncoma 0.4 field 1 0\ndefocus 1\n",
		"annular 0.4 0.8\nastigmatism 0.4 field 1 0\n",
		"quadrupole 0.6 0.2\nspherical 0.5\n",
		"dipole 0.7 0.25 y\nzernike 7 0.3\ndefocus -0.5\n",
		"sigma 1.2\n",
	};
	double worst = 0;
	for (int k = 0; k < 6; k++) {
		char buf[512];
		snprintf(buf, sizeof buf, "%swindow -2 2 -2 2\nrect -0.6 -0.6 0.6 0.6\n"
			 "rect 0.9 -1.5 1.3 1.5 1 180\ngrid 21 21\n", cases[k]);
		struct splat_input *in = input(buf);
		struct pupil p;
		pupil_init(&p, in);
		int no, ni;
		quad_default(&p, &no, &ni);
		double *a = grid(in, 0, 0), *b = grid(in, 4 * no, 4 * ni);
		double d = maxdiff(a, b, 21 * 21);
		printf("convergence %d: default (%d, %d) vs (%d, %d): %.3g\n", k, no, ni,
		       4 * no, 4 * ni, d);
		worst = fmax(worst, d);
		CHECK(d <= TOL, "case %d: quadrature not converged (%g)", k, d);
		free(a);
		free(b);
		fmt_splat_free(in);
	}
	printf("convergence: worst %.3g\n", worst);
}

/* ---- fringe Zernike numbering spot checks ---- */
static void test_zernike(void)
{
	const double TOL = 1e-12;
	double r = 0.7, t = 0.4;
	CHECK(fabs(pupil_zernike(4, r, t) - (2 * r * r - 1)) < TOL, "Z4");
	CHECK(fabs(pupil_zernike(7, r, t) - (3 * r * r * r - 2 * r) * cos(t)) < TOL, "Z7");
	CHECK(fabs(pupil_zernike(8, r, t) - (3 * r * r * r - 2 * r) * sin(t)) < TOL, "Z8");
	CHECK(fabs(pupil_zernike(9, r, t) - (6 * pow(r, 4) - 6 * r * r + 1)) < TOL, "Z9");
	CHECK(fabs(pupil_zernike(12, r, t) - (4 * pow(r, 4) - 3 * r * r) * cos(2 * t)) < TOL, "Z12");
	CHECK(fabs(pupil_zernike(16, r, t) - (20 * pow(r, 6) - 30 * pow(r, 4) + 12 * r * r - 1)) < TOL, "Z16");
	CHECK(fabs(pupil_zernike(36, r, t) - (252 * pow(r, 10) - 630 * pow(r, 8) + 560 * pow(r, 6)
					   - 210 * pow(r, 4) + 30 * r * r - 1)) < TOL, "Z36");
	CHECK(fabs(pupil_zernike(37, r, t) - (924 * pow(r, 12) - 2772 * pow(r, 10) + 3150 * pow(r, 8)
					   - 1680 * pow(r, 6) + 420 * pow(r, 4) - 42 * r * r + 1)) < TOL, "Z37");
	CHECK(fabs(pupil_zernike(26, r, t) - pow(r, 5) * cos(5 * t)) < TOL, "Z26");
}

int main(void)
{
	test_fields();
	test_three_beam();
	test_abbe();
	test_symmetry();
	test_convergence();
	test_zernike();
	if (failures)
		printf("%d failures\n", failures);
	return failures ? 1 : 0;
}
