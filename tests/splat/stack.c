/*
 * stack.c - checks splat's image stack (the image inside the resist,
 * splat(5)'s resist statement) against results that do not
 * come from its TCC code:
 *   1. an Abbe summation written here - its own mask coefficients, its
 *      own pupil with angles, its own depth phase
 *      W_z = (z / lambda)(sqrt(n^2 - lambda^2 |f|^2) - n), its own source
 *      integration (rows cut at every pupil edge) - against every plane
 *      of a stack at NA 0.6 with partial coherence, defocus and coma
 *      (1e-6, the accuracy asked);
 *   2. with index n = 1 the depth phase is the defocus phase, so plane z
 *      of a stack at defocus d equals the single image at defocus d + z
 *      (1e-12 at equal quadrature orders: rounding only);
 *   3. the z = 0 plane is today's image: identical to rounding (1e-15) at
 *      equal quadrature orders, and within the quadrature error (1e-7;
 *      hopkins.c measures 5e-8 for a 4x change) with each one's defaults;
 *   4. paraxial sanity: at NA 0.1 the plane at depth z matches the image
 *      at defocus z / n (1e-3; the fourth-order difference of the two
 *      phases is ~1e-4 waves here);
 *   5. a clear field is exactly 1 at every depth (1e-12), and the image
 *      does change through the film at NA 0.6 (by more than 1e-2).
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

/* Every plane of the input on its grid (nplanes * nx * ny values), with
 * quadrature orders (0: defaults). */
static double *planes(const struct splat_input *in, int no, int ni, int *np)
{
	struct spectrum *sp = splat_spectrum(in, no, ni, NULL);
	if (!sp)
		die("no light");
	size_t n = (size_t)in->nx * in->ny;
	double *z = xreallocarray(NULL, n * (size_t)sp->nplanes, sizeof *z);
	const struct splat_mask *m = &in->mask;
	for (int k = 0; k < sp->nplanes; k++) {
		struct spectrum v = spectrum_plane(sp, k);
		image_grid(&v, m->xmin, m->xmax, m->ymin, m->ymax, in->nx, in->ny, z + k * n);
	}
	*np = sp->nplanes;
	spectrum_free(sp);
	return z;
}

static double maxdiff(const double *a, const double *b, size_t n)
{
	double d = 0;
	for (size_t i = 0; i < n; i++)
		d = fmax(d, fabs(a[i] - b[i]));
	return d;
}

/* The default quadrature orders of an input (those of its deepest plane
 * for a stack). */
static void orders_of(const struct splat_input *in, int *no, int *ni)
{
	struct pupil p;
	pupil_init(&p, in);
	quad_default(&p, no, ni);
}

/* ---- 1. Abbe summation with the depth phase ---- */

struct arect { double x1, y1, x2, y2, t, deg; };
static const struct arect AR[] = {
	{-0.3, -0.25, 0.25, 0.3, 1, 0},
	{0.4, -0.6, 0.55, 0.5, 0.6, 180},
};
enum { NAR = 2 };
static const double AX0 = -0.8, ALX = 1.6, AY0 = -0.7, ALY = 1.4;
static const double ALAMBDA = 0.365, ANA = 0.6, ASIGMA = 0.4;
static const double ADEF = 0.15, ACOMA = 0.15, AHX = 1, AHY = 0;
static const double ATHICK = 1.2, AINDEX = 1.7;
enum { ANPL = 4 };      /* planes at depths 0, 0.4, 0.8, 1.2 */

