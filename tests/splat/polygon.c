/*
 * polygon.c - the exact mask transform of polygons and unions (splat's
 * polygon path, src/splat/mask.c over poly_boundary), against results
 * that do not come from it:
 *   1. a rectangle given as a polygon has the coefficients of the rect
 *      path (separable sincs) to 1e-12, also painted between rects, over
 *      a phase-shifted background;
 *   2. a triangle against Gauss quadrature of its transform (Duffy map,
 *      24x24 points, converged far below the tolerance) at every order
 *      with |f| <= 3/um, the axes and f = 0 included: 1e-12;
 *   3. unions: overlapping rectangles in one layer equal the L-shaped
 *      polygon they cover, and four overlapping bars forming a frame (a
 *      union with a hole) equal the frame drawn as two painted rects:
 *      1e-12;
 *   4. an Abbe summation written here (its own coefficients by
 *      quadrature over triangles, its own pupil and source integration,
 *      as in hopkins.c) against the Hopkins image of splat for an
 *      L-shape and a 45-degree octagon, partially coherent, defocused,
 *      comatic: 1e-6 (the accuracy asked);
 *   5. fmt_splat_write round trip of rects, polygons, clip on and a gds
 *      statement interleaved: write -> read -> write is byte-identical and
 *      the mask coefficients are the same (exactly).
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

/* Largest difference of the coefficients of two masks (same window). */
static double coef_diff(const struct splat_mask *a, const struct splat_mask *b, double fm)
{
	struct orders *oa = mask_orders(a, fm), *ob = mask_orders(b, fm);
	double d = 0;
	if (oa->n != ob->n)
		d = INFINITY;
	for (int i = 0; i < oa->n && i < ob->n; i++)
		d = fmax(d, cabs(oa->c[i] - ob->c[i]));
	mask_orders_free(oa);
	mask_orders_free(ob);
	return d;
}

/* ---- 1. rect as polygon ---- */
static void test_rect(void)
{
	const double TOL = 1e-12;       /* the accuracy asked */
	struct splat_input *r = input("window -1.5 1.5 -1 1.2\nbackground 0.2 180\n"
				      "rect -0.5 -0.3 0.7 0.4 1 0\nrect 0.2 0.1 1.1 0.9 0.5 90\n"
				      "rect -1.2 -0.8 0 0 1 0\n");
	struct splat_input *p = input("window -1.5 1.5 -1 1.2\nbackground 0.2 180\n"
				      "rect -0.5 -0.3 0.7 0.4 1 0\n"
				      "polygon 0.2 0.1 1.1 0.1 1.1 0.9 0.2 0.9 t 0.5 90\n"
				      "rect -1.2 -0.8 0 0 1 0\n");
	double d = coef_diff(&r->mask, &p->mask, 4);
	printf("rect as polygon: max coefficient difference %.3g\n", d);
	CHECK(d <= TOL, "rect as polygon differs by %g", d);
	fmt_splat_free(r);
	fmt_splat_free(p);
}

/* ---- quadrature of the transform over a triangle ---- */
static double gu[32], gw[32];
static double au[16], aw[16];     /* the Abbe source quadrature */
enum { NG = 24 };

/* (1/A) integral over triangle abc of t e^{-2 pi i f.r} */
static double complex tri_coef(const double *a, const double *b, const double *c,
			       double fx, double fy, double area)
{
	double complex s = 0;
	double j2 = fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
	for (int i = 0; i < NG; i++) {
		double u = 0.5 * (gu[i] + 1), wu = 0.5 * gw[i];
		for (int k = 0; k < NG; k++) {
			double v = 0.5 * (gu[k] + 1), wv = 0.5 * gw[k];
			/* Duffy: r = a + u (b - a) + u v (c - b), dA = j2 u du dv */
			double x = a[0] + u * (b[0] - a[0]) + u * v * (c[0] - b[0]);
			double y = a[1] + u * (b[1] - a[1]) + u * v * (c[1] - b[1]);
			s += wu * wv * u * j2 * cexp(-2 * M_PI * I * (fx * x + fy * y));
		}
	}
	return s / area;
}

