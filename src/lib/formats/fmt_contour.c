/* fmt_contour.c - see fmt_contour.h. */
#include "fmt_contour.h"
#include "checked.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <stdlib.h>
#include <string.h>
#include <strings.h>

struct contour *fmt_contour_new(double xmin, double xmax, double ymin,
				double ymax, int nx, int ny)
{
	struct contour *c = xcalloc(1, sizeof *c);
	c->xmin = xmin, c->xmax = xmax, c->ymin = ymin, c->ymax = ymax;
	c->nx = nx, c->ny = ny;
	c->z = xcalloc((size_t)nx * (size_t)ny, sizeof *c->z);
	return c;
}

double fmt_contour_x(const struct contour *c, int i)
{
	return c->xmin + (c->xmax - c->xmin) * i / (c->nx - 1);
}

double fmt_contour_y(const struct contour *c, int j)
{
	return c->ymin + (c->ymax - c->ymin) * j / (c->ny - 1);
}

/* The first number of the header, already read as token t; the same
 * messages as lex_number (a token shown printable, cut at 24 bytes). */
static double first_number(struct lex *lx, const char *t, const char *what)
{
	double v;
	char s[40];
	if (!t)
		return lex_number(lx, what);    /* at the end: its message and line */
	if (!num_parse(t, &v)) {
		size_t j = 0;
		for (size_t i = 0; t[i] && i < 24; i++)
			s[j++] = (t[i] >= 32 && t[i] < 127) ? t[i] : '?';
		if (strlen(t) > 24)
			s[j++] = '.', s[j++] = '.', s[j++] = '.';
		s[j] = '\0';
		lex_error(lx, "expected %s (a finite number), found \"%s\"", what, s);
	}
	return v;
}

struct contour *fmt_contour_parse(struct lex *lx, const char *first, int old)
{
	double b[4];
	int nx, ny;
	if (old) {
		double x0 = first_number(lx, first, "xmin");
		double y0 = lex_number(lx, "ymin");
		double xl = lex_number(lx, "xlength");
		double yl = lex_number(lx, "ylength");
		if (!(xl > 0) || !(yl > 0))
			lex_error(lx, "xlength and ylength must be positive");
		b[0] = x0, b[1] = x0 + xl, b[2] = y0, b[3] = y0 + yl;
		nx = ny = CONTOUR_OLD_N;
	} else {
		b[0] = first_number(lx, first, "xmin");
		b[1] = lex_number(lx, "xmax");
		b[2] = lex_number(lx, "ymin");
		b[3] = lex_number(lx, "ymax");
		if (!(b[1] > b[0]))
			lex_error(lx, "xmax must be greater than xmin");
		if (!(b[3] > b[2]))
			lex_error(lx, "ymax must be greater than ymin");
		nx = (int)lex_count(lx, "nxpts", 2, CONTOUR_MAX_N);
		ny = (int)lex_count(lx, "nypts", 2, CONTOUR_MAX_N);
	}
	/* grow as values arrive: a header claiming a huge grid allocates
	 * only what the file really holds */
	size_t want = ck_mul((size_t)nx, (size_t)ny, "contour grid points"), cap = 0, n = 0;
	double *z = NULL;
	while (n < want) {
		const char *t = lex_token(lx);
		if (!t) {
			free(z);
			lex_error(lx, "truncated: %zu of %zu z values", n, want);
		}
		double v;
		if (!num_parse(t, &v)) {
			free(z);
			lex_error(lx, "expected z value %zu (a finite number)", n + 1);
		}
		xgrow(&z, &cap, n + 1, sizeof *z);
		z[n++] = v;
	}
	struct contour *c = xcalloc(1, sizeof *c);
	c->xmin = b[0], c->xmax = b[1], c->ymin = b[2], c->ymax = b[3];
	c->nx = nx, c->ny = ny;
	c->z = z;
	return c;
}

struct contour *fmt_contour_read(const char *path, int old)
{
	struct lex *lx = lex_open(path);
	lex_expect(lx, "contour(5)");
	struct plot_labels lab;
	fmt_labels_read(lx, &lab, 1);
	const char *t = lex_token(lx);
	/* an image stack (stack.5) starts with its keyword: say what it is
	 * rather than "expected xmin" */
	if (t && strcasecmp(t, "stack") == 0)
		lex_error(lx, "an image stack (see stack(5)), not a single contour-file");
	struct contour *c = fmt_contour_parse(lx, t, old);
	c->labels = lab;
	if (lex_token(lx)) {
		size_t want = (size_t)c->nx * (size_t)c->ny;
		fmt_contour_free(c);
		lex_error(lx, "unexpected data after the %zu z values", want);
	}
	lex_close(lx);
	return c;
}

static void write_values(FILE *f, const struct contour *c)
{
	size_t n = (size_t)c->nx * (size_t)c->ny;
	for (size_t k = 0; k < n; k++) {
		num_print(f, c->z[k]);
		fputc('\n', f);
	}
}

void fmt_contour_put(FILE *f, const struct contour *c)
{
	double b[4] = {c->xmin, c->xmax, c->ymin, c->ymax};
	num_print_row(f, b, 4);
	fprintf(f, "%d %d\n", c->nx, c->ny);
	write_values(f, c);
}

void fmt_contour_write(const char *path, const struct contour *c)
{
	struct aout *a = aout_open(path);
	fmt_labels_put(a->f, &c->labels);
	fmt_contour_put(a->f, c);
	aout_commit(a);
}

void fmt_contour_write_old(const char *path, const struct contour *c)
{
	if (c->nx != CONTOUR_OLD_N || c->ny != CONTOUR_OLD_N)
		die("%s: the old contour format holds only a %dx%d grid",
		    path, CONTOUR_OLD_N, CONTOUR_OLD_N);
	struct aout *a = aout_open(path);
	double b[4] = {c->xmin, c->ymin, c->xmax - c->xmin, c->ymax - c->ymin};
	num_print_row(a->f, b, 4);
	write_values(a->f, c);
	aout_commit(a);
}

void fmt_contour_free(struct contour *c)
{
	if (c) {
		free(c->z);
		free(c);
	}
}
