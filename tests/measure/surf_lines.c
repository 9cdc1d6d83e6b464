/*
 * tests/measure/surf_lines.c - the library's many-lines geometry
 * (surf_lines.h) against the one-line functions and known layouts:
 *   - surf_lines_spans against surf_line_spans called line by line, on a
 *     rough height field, along x and along y, with 1 and 3 threads: the
 *     same spans, bit for bit;
 *   - surf_sample_lines on meshes of known rows: 100 rows from the box
 *     side (1100 lines, 11 per row, each 11th the row's own coordinate
 *     bit for bit), 3000 rows (the 3000 rows themselves), rows at the
 *     middles of 1500 bands (those middles), jittered rows (1024 lines at
 *     the middles of 1024 equal parts), 70000 rows (more than 65536: the
 *     65536 middles); spacing even to 1e-12 um;
 *   - surf_regions on a square hole with a square island in it (one
 *     region, the annulus: 0.95^2 - 0.45^2 within 1e-3, centroid (0, 0)
 *     within 1e-6) and on a hole cut by the box edge (marked edge).
 */
#include "surf_lines.h"
#include "par.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int failures;
#define CHECK(c, ...) do { if (!(c)) { printf("FAIL: " __VA_ARGS__); printf("\n"); failures++; } } while (0)

static unsigned long long rng = 88172645463325252ULL;
static double urand(void)
{
	rng ^= rng << 13;
	rng ^= rng >> 7;
	rng ^= rng << 17;
	return (double)(rng >> 11) / 9007199254740992.0;
}

/* Quads of a height field z(x, y) on nx x ny cells over the box, the
 * rows of vertices at y[0..ny] (x evenly spaced); z from f. */
static struct surf *height_field(int nx, int ny, const double *y, double (*f)(double, double))
{
	double box[6] = {-1, 1, -1, 1, -1, 0};
	struct surf *s = surf_new(box);
	double h = 2.0 / nx;
	for (int i = 0; i < nx; i++)
		for (int j = 0; j < ny; j++) {
			double x0 = -1 + i * h, x1 = -1 + (i + 1) * h, y0 = y[j], y1 = y[j + 1];
			double a[3] = {x0, y0, f(x0, y0)}, b[3] = {x1, y0, f(x1, y0)};
			double c[3] = {x1, y1, f(x1, y1)}, d[3] = {x0, y1, f(x0, y1)};
			double t1[9] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]};
			double t2[9] = {a[0], a[1], a[2], c[0], c[1], c[2], d[0], d[1], d[2]};
			surf_add(s, t1);
			surf_add(s, t2);
		}
	surf_index(s);
	return s;
}

static double *even_rows(int n, double off)
{
	double *y = xreallocarray(NULL, (size_t)n + 1, sizeof *y);
	for (int j = 0; j <= n; j++)
		y[j] = -1 + 2.0 * (j + off) / n;
	y[0] = -1;
	y[n] = 1;
	return y;
}

static double rough(double x, double y)
{
	return -0.5 + 0.4 * sin(7 * x + 2 * sin(5 * y)) * cos(3 * y - x) + 0.05 * sin(41 * x * y);
}

static double annulus(double x, double y)
{
	double m = fmax(fabs(x), fabs(y));
	return (m < 0.22 || m > 0.48) ? 0 : -1;
}

/* a square hole reaching past the box's left side */
static double cut_hole(double x, double y) { return (x < -0.7 && fabs(y) < 0.2) ? -1 : 0; }

static void spans_check(void)
{
	double *y = even_rows(60, 0);
	struct surf *s = height_field(60, 60, y, rough);
	struct surf_section sec;
	surf_section(s, -0.5, &sec);
	enum { NL = 300 };
	double c[NL];
	for (int l = 0; l < NL; l++)
		c[l] = -1 + 2 * (l + urand()) / NL;
	for (int axis = 0; axis < 2; axis++)
		for (int t = 1; t <= 3; t += 2) {
			par_set_threads(t);
			struct surf_line *all = surf_lines_spans(s, &sec, axis, c, NL);
			struct surf_span *sp = NULL;
			size_t cap = 0, total = 0;
			for (int l = 0; l < NL; l++) {
				size_t m = surf_line_spans(s, &sec, axis, c[l], &sp, &cap);
				total += m;
				int same = m == all[l].n;
				for (size_t k = 0; same && k < m; k++)
					same = sp[k].lo == all[l].sp[k].lo && sp[k].hi == all[l].sp[k].hi &&
					       sp[k].resist == all[l].sp[k].resist;
				CHECK(same, "axis %d, %d threads, line %d: spans differ from surf_line_spans",
				      axis, t, l);
			}
			CHECK(total > 2 * NL, "axis %d: only %zu spans: the field is not rough", axis, total);
			free(sp);
			surf_lines_free(all, NL);
		}
	par_set_threads(0);
	surf_section_free(&sec);
	surf_free(s);
	free(y);
}