static void test_triangle(void)
{
	const double TOL = 1e-12;
	struct splat_input *in = input("window -1 1.5 -1 1\n"
				       "polygon -0.7 -0.4 1.1 -0.2 0.1 0.8 t 1 0\n");
	double A[2] = {-0.7, -0.4}, B[2] = {1.1, -0.2}, C[2] = {0.1, 0.8};
	struct orders *o = mask_orders(&in->mask, 3);
	double d = 0;
	int axes = 0;
	for (int i = 0; i < o->n; i++) {
		double complex q = tri_coef(A, B, C, o->fx[i], o->fy[i], o->lx * o->ly);
		d = fmax(d, cabs(q - o->c[i]));
		axes += o->m[i] == 0 || o->k[i] == 0;
	}
	printf("triangle: %d orders (%d on the axes), max difference from quadrature %.3g\n",
	       o->n, axes, d);
	CHECK(d <= TOL, "triangle transform differs from quadrature by %g", d);
	CHECK(o->n > 50 && axes > 10, "too few orders tested");
	mask_orders_free(o);
	fmt_splat_free(in);
}

/* ---- 3. unions ---- */
static void replace_shapes(struct splat_layer *l, const double *xy, int npoly)
{
	poly_set_free(&l->shapes);
	for (int i = 0; i < npoly; i++)
		poly_set_add(&l->shapes, xy + 8 * i, 4);
}

static void test_union(void)
{
	const double TOL = 1e-12;
	/* L = [-1,1]x[-1,0] U [-1,0]x[-1,1], from two overlapping rectangles */
	struct splat_input *a = input("window -2 2 -2 2\nbackground 0.1 0\n"
				      "polygon -1 -1 1 -1 1 0 0 0 0 1 -1 1 t 1 0\n");
	struct splat_input *b = input("window -2 2 -2 2\nbackground 0.1 0\n"
				      "polygon 0 0 1 0 1 1 t 1 0\n");
	static const double two[] = {-1, -1, 1, -1, 1, 0, -1, 0,
				     -1, -1, -1, 1, 0, 1, 0, -1};  /* second one clockwise */
	replace_shapes(&b->mask.layers[0], two, 2);
	double d = coef_diff(&a->mask, &b->mask, 3);
	printf("union of overlapping rectangles vs the L polygon: %.3g\n", d);
	CHECK(d <= TOL, "union of overlaps differs from the L polygon by %g", d);
	fmt_splat_free(b);
	/* frame: four overlapping bars, against outer clear rect minus inner dark rect */
	struct splat_input *f = input("window -2 2 -2 2\nbackground 0.1 0\n"
				      "rect -1.5 -1.5 1.5 1.5 1 0\nrect -1 -1 1 1 0.1 0\n");
	struct splat_input *g = input("window -2 2 -2 2\nbackground 0.1 0\n"
				      "polygon 0 0 1 0 1 1 t 1 0\n");
	/* bottom, top, left, right bars: the corners overlap */
	static const double bars2[] = {-1.5, -1.5, 1.5, -1.5, 1.5, -1, -1.5, -1,
				       -1.5, 1, 1.5, 1, 1.5, 1.5, -1.5, 1.5,
				       -1.5, -1.5, -1, -1.5, -1, 1.5, -1.5, 1.5,
				       1, -1.5, 1.5, -1.5, 1.5, 1.5, 1, 1.5};
	replace_shapes(&g->mask.layers[0], bars2, 4);
	d = coef_diff(&f->mask, &g->mask, 3);
	printf("frame of four overlapping bars (a hole) vs painted rects: %.3g\n", d);
	CHECK(d <= TOL, "union with a hole differs by %g", d);
	/* the same union from the bars given in the other order */
	static const double bars3[] = {1, -1.5, 1.5, -1.5, 1.5, 1.5, 1, 1.5,
				       -1.5, -1.5, -1, -1.5, -1, 1.5, -1.5, 1.5,
				       -1.5, 1, 1.5, 1, 1.5, 1.5, -1.5, 1.5,
				       -1.5, -1.5, 1.5, -1.5, 1.5, -1, -1.5, -1};
	struct splat_input *h = input("window -2 2 -2 2\nbackground 0.1 0\n"
				      "polygon 0 0 1 0 1 1 t 1 0\n");
	replace_shapes(&h->mask.layers[0], bars3, 4);
	d = coef_diff(&g->mask, &h->mask, 3);
	CHECK(d == 0, "the union depends on the order of its shapes (%g)", d);
	fmt_splat_free(a);
	fmt_splat_free(f);
	fmt_splat_free(g);
	fmt_splat_free(h);
}

