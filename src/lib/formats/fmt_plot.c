/* fmt_plot.c - see fmt_plot.h. */
#include "fmt_plot.h"
#include "budget.h"
#include "surf.h"
#include "checked.h"
#include "lex.h"
#include "num.h"
#include "par.h"
#include "util.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

struct plot_file *fmt_plot_new(int dim)
{
	struct plot_file *pf = xcalloc(1, sizeof *pf);
	pf->dim = dim;
	return pf;
}

struct plot_set *fmt_plot_add_set(struct plot_file *pf, const double *bounds)
{
	xgrow(&pf->sets, &pf->cap, (size_t)pf->nsets + 1, sizeof *pf->sets);
	struct plot_set *s = &pf->sets[pf->nsets++];
	memset(s, 0, sizeof *s);
	memcpy(s->bounds, bounds, sizeof(double) * 2 * (size_t)pf->dim);
	return s;
}

void fmt_plot_add_curve(struct plot_file *pf, struct plot_set *s, int npts,
			const double *p)
{
	xgrow(&s->curves, &s->cap, (size_t)s->ncurves + 1, sizeof *s->curves);
	struct plot_curve *c = &s->curves[s->ncurves++];
	c->npts = npts;
	size_t n = (size_t)npts * (size_t)pf->dim;
	c->p = xreallocarray(NULL, n, sizeof *c->p);
	if (n)
		memcpy(c->p, p, n * sizeof *p);
}

