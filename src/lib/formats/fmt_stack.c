/*
 * fmt_stack.c - reader and writer of the image stack (see fmt_stack.h and
 * man/man5/stack.5).  Each plane is read by the contour-file's own parser,
 * so a plane is exactly a contour-file and the two formats cannot drift
 * apart.  The whole-stack checks (one window and grid, depths from 0 to
 * the thickness) are made here, so that bleach and contour never meet a
 * stack they cannot use.
 */
#include "fmt_stack.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* Bounds of the header, those of splat(5)'s resist statement. */
static const double STACK_MAX_THICK = 1e3, STACK_MAX_INDEX = 100;
/* The wavelength's bound, that of splat(5)'s wavelength statement, um. */
static const double STACK_MAX_WAVELENGTH = 1e3;
/* The last depth must equal the thickness to this fraction of it: a
 * stack written by hand with rounded depths still reads. */
static const double STACK_DEPTH_SLACK = 1e-9;

struct image_stack *fmt_stack_new(int n, double thick, double index,
				  const struct contour *like)
{
	struct image_stack *s = xcalloc(1, sizeof *s);
	s->is_stack = 1;
	s->n = n;
	s->thick = thick;
	s->index = index;
	s->depth = xcalloc((size_t)n, sizeof *s->depth);
	s->plane = xcalloc((size_t)n, sizeof *s->plane);
	for (int k = 0; k < n; k++) {
		/* the last depth is the thickness itself, not (n-1) T/(n-1) */
		s->depth[k] = k == n - 1 ? thick : k * thick / (n - 1);
		s->plane[k] = fmt_contour_new(like->xmin, like->xmax, like->ymin, like->ymax,
					      like->nx, like->ny);
	}
	return s;
}

void fmt_stack_free(struct image_stack *s)
{
	if (!s)
		return;
	for (int k = 0; k < s->n; k++)
		fmt_contour_free(s->plane[k]);
	free(s->plane);
	free(s->depth);
	free(s);
}

/* "stack" is read; the pairs planes N, thickness T, index n follow in
 * any order, each once, and optionally wavelength L (stacks written
 * before it was recorded have none) and the word film.  Returns the
 * token after them. */
static const char *header(struct lex *lx, struct image_stack *s)
{
	int got = 0;
	for (;;) {
		const char *k = lex_token(lx);
		int bit = !k ? 0 : strcasecmp(k, "planes") == 0 ? 1 :
			  strcasecmp(k, "thickness") == 0 ? 2 : strcasecmp(k, "index") == 0 ? 4 :
			  strcasecmp(k, "wavelength") == 0 ? 8 : strcasecmp(k, "film") == 0 ? 16 : 0;
		if ((got & 7) == 7 && !bit)
			return k;
		if (!bit || (got & bit))
			lex_error(lx, "stack: expected \"stack planes N thickness T index n "
				  "[wavelength L] [film]\"");
		got |= bit;
		if (bit == 16) {
			s->film = 1;
		} else if (bit == 1) {
			s->n = (int)lex_count(lx, "the number of planes", 2, STACK_MAX_PLANES);
		} else if (bit == 2) {
			s->thick = lex_number(lx, "the resist thickness");
			if (!(s->thick > 0 && s->thick <= STACK_MAX_THICK))
				lex_error(lx, "stack: thickness must be in (0, %g] um, found %g",
					  STACK_MAX_THICK, s->thick);
		} else if (bit == 4) {
			s->index = lex_number(lx, "the resist index");
			if (!(s->index >= 1 && s->index <= STACK_MAX_INDEX))
				lex_error(lx, "stack: index must be in [1, %g], found %g",
					  STACK_MAX_INDEX, s->index);
		} else {
			s->wavelength = lex_number(lx, "the wavelength");
			if (!(s->wavelength > 0 && s->wavelength <= STACK_MAX_WAVELENGTH))
				lex_error(lx, "stack: wavelength must be in (0, %g] um, found %g",
					  STACK_MAX_WAVELENGTH, s->wavelength);
		}
	}
}

/* The stack being read: a fatal error exits at once, and this keeps
 * what was read reachable, so the sanitizers report no leak. */
static struct image_stack *reading;

static int same_grid(const struct contour *a, const struct contour *b)
{
	return a->xmin == b->xmin && a->xmax == b->xmax && a->ymin == b->ymin &&
	       a->ymax == b->ymax && a->nx == b->nx && a->ny == b->ny;
}