/* ---- 4. Abbe summation ---- */
static const double ALX = 3, ALY = 3;          /* window (-1.5,1.5)^2 */
static const double ALAMBDA = 0.436, ANA = 0.28, ASIGMA = 0.5;
static const double ADEF = 0.5, ACOMA = 0.3, AHX = 0.6, AHY = 0.8;

struct tri { double a[2], b[2], c[2]; };
static struct tri tris[16];
static int ntri;
static double complex ttau;     /* feature transmission, dark background */

static double complex abbe_coef(double fx, double fy)
{
	double complex c = 0;
	for (int k = 0; k < ntri; k++)
		c += tri_coef(tris[k].a, tris[k].b, tris[k].c, fx, fy, ALX * ALY);
	return ttau * c;
}

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

enum { AMAXO = 64, ANPT = 4 };
struct abbe {
	int n;
	double fx[AMAXO], fy[AMAXO];
	double complex c[AMAXO];
	double px[ANPT * ANPT], py[ANPT * ANPT];
	double complex ph[ANPT * ANPT][AMAXO];
	double sum[ANPT * ANPT];
	double norm;
	int ng;
};

static void abbe_point(struct abbe *a, double sx, double sy, double w)
{
	double complex amp[AMAXO];
	for (int k = 0; k < a->n; k++)
		amp[k] = a->c[k] * abbe_pupil(a->fx[k] + sx, a->fy[k] + sy);
	for (int p = 0; p < ANPT * ANPT; p++) {
		double complex e = 0;
		for (int k = 0; k < a->n; k++)
			e += amp[k] * a->ph[p][k];
		a->sum[p] += w * creal(e * conj(e));
	}
	a->norm += w;
}

/* abbe_rows calls this at every source node. */
static void abbe_node(void *ctx, double sx, double sy, double w)
{
	abbe_point(ctx, sx, sy, w);
}

static void abbe_image(struct abbe *a)
{
	double R = ANA / ALAMBDA;
	abbe_rows(a->n, a->fx, a->fy, R, ASIGMA * R, a->ng, au, aw, abbe_node, a);
}

static void abbe_case(const char *name, const char *poly)
{
	const double TOL = 1e-6;        /* the accuracy asked */
	static struct abbe a;
	memset(&a, 0, sizeof a);
	a.ng = 12;
	double R = ANA / ALAMBDA, fm = R * (1 + ASIGMA);
	for (int n = -6; n <= 6; n++)
		for (int m = -6; m <= 6; m++)
			if (hypot(m / ALX, n / ALY) < fm && a.n < AMAXO) {
				a.fx[a.n] = m / ALX;
				a.fy[a.n] = n / ALY;
				a.c[a.n] = abbe_coef(a.fx[a.n], a.fy[a.n]);
				a.n++;
			}
	for (int j = 0; j < ANPT; j++)
		for (int i = 0; i < ANPT; i++) {
			int p = j * ANPT + i;
			a.px[p] = -1.2 + 2.4 * i / (ANPT - 1) + 0.013;
			a.py[p] = -1.2 + 2.4 * j / (ANPT - 1) - 0.029;
			for (int k = 0; k < a.n; k++)
				a.ph[p][k] = cexp(2 * M_PI * I * (a.fx[k] * a.px[p] + a.fy[k] * a.py[p]));
		}
	abbe_image(&a);
	char buf[2048];
	snprintf(buf, sizeof buf, "wavelength %g\nna %g\nsigma %g\ndefocus %g\n"
		 "coma %g field %g %g\nwindow -1.5 1.5 -1.5 1.5\n%s\n",
		 ALAMBDA, ANA, ASIGMA, ADEF, ACOMA, AHX, AHY, poly);
	struct splat_input *in = input(buf);
	struct spectrum *sp = splat_spectrum(in, 0, 0, NULL);
	double worst = 0, peak = 0;
	for (int p = 0; p < ANPT * ANPT; p++) {
		double ab = a.sum[p] / a.norm, ho = image_at(sp, a.px[p], a.py[p]);
		worst = fmax(worst, fabs(ab - ho));
		peak = fmax(peak, ab);
	}
	printf("Abbe vs Hopkins, %s (%d orders, peak %.3f): max difference %.3g\n",
	       name, a.n, peak, worst);
	CHECK(worst <= TOL, "%s: Abbe and Hopkins differ by %g", name, worst);
	CHECK(peak > 0.1, "%s: the test image is nearly dark (peak %g)", name, peak);
	spectrum_free(sp);
	fmt_splat_free(in);
}