static const char *bound_names[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
static const char *coord_names[3] = {"x", "y", "z"};

/* Numbers in a sample of text: runs of characters that are neither
 * white space nor commas, outside '#' lines. */
struct number_count {
	double count;
	int in, comment;
};

static void count_chunk(void *ctx, const char *b, size_t n)
{
	struct number_count *c = ctx;
	double count = c->count;
	int in = c->in, comment = c->comment;
	for (size_t i = 0; i < n; i++) {
		char ch = b[i];
		if (ch == '\n') {
			comment = 0, in = 0;
			continue;
		}
		if (comment)
			continue;
		if (ch == '#' && !in) {
			comment = 1;
			continue;
		}
		int sep = ch == ' ' || ch == '\t' || ch == '\r' || ch == ',';
		if (!sep && !in)
			count++;
		in = !sep;
	}
	c->count = count;
	c->in = in;
	c->comment = comment;
}

static double count_numbers(const char *b, size_t n)
{
	struct number_count c = {0, 0, 0};
	count_chunk(&c, b, n);
	return c.count;
}

static int ends_in(const char *s, const char *suffix)
{
	size_t n = strlen(s), m = strlen(suffix);
	return n > m && strcmp(s + n - m, suffix) == 0;
}

int fmt_plot_size(const char *path, double *text, double *numbers)
{
	*text = *numbers = 0;
	struct stat st;
	if (strcmp(path, "-") == 0 || stat(path, &st) != 0 || !S_ISREG(st.st_mode))
		return 0;
	double size = (double)st.st_size;
	if (ends_in(path, ".gz") || ends_in(path, ".Z")) {
		/* its size is known only by inflating it: counted as it comes,
		 * held nowhere, and only until it is beyond the memory limit
		 * (then the estimate refuses it anyway) */
		struct number_count c = {0, 0, 0};
		double max = budget_big() ? 1e300 : budget_memory();
		*text = lex_gz_scan(path, max, count_chunk, &c);
		*numbers = c.count;
		return 1;
	}
	*text = size;
	FILE *f = fopen(path, "rb");
	if (!f)
		return 1;       /* the reader will say why */
	static char buf[PLOT_SAMPLE];
	size_t n = fread(buf, 1, sizeof buf, f);
	fclose(f);
	if (n == 0)
		return 1;
	*numbers = count_numbers(buf, n) * (size / (double)n);
	return 1;
}

struct plot_file *fmt_plot_read(const char *path, int dim)
{
	struct lex *lx = lex_open(path);
	lex_expect(lx, dim == 3 ? "plot3d(5)" : "plot2d(5)");
	struct plot_file *pf = fmt_plot_new(dim);
	fmt_labels_read(lx, &pf->labels, dim == 3);
	if (lex_at_end(lx))
		lex_error(lx, "empty plot file: expected %s", bound_names[0]);
	while (!lex_at_end(lx)) {
		double b[6];
		for (int k = 0; k < 2 * dim; k++) {
			b[k] = lex_number(lx, bound_names[k]);
			if (!pf->first_line)
				pf->first_line = lex_lineno(lx);
		}
		struct plot_set *s = fmt_plot_add_set(pf, b);
		long nc = lex_count(lx, "ncurves", 0, PLOT_MAX_COUNT);
		/* the points of all curves of the set go to one block (a
		 * triangle is 96 bytes, not a block of its own with its
		 * allocation slack); it grows as points arrive, never by the
		 * claimed counts, and the curves point into it once complete */
		size_t cap = 0, n = 0;
		double *pool = NULL;
		for (long c = 0; c < nc; c++) {
			long np = lex_count(lx, "npts", 0, PLOT_MAX_COUNT);
			size_t want = ck_add(n, ck_mul((size_t)np, (size_t)dim, "plot points"),
					     "plot points");
			size_t first = n;
			while (n < want) {
				double v = lex_numberf(lx, "%s of point %zu of curve %ld",
						       coord_names[(n - first) % (size_t)dim],
						       (n - first) / (size_t)dim + 1, c + 1);
				xgrow(&pool, &cap, n + 1, sizeof *pool);
				pool[n++] = v;
			}
			xgrow(&s->curves, &s->cap, (size_t)s->ncurves + 1, sizeof *s->curves);
			s->curves[s->ncurves].npts = (int)np;
			s->curves[s->ncurves].p = NULL;
			s->ncurves++;
		}
		if (n) {
			pool = xreallocarray(pool, n, sizeof *pool);   /* no slack */
			s->pool = pool;
			s->npooled = s->ncurves;
			size_t at = 0;
			for (int c = 0; c < s->ncurves; c++) {
				s->curves[c].p = pool + at;
				at += (size_t)s->curves[c].npts * (size_t)dim;
			}
		} else {
			free(pool);
		}
		if (s->ncurves)
			s->curves = xreallocarray(s->curves, (size_t)s->ncurves, sizeof *s->curves);
		s->cap = (size_t)s->ncurves;
	}
	lex_close(lx);
	return pf;
}

struct plot_writer {
	struct aout *a;
	int dim;
	int nsets;
	long promised, written;
	char *path;
};

struct plot_writer *fmt_plot_open(const char *path, int dim)
{
	struct plot_writer *w = xcalloc(1, sizeof *w);
	w->a = aout_open(path);
	w->dim = dim;
	w->path = xstrdup(path);
	return w;
}

void fmt_plot_labels(struct plot_writer *w, const struct plot_labels *l)
{
	if (!w)
		return;
	if (w->nsets)
		die("%s: internal error: labels after the first set", w->path);
	if (!l)
		return;
	struct plot_labels c = *l;
	if (w->dim == 2)
		c.axis[2][0] = '\0';   /* a 2D file has no z label to read back */
	fmt_labels_put(w->a->f, &c);
}

static void check_set_done(const struct plot_writer *w)
{
	if (w->nsets && w->written != w->promised)
		die("%s: internal error: %ld curves promised, %ld written",
		    w->path, w->promised, w->written);
}

void fmt_plot_begin_set(struct plot_writer *w, const double *bounds, long ncurves)
{
	check_set_done(w);
	if (w->nsets)
		aout_mark(w->a, w->nsets);      /* the sets so far are whole */
	if (w->nsets)
		fputc('\n', w->a->f);
	num_print_row(w->a->f, bounds, 2 * w->dim);
	fprintf(w->a->f, "%ld\n", ncurves);
	w->nsets++;
	w->promised = ncurves;
	w->written = 0;
}

void fmt_plot_curve(struct plot_writer *w, int npts, const double *p)
{
	FILE *f = w->a->f;
	fprintf(f, "%d\n", npts);
	for (int i = 0; i < npts; i++)
		num_print_row(f, p + (size_t)i * (size_t)w->dim, w->dim);
	w->written++;
}

/* Curves per batch of fmt_plot_curves: bounds the text held in memory
 * (about 16 MB for triangles in 3D) while giving every thread plenty. */
#define CURVES_BATCH 65536
/* Curves per thread at least: formatting one is about a microsecond. */
#define CURVES_MIN_CHUNK 512

struct curves_job {
	size_t first;                   /* index of the batch's first curve */
	int npts, dim;
	void (*get)(void *, size_t, double *);
	void *ctx;
	struct { char *s; size_t len, cap; } *text;     /* per range, in order */
};

static void format_curves(void *arg, size_t lo, size_t hi, int range)
{
	struct curves_job *j = arg;
	int nv = j->npts * j->dim;
	double *p = xreallocarray(NULL, (size_t)nv, sizeof *p);
	size_t most = 16 + (size_t)nv * (NUM_BUFSZ + 1);   /* text of one curve */
	char **s = &j->text[range].s;
	size_t *len = &j->text[range].len, *cap = &j->text[range].cap;
	*len = 0;
	for (size_t i = lo; i < hi; i++) {
		j->get(j->ctx, j->first + i, p);
		xgrow(s, cap, *len + most, 1);
		*len += (size_t)sprintf(*s + *len, "%d\n", j->npts);
		for (int v = 0; v < nv; v++) {
			*len = (size_t)(num_put(*s + *len, p[v]) - *s);
			(*s)[(*len)++] = (v + 1) % j->dim ? ' ' : '\n';
		}
	}
	free(p);
}

void fmt_plot_curves(struct plot_writer *w, size_t n, int npts,
		     void (*get)(void *ctx, size_t i, double *p), void *ctx)
{
	int nt = par_threads();
	struct curves_job j = {0, npts, w->dim, get, ctx,
			       xcalloc((size_t)nt, sizeof *j.text)};
	for (size_t b = 0; b < n; b += CURVES_BATCH) {
		size_t m = n - b < CURVES_BATCH ? n - b : CURVES_BATCH;
		for (int t = 0; t < nt; t++)
			j.text[t].len = 0;
		j.first = b;
		par_for(m, CURVES_MIN_CHUNK, format_curves, &j);
		for (int t = 0; t < nt; t++)
			fwrite(j.text[t].s ? j.text[t].s : "", 1, j.text[t].len, w->a->f);
	}
	for (int t = 0; t < nt; t++)
		free(j.text[t].s);
	free(j.text);
	w->written += (long)n;
}

void fmt_plot_close(struct plot_writer *w)
{
	check_set_done(w);
	aout_mark(w->a, w->nsets);
	aout_commit(w->a);
	free(w->path);
	free(w);
}

void fmt_plot_write(const char *path, const struct plot_file *pf)
{
	struct plot_writer *w = fmt_plot_open(path, pf->dim);
	fmt_plot_labels(w, &pf->labels);
	for (int s = 0; s < pf->nsets; s++) {
		const struct plot_set *set = &pf->sets[s];
		fmt_plot_begin_set(w, set->bounds, set->ncurves);
		for (int c = 0; c < set->ncurves; c++)
			fmt_plot_curve(w, set->curves[c].npts, set->curves[c].p);
	}
	fmt_plot_close(w);
}

void fmt_plot_free(struct plot_file *pf)
{
	if (!pf)
		return;
	for (int s = 0; s < pf->nsets; s++) {
		for (int c = pf->sets[s].npooled; c < pf->sets[s].ncurves; c++)
			free(pf->sets[s].curves[c].p);
		free(pf->sets[s].pool);
		free(pf->sets[s].curves);
	}
	free(pf->sets);
	free(pf);
}

struct surf *surf_from_plot_set(const struct plot_set *set, char *err, size_t errsz)
{
	const double *b = set->bounds;
	if (!(b[0] < b[1] && b[2] < b[3] && b[4] < b[5])) {
		snprintf(err, errsz, "the bounds line is not a box (each minimum below its maximum)");
		return NULL;
	}
	if ((size_t)set->ncurves >= UINT_MAX) {
		snprintf(err, errsz, "too many triangles");
		return NULL;
	}
	for (int c = 0; c < set->ncurves; c++) {
		const struct plot_curve *cv = &set->curves[c];
		if (cv->npts != 4) {
			snprintf(err, errsz, "curve %d: %d points, expected a triangle "
				 "(a closed curve of 4 points)", c + 1, cv->npts);
			return NULL;
		}
		if (memcmp(cv->p, cv->p + 9, 3 * sizeof *cv->p) != 0) {
			snprintf(err, errsz, "curve %d: not closed (the 4th point must repeat "
				 "the 1st)", c + 1);
			return NULL;
		}
	}
	struct surf *s = surf_new(b);
	s->cap = 9 * (size_t)set->ncurves;
	s->v = xreallocarray(NULL, s->cap ? s->cap : 1, sizeof *s->v);
	for (int c = 0; c < set->ncurves; c++)
		memcpy(s->v + 9 * s->ntri++, set->curves[c].p, 9 * sizeof *s->v);
	return s;
}