static double complex abbe_coef(int m, int n)
{
	double complex c = 0;
	for (int k = 0; k < NAR; k++) {
		const struct arect *r = &AR[k];
		double complex cx, cy;
		/* (1/L) integral of exp(-2 pi i q x / L) over [a, b] */
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

/* The pupil with angles, defocus and coma, and the wave's extra phase at
 * depth z in the resist; 0 outside NA. */
static double complex abbe_pupil(double gx, double gy, double z)
{
	double R = ANA / ALAMBDA, g = hypot(gx, gy);
	if (g > R)
		return 0;
	double rho = g / R, th = atan2(gy, gx), thh = atan2(AHY, AHX), h = hypot(AHX, AHY);
	double w = ACOMA * h * rho * rho * rho * cos(th - thh);
	w += ADEF / ALAMBDA * (sqrt(1 - ALAMBDA * ALAMBDA * g * g) - 1);
	/* the wave travels at sin(theta) = lambda g / n in the resist: its
	 * path to depth z is z cos(theta) n / lambda waves, less the axial
	 * wave's z n / lambda */
	double st = ALAMBDA * g / AINDEX;
	w += z * AINDEX / ALAMBDA * (sqrt(1 - st * st) - 1);
	return cexp(2 * M_PI * I * w);
}

enum { AMAXO = 96, ANPT = 4 };
struct abbe {
	int n;
	double fx[AMAXO], fy[AMAXO];
	double complex c[AMAXO];
	double px[ANPT * ANPT], py[ANPT * ANPT];
	double complex ep[ANPT * ANPT][AMAXO];     /* exp(2 pi i f.r) */
	double sum[ANPL][ANPT * ANPT];
	double norm;
	double gu[16], gw[16];
	int ng;
};

static void abbe_point(struct abbe *a, double sx, double sy, double w)
{
	double complex amp[AMAXO];
	for (int l = 0; l < ANPL; l++) {
		double z = ATHICK * l / (ANPL - 1);
		for (int k = 0; k < a->n; k++)
			amp[k] = a->c[k] * abbe_pupil(a->fx[k] + sx, a->fy[k] + sy, z);
		for (int p = 0; p < ANPT * ANPT; p++) {
			double complex e = 0;
			for (int k = 0; k < a->n; k++)
				e += amp[k] * a->ep[p][k];
			a->sum[l][p] += w * creal(e * conj(e));
		}
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
	static struct abbe a;
	a.ng = 10;
	quad_gauss(a.ng, a.gu, a.gw);
	double R = ANA / ALAMBDA, fcut = R * (1 + ASIGMA);
	for (int n = -6; n <= 6; n++)
		for (int m = -6; m <= 6; m++)
			if (hypot(m / ALX, n / ALY) < fcut) {
				if (a.n == AMAXO)
					die("stack.c: more than %d orders", AMAXO);
				a.fx[a.n] = m / ALX;
				a.fy[a.n] = n / ALY;
				a.c[a.n] = abbe_coef(m, n);
				a.n++;
			}
	for (int j = 0; j < ANPT; j++)
		for (int i = 0; i < ANPT; i++) {
			a.px[j * ANPT + i] = AX0 + ALX * (i + 0.21) / ANPT;
			a.py[j * ANPT + i] = AY0 + ALY * (j + 0.17) / ANPT;
		}
	for (int p = 0; p < ANPT * ANPT; p++)
		for (int k = 0; k < a.n; k++)
			a.ep[p][k] = cexp(2 * M_PI * I * (a.fx[k] * a.px[p] + a.fy[k] * a.py[p]));
	abbe_image(&a);

	char buf[1024];
	int len = snprintf(buf, sizeof buf, "wavelength %g\nna %g\nsigma %g\ndefocus %g\n"
			   "coma %g field %g %g\nwindow %g %g %g %g\n"
			   "resist planes %d index %g thickness %g\n",
			   ALAMBDA, ANA, ASIGMA, ADEF, ACOMA, AHX, AHY,
			   AX0, AX0 + ALX, AY0, AY0 + ALY, ANPL, AINDEX, ATHICK);
	for (int k = 0; k < NAR; k++)
		len += snprintf(buf + len, sizeof buf - (size_t)len, "rect %g %g %g %g %g %g\n",
				AR[k].x1, AR[k].y1, AR[k].x2, AR[k].y2, AR[k].t, AR[k].deg);
	struct splat_input *in = input(buf);
	struct spectrum *sp = splat_spectrum(in, 0, 0, NULL);
	CHECK(sp && sp->nplanes == ANPL, "the stack has %d planes, expected %d",
	      sp ? sp->nplanes : 0, ANPL);
	double worst = 0, lo = INFINITY, hi = 0, change = 0;
	for (int l = 0; sp && l < ANPL; l++) {
		struct spectrum v = spectrum_plane(sp, l);
		double pw = 0;
		for (int p = 0; p < ANPT * ANPT; p++) {
			double ab = a.sum[l][p] / a.norm;
			double ho = image_at(&v, a.px[p], a.py[p]);
			pw = fmax(pw, fabs(ab - ho));
			lo = fmin(lo, ab);
			hi = fmax(hi, ab);
			change = fmax(change, fabs(ab - a.sum[0][p] / a.norm));
		}
		printf("Abbe vs stack plane %d (depth %g um): max difference %.3g\n", l,
		       ATHICK * l / (ANPL - 1), pw);
		worst = fmax(worst, pw);
	}
	printf("Abbe: %d orders, intensity %.3f to %.3f, change through the film %.3f\n",
	       a.n, lo, hi, change);
	CHECK(worst <= TOL, "Abbe and the stack differ by %g", worst);
	CHECK(hi - lo > 0.1, "the Abbe test image is nearly uniform (%g to %g): a weak test",
	      lo, hi);
	CHECK(change > 1e-2, "the image hardly changes through the film (%g): a weak test",
	      change);
	spectrum_free(sp);
	fmt_splat_free(in);
}

/* ---- 2. n = 1: depth is defocus ---- */
static void test_index_one(void)
{
	const double TOL = 1e-12;     /* the same phase by two routes: rounding */
	static const char base[] = "wavelength 0.365\nna 0.6\nsigma 0.5\n"
		"coma 0.1 field 1 0\nwindow -1 1 -1 1\nrect -0.3 -0.3 0.3 0.3\n"
		"rect 0.5 -0.8 0.7 0.8 1 180\ngrid 15 15\n";
	const double d = -0.2, T = 0.6;
	enum { NP = 4 };
	char buf[1024];
	snprintf(buf, sizeof buf, "%sdefocus %g\nresist thickness %g index 1 planes %d\n",
		 base, d, T, NP);
	struct splat_input *st = input(buf);
	int no, ni, np;
	orders_of(st, &no, &ni);
	double *z = planes(st, no, ni, &np);
	double worst = 0;
	for (int k = 0; k < NP; k++) {
		snprintf(buf, sizeof buf, "%sdefocus %.17g\n", base, d + k * T / (NP - 1));
		struct splat_input *one = input(buf);
		int n1;
		double *y = planes(one, no, ni, &n1);
		double e = maxdiff(z + (size_t)k * 225, y, 225);
		printf("n = 1: plane %d vs defocus %g: %.3g\n", k, d + k * T / (NP - 1), e);
		worst = fmax(worst, e);
		free(y);
		fmt_splat_free(one);
	}
	CHECK(worst <= TOL, "n = 1: depth z and defocus d + z differ by %g", worst);
	free(z);
	fmt_splat_free(st);
}

/* ---- 3. the top plane is today's image ---- */
static void test_top_plane(void)
{
	const double SAME = 1e-15;    /* the same sums in the same order */
	const double QUAD = 1e-7;     /* quadrature error (hopkins.c, test 5: 5e-8) */
	static const char *cases[] = {
		"sigma 0.5\ndefocus 0.3\ncoma 0.2 field 0.6 0.8\n",
		"sigma 0\ndefocus -0.4\n",
		"annular 0.3 0.7\n",
	};
	for (int c = 0; c < 3; c++) {
		char buf[1024];
		snprintf(buf, sizeof buf, "%swavelength 0.365\nna 0.6\nwindow -1 1 -1.2 1.2\n"
			 "rect -0.3 -0.3 0.35 0.3\ngrid 17 13\n", cases[c]);
		struct splat_input *one = input(buf);
		strcat(buf, "resist thickness 1 index 1.7 planes 3\n");
		struct splat_input *st = input(buf);
		int no, ni, np;
		orders_of(st, &no, &ni);
		double *a = planes(st, no, ni, &np), *b = planes(one, no, ni, &np);
		double e1 = maxdiff(a, b, 17 * 13);
		free(a);
		free(b);
		a = planes(st, 0, 0, &np);
		b = planes(one, 0, 0, &np);
		double e2 = maxdiff(a, b, 17 * 13);
		printf("top plane %d vs the single image: %.3g at equal orders, %.3g with "
		       "the defaults\n", c, e1, e2);
		CHECK(e1 <= SAME, "case %d: top plane differs from the image by %g", c, e1);
		CHECK(e2 <= QUAD, "case %d: top plane differs from the default image by %g", c, e2);
		free(a);
		free(b);
		fmt_splat_free(one);
		fmt_splat_free(st);
	}
}

/* ---- 4. paraxial: depth z is defocus z / n ---- */
static void test_paraxial(void)
{
	/* the phases differ by (z lambda^3 |f|^4 / 8)(1/n - 1/n^3) waves at
	 * fourth order, ~1e-4 waves at the pupil edge at z = 20 um; a 20 um
	 * film is 0.55 of the focal depth lambda/NA^2, so the image moves */
	const double TOL = 1e-3;      /* the accuracy asked */
	const double T = 20, n = 1.7;
	enum { NP = 3 };
	static const char base[] = "wavelength 0.365\nna 0.1\nsigma 0.5\n"
		"window -6 6 -6 6\nrect -2 -2 2 2\ngrid 13 13\n";
	char buf[1024];
	snprintf(buf, sizeof buf, "%sresist thickness %g index %g planes %d\n", base, T, n, NP);
	struct splat_input *st = input(buf);
	int np;
	double *z = planes(st, 0, 0, &np);
	double worst = 0, moved = 0;
	for (int k = 1; k < NP; k++) {
		snprintf(buf, sizeof buf, "%sdefocus %.17g\n", base, k * T / (NP - 1) / n);
		struct splat_input *one = input(buf);
		int n1;
		double *y = planes(one, 0, 0, &n1);
		double e = maxdiff(z + (size_t)k * 169, y, 169);
		moved = fmax(moved, maxdiff(z + (size_t)k * 169, z, 169));
		printf("paraxial: depth %g vs defocus %g: %.3g\n", k * T / (NP - 1),
		       k * T / (NP - 1) / n, e);
		worst = fmax(worst, e);
		free(y);
		fmt_splat_free(one);
	}
	CHECK(worst <= TOL, "paraxial: depth z and defocus z/n differ by %g", worst);
	CHECK(moved > 10 * TOL, "paraxial: the image moves only %g through the film: a weak test",
	      moved);
	free(z);
	fmt_splat_free(st);
}

/* ---- 5. clear field at every depth ---- */
static void test_clear(void)
{
	const double TOL = 1e-12;
	struct splat_input *in = input("wavelength 0.365\nna 0.8\nannular 0.4 0.9\n"
				       "defocus 0.5\nspherical 0.2\nwindow 0 2 0 2\n"
				       "background clear\ngrid 5 5\n"
				       "resist thickness 2 index 1.6 planes 7\n");
	int np;
	double *z = planes(in, 0, 0, &np);
	double worst = 0;
	for (int i = 0; i < np * 25; i++)
		worst = fmax(worst, fabs(z[i] - 1));
	printf("clear field through the film: max |I - 1| %.3g\n", worst);
	CHECK(np == 7 && worst <= TOL, "clear field is not 1 at every depth (%g)", worst);
	free(z);
	fmt_splat_free(in);
}

int main(void)
{
	test_abbe();
	test_index_one();
	test_top_plane();
	test_paraxial();
	test_clear();
	if (failures)
		printf("%d failures\n", failures);
	return failures ? 1 : 0;
}
