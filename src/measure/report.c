/*
 * report.c - measure's outputs: the table (fmt_measure.h, measure(5): a
 * '#' line of column names, one row per height, then '#' lines of the
 * feature's figures) and the cd against z plot file for drawplot.
 */
#include "measure.h"
#include "fmt_measure.h"
#include "rough.h"
#include "fmt_plot.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>

void report_table(const struct options *o, const struct result *r)
{
	struct measure_table t = {
		.hole = o->kind == HOLE, .nrows = r->nrows,
		.rows = xreallocarray(NULL, (size_t)(r->nrows > 0 ? r->nrows : 1), sizeof *t.rows),
		.have_swa = r->have_swa, .swa = r->swa_known ? r->swa : NAN,
		.resist_loss = r->resist_loss, .cleared = r->cleared, .have_err = r->have_err,
	};
	for (int i = 0; i < r->nrows; i++) {
		const struct row *w = &r->rows[i];
		t.rows[i] = (struct measure_row){w->z, w->cd, {w->a, w->b, w->c}, w->err};
	}
	if (r->rough) {
		const struct roughness *g = r->rough;
		t.have_rough = 1;
		t.ler[0] = g->ler[0];
		t.ler[1] = g->ler[1];
		t.lwr = g->lwr;
		t.corr_length = g->corr[0] >= 0 && g->corr[1] >= 0 ?
			0.5 * (g->corr[0] + g->corr[1]) : NAN;
	}
	fmt_measure_write(o->out, &t);
	fmt_measure_free(&t);
}

static int by_z(const void *p, const void *q)
{
	const double *a = p, *b = q;
	return (a[0] > b[0]) - (a[0] < b[0]);
}

void report_plot(const struct options *o, const struct surf *s, const struct result *r)
{
	double *p = xreallocarray(NULL, 2 * (size_t)r->nrows, sizeof *p);
	double cdmax = 0;
	for (int i = 0; i < r->nrows; i++) {
		p[2 * i] = r->rows[i].z;
		p[2 * i + 1] = r->rows[i].cd;
		cdmax = fmax(cdmax, r->rows[i].cd);
	}
	qsort(p, (size_t)r->nrows, 2 * sizeof *p, by_z);
	/* x: the resist's heights; y: from 0 to a tenth above the largest cd */
	double bounds[4] = {s->box[4], s->box[5], 0, cdmax > 0 ? 1.1 * cdmax : 1};
	struct plot_writer *w = fmt_plot_open(o->plot, 2);
	struct plot_labels lab;
	fmt_labels_set(&lab, "CD through the resist height", "z (um)", "CD (um)", NULL);
	fmt_plot_labels(w, &lab);
	fmt_plot_begin_set(w, bounds, 1);
	fmt_plot_curve(w, r->nrows, p);
	fmt_plot_close(w);
	free(p);
}
