/*
 * fmt_measure.c - measure(1)'s table (fmt_measure.h, measure(5)).
 *
 * The columns of each kind of feature are listed once, with the
 * resolution each is rounded to before printing: the rounding makes the
 * tables short and equal across machines whose last bits differ.
 */
#include "fmt_measure.h"
#include "fmt_lines.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Printing resolutions: per um, per um2, per degree. */
#define RES_LEN 1000000.0
#define RES_AREA 1000000000.0
#define RES_DEG 1000.0

struct column { const char *name; double res; };

static const struct column hole_cols[] = {
	{"z", RES_LEN}, {"cd", RES_LEN}, {"area", RES_AREA}, {"dx", RES_LEN}, {"dy", RES_LEN}
};
static const struct column stretch_cols[] = {
	{"z", RES_LEN}, {"cd", RES_LEN}, {"lo", RES_LEN}, {"hi", RES_LEN}
};
enum { HOLE_NCOLS = 5, STRETCH_NCOLS = 4 };

static void put(FILE *f, double v, double res, int first)
{
	char buf[NUM_BUFSZ];
	if (!first)
		fputc(' ', f);
	fputs(num_fmt(buf, round(v * res) / res), f);
}

/* v, or "-" when it is NAN (a figure that does not exist). */
static void put_or_dash(FILE *f, double v, double res)
{
	if (isnan(v))
		fputs(" -", f);
	else
		put(f, v, res, 0);
}

void fmt_measure_write(const char *path, const struct measure_table *t)
{
	const struct column *col = t->hole ? hole_cols : stretch_cols;
	int ncols = t->hole ? HOLE_NCOLS : STRETCH_NCOLS;
	struct aout *a = aout_open(path);
	FILE *f = a->f;
	fputc('#', f);
	for (int i = 0; i < ncols; i++)
		fprintf(f, " %s", col[i].name);
	if (t->have_err)
		fputs(" err", f);
	fputc('\n', f);
	for (int i = 0; i < t->nrows; i++) {
		const struct measure_row *w = &t->rows[i];
		put(f, w->z, col[0].res, 1);
		put(f, w->cd, col[1].res, 0);
		for (int k = 2; k < ncols; k++)
			put(f, w->v[k - 2], col[k].res, 0);
		if (t->have_err)
			put(f, w->err, RES_LEN, 0);
		fputc('\n', f);
	}
	if (t->have_swa) {
		fputs("# swa", f);
		put_or_dash(f, t->swa, RES_DEG);
		fputc('\n', f);
	}
	fputs("# resist_loss", f);
	put(f, t->resist_loss, RES_LEN, 0);
	fprintf(f, "\n# cleared %s\n", t->cleared ? "yes" : "no");
	if (t->have_rough) {
		fputs("# ler left", f);
		put(f, t->ler[0], RES_LEN, 0);
		fputs(" right", f);
		put(f, t->ler[1], RES_LEN, 0);
		fputs("\n# lwr", f);
		put(f, t->lwr, RES_LEN, 0);
		fputs("\n# corr_length", f);
		put_or_dash(f, t->corr_length, RES_LEN);
		fputc('\n', f);
	}
	aout_commit(a);
}

void fmt_measure_write_holes(const char *path, const struct measure_hole *h, size_t n,
			     double lcdu)
{
	struct aout *a = aout_open(path);
	FILE *f = a->f;
	fputs("# x y cd\n", f);
	for (size_t i = 0; i < n; i++) {
		put(f, h[i].x, RES_LEN, 1);
		put(f, h[i].y, RES_LEN, 0);
		put(f, h[i].cd, RES_LEN, 0);
		fputc('\n', f);
	}
	fputs("# lcdu", f);
	put_or_dash(f, lcdu, RES_LEN);
	fprintf(f, "\n# holes %zu\n", n);
	aout_commit(a);
}

/* The header "# z cd ... [err]": its column count, 0 if it is not one;
 * *have_err when the last of more than two columns is err. */
