/* fmt_contour.c - see fmt_contour.h. */
#include "fmt_contour.h"
#include "checked.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <stdlib.h>

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

struct contour *fmt_contour_read(const char *path, int old)
{
	struct lex *lx = lex_open(path);
	double b[4];
	int nx, ny;
	if (old) {
		double x0 = lex_number(lx, "xmin");
		double y0 = lex_number(lx, "ymin");
		double xl = lex_number(lx, "xlength");
		double yl = lex_number(lx, "ylength");
		if (!(xl > 0) || !(yl > 0))
			lex_error(lx, "xlength and ylength must be positive");
		b[0] = x0, b[1] = x0 + xl, b[2] = y0, b[3] = y0 + yl;
		nx = ny = CONTOUR_OLD_N;
	} else {
		b[0] = lex_number(lx, "xmin");
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
	if (lex_token(lx)) {
		free(z);
		lex_error(lx, "unexpected data after the %zu z values", want);
	}
	lex_close(lx);
	struct contour *c = xcalloc(1, sizeof *c);
	c->xmin = b[0], c->xmax = b[1], c->ymin = b[2], c->ymax = b[3];
	c->nx = nx, c->ny = ny;
	c->z = z;
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

void fmt_contour_write(const char *path, const struct contour *c)
{
	struct aout *a = aout_open(path);
	double b[4] = {c->xmin, c->xmax, c->ymin, c->ymax};
	num_print_row(a->f, b, 4);
	fprintf(a->f, "%d %d\n", c->nx, c->ny);
	write_values(a->f, c);
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