static void grid_text(char *buf, size_t n, const struct contour *c)
{
	char v[4][NUM_BUFSZ];
	snprintf(buf, n, "%s %s %s %s, %dx%d", num_fmt(v[0], c->xmin), num_fmt(v[1], c->xmax),
		 num_fmt(v[2], c->ymin), num_fmt(v[3], c->ymax), c->nx, c->ny);
}

struct image_stack *fmt_stack_read(const char *path)
{
	struct lex *lx = lex_open(path);
	lex_expect(lx, "stack(5) or contour(5)");
	struct plot_labels lab;         /* a plain contour-file's (contour.5) */
	fmt_labels_read(lx, &lab, 1);
	const char *t = lex_token(lx);
	struct image_stack *s = reading = xcalloc(1, sizeof *s);
	if (!t || strcasecmp(t, "stack") != 0) {
		/* a plain contour-file: one plane at the top */
		struct contour *c = fmt_contour_parse(lx, t, 0);
		s->n = 1;
		s->depth = xcalloc(1, sizeof *s->depth);
		s->plane = xcalloc(1, sizeof *s->plane);
		s->plane[0] = c;
		c->labels = lab;
		if (lex_token(lx))
			lex_error(lx, "unexpected data after the %zu z values",
				  (size_t)c->nx * (size_t)c->ny);
		lex_close(lx);
		reading = NULL;
		return s;
	}
	s->is_stack = 1;
	t = header(lx, s);
	s->depth = xcalloc((size_t)s->n, sizeof *s->depth);
	s->plane = xcalloc((size_t)s->n, sizeof *s->plane);
	int n = s->n;
	s->n = 0;               /* planes read so far */
	for (int k = 0; k < n; k++) {
		if (!t || strcasecmp(t, "depth") != 0) {
			if (!t)
				lex_error(lx, "truncated: %d of %d planes", k, n);
			lex_error(lx, "expected \"depth\" before plane %d", k + 1);
		}
		double d = lex_number(lx, "the depth of a plane");
		long line = lex_lineno(lx);
		if (k == 0 && d != 0) {
			lex_error(lx, "the first plane must be at depth 0 (the resist top), found %g", d);
		}
		if (k > 0 && !(d > s->depth[k - 1])) {
			lex_error(lx, "plane %d at depth %g is not below plane %d at %g",
				  k + 1, d, k, s->depth[k - 1]);
		}
		if (!(d <= s->thick * (1 + STACK_DEPTH_SLACK)))
			lex_error(lx, "plane %d at depth %g is below the thickness %g", k + 1, d, s->thick);
		s->depth[k] = d;
		struct contour *c = fmt_contour_parse(lx, lex_token(lx), 0);
		s->plane[s->n++] = c;
		const struct contour *c0 = s->plane[0];
		if (!same_grid(c, c0)) {
			/* shortest round-trip numbers: windows that differ by
			 * 1e-10 must not print alike */
			char a[200], b[200];
			grid_text(a, sizeof a, c);
			grid_text(b, sizeof b, c0);
			die("%s:%ld: plane %d has window and grid %s, plane 1 has %s", lex_name(lx),
			    line, k + 1, a, b);
		}
		t = lex_token(lx);
	}
	if (t)
		lex_error(lx, "unexpected data after the %d planes", n);
	if (!(s->depth[n - 1] >= s->thick * (1 - STACK_DEPTH_SLACK)))
		lex_error(lx, "the last plane is at depth %g, not at the thickness %g",
			  s->depth[n - 1], s->thick);
	lex_close(lx);
	reading = NULL;
	return s;
}

void fmt_stack_write(const char *path, const struct image_stack *s)
{
	if (!s->is_stack) {
		fmt_contour_write(path, s->plane[0]);
		return;
	}
	struct aout *a = aout_open(path);
	fputs("stack planes ", a->f);
	fprintf(a->f, "%d thickness ", s->n);
	num_print(a->f, s->thick);
	fputs(" index ", a->f);
	num_print(a->f, s->index);
	if (s->wavelength > 0) {
		fputs(" wavelength ", a->f);
		num_print(a->f, s->wavelength);
	}
	if (s->film)
		fputs(" film", a->f);
	fputc('\n', a->f);
	for (int k = 0; k < s->n; k++) {
		fputs("depth ", a->f);
		num_print(a->f, s->depth[k]);
		fputc('\n', a->f);
		fmt_contour_put(a->f, s->plane[k]);
	}
	aout_commit(a);
}