static void test_abbe(void)
{
	/* L-shape, 180-degree phase, as four triangles */
	static const struct tri L[] = {
		{{-0.9, -0.8}, {0.8, -0.8}, {0.8, -0.2}}, {{-0.9, -0.8}, {0.8, -0.2}, {-0.9, -0.2}},
		{{-0.9, -0.2}, {-0.3, -0.2}, {-0.3, 0.9}}, {{-0.9, -0.2}, {-0.3, 0.9}, {-0.9, 0.9}}};
	ntri = 4;
	memcpy(tris, L, sizeof L);
	ttau = cexp(I * M_PI);
	abbe_case("L-shape", "polygon -0.9 -0.8 0.8 -0.8 0.8 -0.2 -0.3 -0.2 -0.3 0.9 -0.9 0.9 t 1 180");
	/* octagon with 45-degree sides, transmission 0.7 at 90 degrees, as a fan */
	double v[16];
	char poly[512];
	int len = snprintf(poly, sizeof poly, "polygon");
	for (int k = 0; k < 8; k++) {
		double ang = M_PI / 8 + k * M_PI / 4;
		v[2 * k] = 0.1 + 0.9 * cos(ang);
		v[2 * k + 1] = -0.05 + 0.9 * sin(ang);
	}
	/* the vertices as printed, so both sides see the same polygon */
	for (int k = 0; k < 16; k++) {
		len += snprintf(poly + len, sizeof poly - (size_t)len, " %.17g", v[k]);
		v[k] = strtod(strrchr(poly, ' ') + 1, NULL);
	}
	snprintf(poly + len, sizeof poly - (size_t)len, " t 0.7 90");
	ntri = 8;
	for (int k = 0; k < 8; k++) {
		int j = (k + 1) % 8;
		tris[k] = (struct tri){{0.1, -0.05}, {v[2 * k], v[2 * k + 1]}, {v[2 * j], v[2 * j + 1]}};
	}
	ttau = 0.7 * cexp(I * M_PI / 2);
	abbe_case("octagon", poly);
}

/* ---- 5. round trip ---- */
static char *slurp(const char *path)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		die("%s:", path);
	static char buf[2][65536];
	static int k;
	char *b = buf[k++ % 2];
	size_t n = fread(b, 1, sizeof buf[0] - 1, f);
	b[n] = '\0';
	fclose(f);
	return b;
}

static void test_roundtrip(void)
{
	const char *top = getenv("TOP");
	char text[8192];
	snprintf(text, sizeof text, "window -3 3 -3 3\nbackground 0.2 90\nclip on\n"
		 "rect -2 -2 1 1\npolygon -2.5 -1 4 -1 0 2.5 t 0.5 180\n"
		 "gds \"%s/tests/gds/data/boxes.gds\" layer 1/0 cell TOP 1 0\n"
		 "rect 0 0 0.5 0.5 0 0\npolygon 0 0 1 0 1 1 0 1\n", top ? top : ".");
	struct splat_input *a = input(text);
	fmt_splat_write("rt1.in", a);
	struct splat_input *b = fmt_splat_read("rt1.in");
	fmt_splat_write("rt2.in", b);
	char *s1 = slurp("rt1.in"), *s2 = slurp("rt2.in");
	CHECK(strcmp(s1, s2) == 0, "write -> read -> write differs");
	CHECK(strstr(s1, "polygon") && strstr(s1, "gds") && strstr(s1, "clip on"),
	      "the written file lacks a statement:\n%s", s1);
	double d = coef_diff(&a->mask, &b->mask, 3);
	CHECK(d == 0, "the mask read back differs by %g", d);
	fmt_splat_free(a);
	fmt_splat_free(b);
}

int main(void)
{
	quad_gauss(NG, gu, gw);
	quad_gauss(12, au, aw);
	test_rect();
	test_triangle();
	test_union();
	test_abbe();
	test_roundtrip();
	return failures ? 1 : 0;
}
