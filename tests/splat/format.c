/*
 * format.c - the splat input format (src/lib/fmt_splat.c): every example
 * of examples/ and a file using every statement read, are written back by
 * fmt_splat_write, read again and written again byte-identically (a
 * golden round trip: the writer prints the reader's whole state), keep
 * their values (exact doubles), and fmt_splat_mask_at paints later rects
 * over earlier ones (exact).
 */
#include "fmt_splat.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;
#define CHECK(c, ...) do { if (!(c)) { printf("FAIL: " __VA_ARGS__); printf("\n"); failures++; } } while (0)

static char *slurp(const char *path)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		die("%s:", path);
	static char buf[1 << 16];
	size_t n = fread(buf, 1, sizeof buf - 1, f);
	buf[n] = 0;
	fclose(f);
	return xstrdup(buf);
}

static void roundtrip(const char *path)
{
	struct splat_input *a = fmt_splat_read(path);
	fmt_splat_write("rt1.in", a);
	struct splat_input *b = fmt_splat_read("rt1.in");
	fmt_splat_write("rt2.in", b);
	char *s1 = slurp("rt1.in"), *s2 = slurp("rt2.in");
	CHECK(strcmp(s1, s2) == 0, "%s: second write differs", path);
	CHECK(a->mask.nrects == b->mask.nrects && a->naberr == b->naberr &&
	      a->ncutlines == b->ncutlines && a->nx == b->nx && a->ny == b->ny &&
	      a->wavelength == b->wavelength && a->na == b->na && a->sigma == b->sigma &&
	      a->source == b->source && a->defocus == b->defocus &&
	      a->vector == b->vector && a->immersion == b->immersion &&
	      a->polarization == b->polarization && a->reduction == b->reduction &&
	      strcmp(a->contour, b->contour) == 0, "%s: values changed", path);
	for (int i = 0; i < a->mask.nrects && i < b->mask.nrects; i++)
		CHECK(memcmp(&a->mask.rects[i].x1, &b->mask.rects[i].x1, 6 * sizeof(double)) == 0,
		      "%s: rect %d changed", path, i);
	free(s1);
	free(s2);
	fmt_splat_free(a);
	fmt_splat_free(b);
}

int main(void)
{
	static const char *ex[] = {"contact", "elbow", "defect", "corner-defect",
		"phase-lines", "clear-lines-2", "clear-lines-4", "clear-lines-inf",
		"ca-lines", "coma-contact", "astig-contact", "outrigger"};
	const char *top = getenv("TOP");
	if (!top)
		top = ".";
	for (size_t i = 0; i < sizeof ex / sizeof *ex; i++) {
		char path[4096];
		snprintf(path, sizeof path, "%s/examples/%s/mask.in", top, ex[i]);
		roundtrip(path);
	}
	FILE *f = fopen("all.in", "w");
	if (!f)
		die("all.in:");
	fputs("# every statement\nWAVELENGTH 0.365\nna 0.5\nannular 0.3 0.7\n"
	      "quadrupole 0.6 0.2\ndipole 0.7 0.25 y\ndefocus -0.3\n"
	      "coma 0.1 field 0.6 0.8\nastigmatism 0.2 field 1 0\nspherical 0.05\n"
	      "curvature 0.1 field 0 1\ndistortion 0.01 field 0.5 0.5\nzernike 9 0.02\n"
	      "background 0.245 180\nwindow -1 1 -2 2\nrect 0.5 0.5 -0.5 -0.5\n"
	      "rect 0 0 1 1 0.5 90\ngrid 11 21\ncontour \"out file.cont\"\n"
	      "cutline -1 0 1 0 5 c1.2D\ncutline 0 -2 0 2 7 c2.2D\n", f);
	fshut(f, "all.in");
	roundtrip("all.in");
	/* the vector statements, and reduction inf */
	f = fopen("vec.in", "w");
	if (!f)
		die("vec.in:");
	fputs("imaging vector\nimmersion 1.44\nna 1.35\npolarization tm\nreduction inf\n"
	      "window 0 1 0 1\n", f);
	fshut(f, "vec.in");
	roundtrip("vec.in");
	{
		char path[4096];
		snprintf(path, sizeof path, "%s/examples/arf-immersion-lines/mask-te.in", top);
		roundtrip(path);
		struct splat_input *v = fmt_splat_read("vec.in");
		CHECK(v->vector && v->immersion == 1.44 && v->polarization == SPLAT_POL_TM &&
		      isinf(v->reduction), "vector statements not read");
		fmt_splat_free(v);
	}
	struct splat_input *in = fmt_splat_read("all.in");
	CHECK(in->source == SPLAT_SRC_DIPOLE && in->dipole_y == 1, "last source wins");
	CHECK(in->naberr == 6 && in->aberr[5].kind == SPLAT_AB_ZERNIKE && in->aberr[5].zernike == 9,
	      "aberrations in file order");
	CHECK(in->mask.rects[0].x1 == -0.5 && in->mask.rects[0].y2 == 0.5, "rect corners sorted");
	CHECK(strcmp(in->contour, "out file.cont") == 0, "quoted contour name");
	double t, ph;
	fmt_splat_mask_at(&in->mask, 0.25, 0.25, &t, &ph);
	CHECK(t == 0.5 && ph == 90, "later rect paints over the earlier one");
	fmt_splat_mask_at(&in->mask, -0.25, -0.25, &t, &ph);
	CHECK(t == 1 && ph == 0, "first rect");
	fmt_splat_mask_at(&in->mask, -0.9, 1.5, &t, &ph);
	CHECK(t == 0.245 && ph == 180, "background");
	fmt_splat_free(in);
	return failures ? 1 : 0;
}