static int header(const struct fmt_lines *l, int *hole, int *have_err)
{
	if (l->ntok < 3 || strcmp(l->tok[0], "#") != 0 ||
	    strcmp(l->tok[1], hole_cols[0].name) != 0 || strcmp(l->tok[2], hole_cols[1].name) != 0)
		return 0;
	int ncols = l->ntok - 1;
	*have_err = ncols > 2 && strcmp(l->tok[ncols], "err") == 0;
	ncols -= *have_err;
	*hole = ncols == HOLE_NCOLS;
	for (int i = 2; *hole && i < ncols; i++)
		*hole = strcmp(l->tok[i + 1], hole_cols[i].name) == 0;
	return ncols + *have_err;
}

/* A '#' line after the header: "# swa DEG" ("-" where the angle is
 * undefined), "# resist_loss UM", "# cleared yes|no" (the key may touch
 * the '#'); other comment lines are skipped.  Sets *have_cleared. */
static void figure(struct fmt_lines *l, struct measure_table *t, int *have_cleared)
{
	const char *key = l->tok[0][1] ? l->tok[0] + 1 : (l->ntok > 1 ? l->tok[1] : "");
	int vi = l->tok[0][1] ? 1 : 2;
	int known = strcmp(key, "swa") == 0 || strcmp(key, "resist_loss") == 0 ||
		    strcmp(key, "cleared") == 0;
	if (!known)
		return;
	if (l->ntok <= vi)
		die("%s:%ld: # %s: missing value", l->path, l->line, key);
	if (strcmp(key, "cleared") == 0) {
		if (strcmp(l->tok[vi], "yes") == 0)
			t->cleared = 1;
		else if (strcmp(l->tok[vi], "no") == 0)
			t->cleared = 0;
		else
			die("%s:%ld: # cleared: expected yes or no, found \"%.40s\"",
			    l->path, l->line, l->tok[vi]);
		*have_cleared = 1;
	} else if (strcmp(key, "swa") == 0) {
		t->swa = fmt_lines_opt(l, vi, "swa");
		t->have_swa = 1;
	} else {
		t->resist_loss = fmt_lines_opt(l, vi, "resist_loss");
	}
}

void fmt_measure_read(const char *path, struct measure_table *t)
{
	struct fmt_lines l;
	fmt_lines_open(&l, path);
	memset(t, 0, sizeof *t);
	t->swa = t->resist_loss = NAN;
	size_t cap = 0;
	int have_cleared = 0;
	while (fmt_lines_next(&l)) {
		if (l.ntok == 0)
			continue;
		if (t->ncols == 0) {
			if (!(t->ncols = header(&l, &t->hole, &t->have_err)))
				die("%s:%ld: not a measure table: expected a header \"# z cd ...\"",
				    path, l.line);
			continue;
		}
		if (l.tok[0][0] == '#') {
			figure(&l, t, &have_cleared);
			continue;
		}
		if (l.ntok != t->ncols)
			die("%s:%ld: expected %d fields as the header names, found %d", path,
			    l.line, t->ncols, l.ntok);
		struct measure_row w = {0, 0, {0, 0, 0}, 0};
		w.z = fmt_lines_num(&l, 0, "z");
		w.cd = fmt_lines_num(&l, 1, "cd");
		int nv = t->ncols - t->have_err;
		if (t->have_err && !((w.err = fmt_lines_num(&l, nv, "err")) >= 0))
			die("%s:%ld: err: expected an error estimate >= 0", path, l.line);
		for (int i = 2; i < nv; i++) {
			double v = fmt_lines_num(&l, i, "value");
			if (i - 2 < MEASURE_MAX_EXTRA)
				w.v[i - 2] = v;
		}
		xgrow(&t->rows, &cap, (size_t)t->nrows + 1, sizeof *t->rows);
		t->rows[t->nrows++] = w;
	}
	if (t->ncols == 0)
		die("%s:%ld: empty: not a measure table", path, l.line > 0 ? l.line : 1);
	if (t->nrows == 0)
		die("%s:%ld: measure table without rows", path, l.line);
	if (!have_cleared)
		die("%s:%ld: measure table without a \"# cleared yes|no\" line", path, l.line);
	fmt_lines_close(&l);
}

void fmt_measure_free(struct measure_table *t)
{
	free(t->rows);
	t->rows = NULL;
	t->nrows = 0;
}
