/*
 * collect.c - one focus-exposure matrix from its points' measure tables:
 * fem.dat (focus outer, dose inner, ascending), and the Bossung plot (cd
 * against focus, one curve per dose) with a drawplot template that labels
 * the curves by dose.  A point whose feature is absent at the measured
 * height (cd 0) is left out of its curve, as a Bossung plot shows printed
 * features only; a dose with none keeps an empty curve, so that the
 * template's labels stay with their doses.
 *
 * A point whose table does not exist (its stage failed, or it has not run
 * yet) is left out of fem.dat and counted; a table that exists but is not
 * a measure table is an error, since it means something else went wrong.
 */
#include "femwin.h"
#include "fmt_measure.h"
#include "fmt_plot.h"
#include "fmt_template.h"
#include "num.h"
#include "util.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int cmp_point(const void *pa, const void *pb)
{
	const struct fem_point *a = pa, *b = pb;
	if (a->focus != b->focus)
		return a->focus < b->focus ? -1 : 1;
	if (a->dose != b->dose)
		return a->dose < b->dose ? -1 : 1;
	return 0;
}

static int cmp_double(const void *pa, const void *pb)
{
	double a = *(const double *)pa, b = *(const double *)pb;
	return a < b ? -1 : a > b;
}

/* Curve styles: line types 1-10 and markers that stay visible when the
 * curves overlap (square, diamond, triangles, circle, x; white then black). */
static const int markers[] = {2, 5, 8, 11, 14, 17, 4, 7, 10, 13, 16};
enum { NMARKERS = sizeof markers / sizeof markers[0] };

