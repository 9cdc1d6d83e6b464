/* fmt_plot.c - see fmt_plot.h. */
#include "fmt_plot.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <stdlib.h>
#include <string.h>

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

struct plot_file *fmt_plot_read(const char *path, int dim)
{
	struct lex *lx = lex_open(path);
	struct plot_file *pf = fmt_plot_new(dim);
	if (lex_at_end(lx))
		lex_error(lx, "empty plot file: expected %s", bound_names[0]);
	while (!lex_at_end(lx)) {
		double b[6];
		for (int k = 0; k < 2 * dim; k++)
			b[k] = lex_number(lx, bound_names[k]);
		struct plot_set *s = fmt_plot_add_set(pf, b);
		long nc = lex_count(lx, "ncurves", 0, PLOT_MAX_COUNT);
		for (long c = 0; c < nc; c++) {
			long np = lex_count(lx, "npts", 0, PLOT_MAX_COUNT);
			/* grow as points arrive, never by the claimed count */
			size_t cap = 0, n = 0, want = (size_t)np * (size_t)dim;
			double *p = NULL;
			while (n < want) {
				double v = lex_numberf(lx, "%s of point %zu of curve %ld",
						       coord_names[n % (size_t)dim],
						       n / (size_t)dim + 1, c + 1);
				xgrow(&p, &cap, n + 1, sizeof *p);
				p[n++] = v;
			}
			xgrow(&s->curves, &s->cap, (size_t)s->ncurves + 1, sizeof *s->curves);
			s->curves[s->ncurves].npts = (int)np;
			s->curves[s->ncurves].p = p;
			s->ncurves++;
		}
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

void fmt_plot_close(struct plot_writer *w)
{
	check_set_done(w);
	aout_commit(w->a);
	free(w->path);
	free(w);
}

void fmt_plot_write(const char *path, const struct plot_file *pf)
{
	struct plot_writer *w = fmt_plot_open(path, pf->dim);
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
		for (int c = 0; c < pf->sets[s].ncurves; c++)
			free(pf->sets[s].curves[c].p);
		free(pf->sets[s].curves);
	}
	free(pf->sets);
	free(pf);
}
