/*
 * abbe.c - splat's Abbe method (src/splat/abbe.c) against the exact
 * Hopkins sum (tcc.c) on the same inputs, image on the grid:
 *   1. the partial cover of a square cell by a straight edge
 *      (abbe_cover) against a direct integral of the covered length
 *      (1e-9), at many angles and distances;
 *   2. clear field: exactly 1 (1e-12) for a disc, an annulus, poles and
 *      a source wider than the pupil, with defocus and coma;
 *   3. coherent (sigma 0): the same orders through the same pupil, one
 *      source point, so the two agree to rounding (1e-12);
 *   4. partially coherent, every source shape and the pupil phases: a
 *      dark-field contact, lines and spaces, a polygon with a defect, an
 *      annular, a quadrupole, a dipole and a sigma 1.3 source, defocus
 *      with coma and spherical aberration, a three-plane image stack (resist
 *      statement): max |I_abbe - I_hopkins| < 1e-3 (the accuracy asked; with the
 *      default source cells it is about 1e-4; printed), and 4 times
 *      finer cells come 4 times closer (the error is second order in the
 *      cell: checked as at least 2.5 times closer on the contact);
 *   5. image_grid_fft (the Abbe output's grid by FFT) against image_grid's
 *      direct sums: 1e-12, on grids whose period has 40, 29 (a prime:
 *      Bluestein), 1 and 12 points, the window off the origin.
 */
#include "fmt_splat.h"
#include "splat.h"
#include "util.h"
#include "splattest.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* max |I_abbe - I_hopkins| over every plane of the grid; cells: abbe's
 * cells across the smallest source disc (0: default) */
static double compare(const struct splat_input *in, int cells, double *imax)
{
	struct spectrum *h = splat_spectrum_method(in, SPLAT_HOPKINS, 0, 0, NULL);
	struct spectrum *a = splat_spectrum_method(in, SPLAT_ABBE, cells, 0, NULL);
	if (!h || !a)
		die("no light");
	size_t n = (size_t)in->nx * in->ny;
	double *zh = xreallocarray(NULL, n, sizeof *zh), *za = xreallocarray(NULL, n, sizeof *za);
	const struct splat_mask *m = &in->mask;
	double d = 0, top = 0;
	for (int k = 0; k < h->nplanes; k++) {
		struct spectrum vh = spectrum_plane(h, k), va = spectrum_plane(a, k);
		image_grid(&vh, m->xmin, m->xmax, m->ymin, m->ymax, in->nx, in->ny, zh);
		image_grid(&va, m->xmin, m->xmax, m->ymin, m->ymax, in->nx, in->ny, za);
		for (size_t i = 0; i < n; i++) {
			if (fabs(zh[i] - za[i]) > d)
				d = fabs(zh[i] - za[i]);
			if (zh[i] > top)
				top = zh[i];
		}
	}
	if (imax)
		*imax = top;
	free(zh);
	free(za);
	spectrum_free(h);
	spectrum_free(a);
	return d;
}

/* ---- 1. the cover of a cell ---- */
static void test_cover(void)
{
	double worst = 0;
	for (int ia = 0; ia <= 24; ia++) {
		double t = M_PI / 2 * ia / 24, ux = cos(t), uy = sin(t);
		for (int id = -12; id <= 12; id++) {
			double d = 0.75 * id / 10;       /* beyond the corners too */
			/* the square [-1/2, 1/2]^2 below the line ux x + uy y = d:
			 * the covered length in y at each x, by the midpoint rule
			 * (exact where the length is linear in x; 20000 pieces) */
			int nstep = 20000;
			double area = 0;
			for (int k = 0; k < nstep; k++) {
				double x = -0.5 + (k + 0.5) / nstep, len;
				if (uy < 1e-15)
					len = ux * x < d ? 1 : 0;
				else {
					double y = (d - ux * x) / uy;
					len = y < -0.5 ? 0 : y > 0.5 ? 1 : y + 0.5;
				}
				area += len / nstep;
			}
			double c = abbe_cover(d, ux, uy, 1);
			if (fabs(c - area) > worst)
				worst = fabs(c - area);
		}
	}
	/* the midpoint rule is exact on the linear parts, 1e-9 at the kinks */
	CHECK(worst < 1e-8, "abbe_cover off the direct integral by %.3g", worst);
}

/* ---- 2. clear field ---- */
static void test_clear(void)
{
	static const char *srcs[] = {"sigma 0.5", "annular 0.3 0.7", "quadrupole 0.6 0.2",
				     "dipole 0.7 0.2 y", "sigma 1.3"};
	for (int k = 0; k < 5; k++) {
		char buf[512];
		snprintf(buf, sizeof buf, "%s\ndefocus 1\ncoma 0.2 field 1 0\n"
			 "window 0 3 0 2\nbackground clear\ngrid 9 7\n", srcs[k]);
		struct splat_input *in = input(buf);
		struct spectrum *a = splat_spectrum_method(in, SPLAT_ABBE, 0, 0, NULL);
		double z[63], d = 0;
		image_grid(a, 0, 3, 0, 2, 9, 7, z);
		for (int i = 0; i < 63; i++)
			if (fabs(z[i] - 1) > d)
				d = fabs(z[i] - 1);
		CHECK(d < 1e-12, "%s: clear field off 1 by %.3g", srcs[k], d);
		spectrum_free(a);
		fmt_splat_free(in);
	}
}

/* ---- 3. coherent ---- */
static void test_coherent(void)
{
	struct splat_input *in = input("sigma 0\ndefocus 0.8\nspherical 0.2\n"
				       "window -2 2 -2 2\nbackground dark\n"
				       "rect -0.6 -0.6 0.6 0.6\nrect 1 -0.2 1.4 0.2 1 180\n"
				       "grid 33 33\n");
	double d = compare(in, 0, NULL);
	printf("abbe: coherent: %.3g\n", d);
	CHECK(d < 1e-12, "coherent: abbe off hopkins by %.3g", d);
	fmt_splat_free(in);
}

