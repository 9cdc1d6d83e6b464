/*
 * report.c - measure's outputs: the table (a '#' line of column names,
 * one row per height, then '#' lines of the feature's figures) and the cd
 * against z plot file for drawplot.
 *
 * Numbers are rounded to a fixed resolution before printing (lengths to
 * 1e-6 um, areas to 1e-9 um2, angles to 1e-3 degree) and printed in the
 * shortest form that reads back, so tables are short, and equal across
 * machines whose last bits differ.
 */
#include "measure.h"
#include "rough.h"
#include "fmt_plot.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { RES_LEN = 1000000, RES_AREA = 1000000000, RES_DEG = 1000 };

static void put(FILE *f, double v, double res, int first)
{
	char buf[NUM_BUFSZ];
	if (!first)
		fputc(' ', f);
	fputs(num_fmt(buf, round(v * res) / res), f);
}

void report_len(FILE *f, double um, int first) { put(f, um, RES_LEN, first); }

void report_table(const struct options *o, const struct result *r)
{
	struct aout *a = aout_open(o->out);
	FILE *f = a->f;
	if (o->kind == HOLE)
		fputs("# z cd area dx dy\n", f);
	else
		fputs("# z cd lo hi\n", f);
	for (int i = 0; i < r->nrows; i++) {
		const struct row *w = &r->rows[i];
		put(f, w->z, RES_LEN, 1);
		put(f, w->cd, RES_LEN, 0);
		if (o->kind == HOLE) {
			put(f, w->a, RES_AREA, 0);
			put(f, w->b, RES_LEN, 0);
			put(f, w->c, RES_LEN, 0);
		} else {
			put(f, w->a, RES_LEN, 0);
			put(f, w->b, RES_LEN, 0);
		}
		fputc('\n', f);
	}
	if (r->have_swa) {
		fputs("# swa", f);
		if (r->swa_known)
			put(f, r->swa, RES_DEG, 0);
		else
			fputs(" -", f);
		fputc('\n', f);
	}
	fputs("# resist_loss", f);
	put(f, r->resist_loss, RES_LEN, 0);
	fprintf(f, "\n# cleared %s\n", r->cleared ? "yes" : "no");
	if (r->rough)
		roughness_report(f, r->rough);
	aout_commit(a);
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