/* surf_sample_lines on a field whose rows are y[0..ny]: expects n lines,
 * rows rows, and (if rows) every per-th line on row first + k. */
static void sample_check(const char *name, int ny, const double *y, size_t want_n,
			 size_t want_rows, int per, int first)
{
	struct surf *s = height_field(4, ny, y, annulus);
	size_t n, rows;
	double *c = surf_sample_lines(s, 1, 1024, 65536, &n, &rows);
	CHECK(n == want_n && rows == want_rows, "%s: %zu lines on %zu rows, expected %zu on %zu",
	      name, n, rows, want_n, want_rows);
	if (n == want_n) {
		double dl = 2.0 / (double)n;
		for (size_t j = 0; j < n; j++) {
			double expect = rows ? y[first] + (double)j * dl : -1 + (j + 0.5) * dl;
			if (rows && j % (size_t)per == 0)
				CHECK(c[j] == y[first + j / (size_t)per], "%s: line %zu is not row %zu",
				      name, j, first + j / (size_t)per);
			CHECK(fabs(c[j] - expect) < 1e-12, "%s: line %zu at %.17g, expected %.17g",
			      name, j, c[j], expect);
		}
	}
	free(c);
	surf_free(s);
}

static void regions_check(void)
{
	double *y = even_rows(40, 0);
	struct surf *s = height_field(40, 40, y, annulus);
	struct surf_section sec;
	surf_section(s, -0.5, &sec);
	struct surf_region *reg;
	size_t n = surf_regions(s, &sec, 2000, &reg);
	double want = 0.95 * 0.95 - 0.45 * 0.45;
	CHECK(n == 1, "annulus: %zu regions, expected 1", n);
	if (n >= 1) {
		printf("annulus: area %.6f (exact %.6f), centroid %.2g %.2g\n", reg[0].area, want,
		       reg[0].cx, reg[0].cy);
		CHECK(fabs(reg[0].area - want) < 1e-3, "annulus area %g, exact %g", reg[0].area, want);
		CHECK(fabs(reg[0].cx) < 1e-6 && fabs(reg[0].cy) < 1e-6, "annulus centroid %g %g",
		      reg[0].cx, reg[0].cy);
		CHECK(!reg[0].edge, "annulus marked as cut by the box edge");
	}
	free(reg);
	surf_section_free(&sec);
	surf_free(s);
	s = height_field(40, 40, y, cut_hole);
	surf_section(s, -0.5, &sec);
	n = surf_regions(s, &sec, 2000, &reg);
	CHECK(n == 1 && reg[0].edge, "a hole cut by the box edge: %zu regions, edge %d", n,
	      n ? reg[0].edge : -1);
	free(reg);
	surf_section_free(&sec);
	surf_free(s);
	free(y);
}

int main(void)
{
	util_setprog("surf_lines");
	spans_check();

	double *y = even_rows(100, 0);
	sample_check("100 rows", 100, y, 1100, 100, 11, 0);
	free(y);
	y = even_rows(3000, 0);
	sample_check("3000 rows", 3000, y, 3000, 3000, 1, 0);
	free(y);
	/* rows at the middles of 1500 bands, plus the box sides */
	y = xreallocarray(NULL, 1502, sizeof *y);
	y[0] = -1;
	for (int j = 0; j < 1500; j++)
		y[j + 1] = -1 + 2.0 * (j + 0.5) / 1500;
	y[1501] = 1;
	sample_check("1500 middle rows", 1501, y, 1500, 1500, 1, 1);
	free(y);
	y = even_rows(2000, 0);
	for (int j = 1; j < 2000; j++)
		y[j] += (urand() - 0.5) * 0.6 / 1000;
	sample_check("jittered rows", 2000, y, 1024, 0, 1, 0);
	free(y);
	y = even_rows(70000, 0);
	sample_check("70000 rows", 70000, y, 65536, 0, 1, 0);
	free(y);

	regions_check();
	if (failures)
		printf("%d failures\n", failures);
	return failures != 0;
}