static void write_bossung(const struct fem_table *t, const char *plot_path,
			  const char *template_path)
{
	double *doses = xreallocarray(NULL, (size_t)t->n, sizeof *doses);
	for (int i = 0; i < t->n; i++)
		doses[i] = t->p[i].dose;
	qsort(doses, (size_t)t->n, sizeof *doses, cmp_double);
	int nd = 0;
	for (int i = 0; i < t->n; i++)
		if (nd == 0 || doses[i] != doses[nd - 1])
			doses[nd++] = doses[i];
	double b[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
	for (int i = 0; i < t->n; i++) {
		b[0] = fmin(b[0], t->p[i].focus);
		b[1] = fmax(b[1], t->p[i].focus);
		if (t->p[i].cd > 0) {
			b[2] = fmin(b[2], t->p[i].cd);
			b[3] = fmax(b[3], t->p[i].cd);
		}
	}
	if (b[2] > b[3]) {  /* nothing printed anywhere */
		b[2] = 0;
		b[3] = 1;
	}
	if (plot_path) {
		struct plot_file *pf = fmt_plot_new(2);
		fmt_labels_set(&pf->labels, "Bossung curves", "focus (um)", "CD (um)", NULL);
		struct plot_set *s = fmt_plot_add_set(pf, b);
		double *xy = xreallocarray(NULL, (size_t)t->n * 2, sizeof *xy);
		for (int k = 0; k < nd; k++) {
			int m = 0;
			for (int i = 0; i < t->n; i++)   /* rows are in focus order */
				if (t->p[i].dose == doses[k] && t->p[i].cd > 0) {
					xy[2 * m] = t->p[i].focus;
					xy[2 * m + 1] = t->p[i].cd;
					m++;
				}
			fmt_plot_add_curve(pf, s, m, xy);
		}
		free(xy);
		fmt_plot_write(plot_path, pf);
		fmt_plot_free(pf);
	}
	if (template_path) {
		struct template tp;
		tp.n = nd;
		tp.e = xcalloc((size_t)nd, sizeof *tp.e);
		for (int k = 0; k < nd; k++) {
			char num[NUM_BUFSZ], label[NUM_BUFSZ + 16];
			snprintf(label, sizeof label, "%s mJ/cm2", num_fmt(num, doses[k]));
			tp.e[k].ln_type = 1 + k % 10;
			tp.e[k].mkr_type = markers[k % NMARKERS];
			tp.e[k].label = xstrdup(label);
		}
		fmt_template_write(template_path, &tp);
		for (int k = 0; k < nd; k++)
			free(tp.e[k].label);
		free(tp.e);
	}
	free(doses);
}

/* Points in (focus, dose) order, a merge sort: the seeds of a point keep
 * the order they were given, so that their sums are made in one order. */
static void sort_stable(struct fem_point *p, int n)
{
	struct fem_point *w = xreallocarray(NULL, (size_t)(n > 0 ? n : 1), sizeof *w);
	for (int width = 1; width < n; width *= 2) {
		for (int lo = 0; lo < n; lo += 2 * width) {
			int mid = lo + width < n ? lo + width : n;
			int hi = lo + 2 * width < n ? lo + 2 * width : n;
			int a = lo, b = mid, k = lo;
			while (a < mid || b < hi)
				w[k++] = b >= hi || (a < mid && cmp_point(&p[a], &p[b]) <= 0) ? p[a++]
											: p[b++];
		}
		memcpy(p, w, (size_t)n * sizeof *p);
	}
	free(w);
}

/* The seeds of one stochastic point, t->p[lo..hi): one fem.dat point
 * (the mean of the seeds that printed) and its stoch.dat row. */
static struct fem_point seeds_merge(const struct fem_point *p, int n, struct fem_stoch_row *r)
{
	struct fem_point m = {p[0].focus, p[0].dose, 0, 0, 1, 0};
	double s = 0, s2 = 0, swa = 0, loss = 0;
	int k = 0;
	for (int i = 0; i < n; i++) {
		m.cleared &= p[i].cleared;
		loss += p[i].loss;
		if (!(p[i].cd > 0) || !p[i].cleared)
			continue;
		s += p[i].cd;
		swa += p[i].swa;
		k++;
	}
	double mean = k ? s / k : 0;
	for (int i = 0; i < n; i++)
		if (p[i].cd > 0 && p[i].cleared)
			s2 += (p[i].cd - mean) * (p[i].cd - mean);
	m.cd = mean;
	m.swa = k ? swa / k : NAN;
	m.loss = loss / n;
	*r = (struct fem_stoch_row){m.focus, m.dose, mean, k > 1 ? 3 * sqrt(s2 / (k - 1)) : 0,
				    n - k, n};
	return m;
}

int femwin_collect(const struct femwin_input *in, int n, const char *fem_path,
		   const char *bossung_path, const char *template_path,
		   const char *stoch_path)
{
	struct fem_table t = {0, NULL};
	t.p = xreallocarray(NULL, (size_t)(n > 0 ? n : 1), sizeof *t.p);
	int missing = 0;
	const struct femwin_input *first_missing = NULL;
	for (int i = 0; i < n; i++) {
		if (access(in[i].table, F_OK) != 0) {
			if (errno != ENOENT)
				die("%s: cannot read:", in[i].table);
			if (!missing++)
				first_missing = &in[i];
			continue;
		}
		/* fem.dat takes the first height's cd, which fem(5) holds
		 * not negative, and the feature's figures */
		struct measure_table m;
		fmt_measure_read(in[i].table, &m);
		if (!(m.rows[0].cd >= 0))
			die("%s: negative cd", in[i].table);
		struct fem_point *p = &t.p[t.n++];
		p->focus = in[i].focus;
		p->dose = in[i].dose;
		p->cd = m.rows[0].cd;
		p->swa = m.swa;
		p->cleared = m.cleared;
		p->loss = m.resist_loss;
		fmt_measure_free(&m);
	}
	sort_stable(t.p, t.n);
	struct fem_stoch_row *rows = NULL;
	int nrows = 0;
	if (stoch_path) {
		rows = xreallocarray(NULL, (size_t)(t.n > 0 ? t.n : 1), sizeof *rows);
		int w = 0;
		for (int lo = 0, hi; lo < t.n; lo = hi) {
			for (hi = lo + 1; hi < t.n && cmp_point(&t.p[lo], &t.p[hi]) == 0; hi++)
				;
			t.p[w++] = seeds_merge(t.p + lo, hi - lo, &rows[nrows++]);
		}
		t.n = w;
	}
	for (int i = 1; i < t.n; i++)
		if (cmp_point(&t.p[i - 1], &t.p[i]) == 0)
			die_status(EXIT_USAGE, "the point focus %g dose %g is given twice",
				   t.p[i].focus, t.p[i].dose);
	if (t.n == 0) {
		free(t.p);
		die("no point has a result yet (%d missing, the first %s)", missing,
		    n > 0 ? in[0].table : "-");
	}
	fmt_fem_write(fem_path, &t);
	if (stoch_path) {
		fmt_fem_stoch_write(stoch_path, rows, nrows);
		int nf = 0, ns = 0;
		for (int i = 0; i < nrows; i++) {
			nf += rows[i].failures;
			ns += rows[i].seeds;
		}
		printf("stochastic: %d points, %d runs, %d failures (a feature absent or not "
		       "cleared)\n", nrows, ns, nf);
		free(rows);
	}
	if (bossung_path || template_path)
		write_bossung(&t, bossung_path, template_path);
	if (missing) {
		char f[NUM_BUFSZ], d[NUM_BUFSZ];
		warn("%d of %d points have no result (the first: focus %s dose %s, %s); %s holds the other %d",
		     missing, n, num_fmt(f, first_missing->focus), num_fmt(d, first_missing->dose),
		     first_missing->table, fem_path, t.n);
	}
	free(t.p);
	return missing;
}