/* ---- 4. partially coherent ---- */
static void test_partial(void)
{
	static const struct { const char *name, *text; } cases[] = {
		{"contact", "wavelength 0.436\nna 0.28\nsigma 0.5\nbackground dark\n"
			    "window -2.5 2.5 -2.5 2.5\nrect -0.625 -0.625 0.625 0.625\ngrid 41 41\n"},
		{"lines", "wavelength 0.365\nna 0.6\nsigma 0.6\n"
			  "window 0 1.6 0 0.4\nrect 0 0 0.4 0.4\nrect 0.8 0 1.2 0.4\ngrid 33 9\n"},
		{"polygon and defect", "wavelength 0.365\nna 0.5\nsigma 0.5\n"
			  "window 0 3 0 3\npolygon 0.5 0.5 2.5 0.5 2.5 1.2 1.2 1.2 1.2 2.5 0.5 2.5\n"
			  "rect 1.8 1.8 2.0 2.0\ngrid 31 31\n"},
		{"annular", "wavelength 0.365\nna 0.6\nannular 0.4 0.8\n"
			    "window -1.5 1.5 -1.5 1.5\nbackground dark\nrect -0.3 -0.3 0.3 0.3\n"
			    "grid 31 31\n"},
		{"quadrupole", "wavelength 0.365\nna 0.6\nquadrupole 0.6 0.2\n"
			       "window -1 1 -1 1\nrect -0.25 -1 0.25 1\nrect -1 -0.25 1 0.25\n"
			       "grid 21 21\n"},
		{"source wider than the pupil", "wavelength 0.365\nna 0.6\nsigma 1.3\n"
			  "window -1 1 -1 1\nrect -0.3 -0.3 0.3 0.3\ngrid 21 21\n"},
		{"dipole", "wavelength 0.365\nna 0.6\ndipole 0.7 0.2 x\n"
			   "window 0 1.2 0 0.6\nrect 0 0 0.3 0.6\ngrid 25 13\n"},
		{"defocus and aberrations", "wavelength 0.365\nna 0.5\nsigma 0.5\ndefocus 0.6\n"
			   "coma 0.15 field 1 0\nspherical 0.1\nzernike 5 0.05\n"
			   "window -1.5 1.5 -1.5 1.5\nbackground dark\nrect -0.4 -0.4 0.4 0.4\n"
			   "grid 31 31\n"},
		{"stack", "wavelength 0.365\nna 0.5\nsigma 0.5\ndefocus -0.3\n"
			  "resist thickness 1 index 1.7 planes 3\n"
			  "window -1.5 1.5 -1.5 1.5\nbackground dark\nrect -0.4 -0.4 0.4 0.4\n"
			  "grid 21 21\n"},
	};
	for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
		struct splat_input *in = input(cases[k].text);
		double top, d = compare(in, 0, &top);
		printf("abbe: %s: max |abbe - hopkins| %.3g (largest intensity %.3g)\n",
		       cases[k].name, d, top);
		CHECK(d < 1e-3, "%s: abbe off hopkins by %.3g", cases[k].name, d);
		CHECK(top > 0.05, "%s: too dark to test (%.3g)", cases[k].name, top);
		if (k == 0) {
			double d10 = compare(in, 10, NULL), d40 = compare(in, 40, NULL);
			printf("abbe: contact: 10 cells %.3g, 40 cells %.3g\n", d10, d40);
			CHECK(d10 > 2.5 * d40, "contact: cells 4 times finer gain only %.3g",
			      d10 / d40);
		}
		fmt_splat_free(in);
	}
}

/* ---- 5. the grid by FFT ---- */
static void test_grid_fft(void)
{
	static const int sizes[][2] = {{41, 30}, {2, 13}, {30, 2}, {13, 41}};
	for (int k = 0; k < 4; k++) {
		int nx = sizes[k][0], ny = sizes[k][1];
		char buf[512];
		snprintf(buf, sizeof buf, "wavelength 0.365\nna 0.6\nsigma 0.5\ndefocus 0.3\n"
			 "window -0.7 1.6 0.3 2.2\nrect -0.2 0.5 0.4 1.7\nrect 0.9 1.0 1.3 1.4 1 90\n"
			 "grid %d %d\n", nx, ny);
		struct splat_input *in = input(buf);
		struct spectrum *a = splat_spectrum_method(in, SPLAT_ABBE, 10, 0, NULL);
		size_t n = (size_t)nx * ny;
		double *z1 = xreallocarray(NULL, n, sizeof *z1), *z2 = xreallocarray(NULL, n, sizeof *z2);
		image_grid(a, -0.7, 1.6, 0.3, 2.2, nx, ny, z1);
		image_grid_fft(a, -0.7, 0.3, nx, ny, z2);
		double d = 0, top = 0;
		for (size_t i = 0; i < n; i++) {
			if (fabs(z1[i] - z2[i]) > d)
				d = fabs(z1[i] - z2[i]);
			if (z1[i] > top)
				top = z1[i];
		}
		CHECK(d < 1e-12 && top > 0.005, "grid %d x %d: FFT off the direct sums by %.3g "
		      "(largest %.3g)", nx, ny, d, top);
		free(z1);
		free(z2);
		spectrum_free(a);
		fmt_splat_free(in);
	}
}

int main(void)
{
	util_setprog("abbe");
	test_cover();
	test_clear();
	test_coherent();
	test_partial();
	test_grid_fft();
	if (failures) {
		printf("%d failures\n", failures);
		return 1;
	}
	return 0;
}
