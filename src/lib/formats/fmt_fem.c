/*
 * fmt_fem.c - fem.dat and window.dat (see fmt_fem.h and man/man5/fem.5),
 * line tables whose header is a '#' line, read by fmt_lines.c.
 */
#include "fmt_fem.h"
#include "fmt_lines.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const fem_cols[] = {
	"focus", "dose", "cd", "swa", "cleared", "resist_loss"
};
enum { FEM_NCOLS = 6 };

static const char *const win_cols[] = {
	"el", "dof", "focus_centre", "dose_centre"
};

static int point_cmp(const struct fem_point *a, const struct fem_point *b)
{
	if (a->focus != b->focus)
		return a->focus < b->focus ? -1 : 1;
	if (a->dose != b->dose)
		return a->dose < b->dose ? -1 : 1;
	return 0;
}

struct fem_table *fmt_fem_read(const char *path)
{
	struct fmt_lines l;
	fmt_lines_open(&l, path);
	struct fem_table *t = xcalloc(1, sizeof *t);
	size_t cap = 0;
	int header = 0;
	while (fmt_lines_next(&l)) {
		if (l.ntok == 0)
			continue;
		if (!header) {
			int ok = l.ntok == FEM_NCOLS + 1 && strcmp(l.tok[0], "#") == 0;
			for (int i = 0; ok && i < FEM_NCOLS; i++)
				ok = strcmp(l.tok[i + 1], fem_cols[i]) == 0;
			if (!ok)
				die("%s:%ld: expected the header \"# focus dose cd swa cleared resist_loss\"",
				    path, l.line);
			header = 1;
			continue;
		}
		if (l.tok[0][0] == '#')
			continue;
		if (l.ntok != FEM_NCOLS)
			die("%s:%ld: expected %d fields (focus dose cd swa cleared resist_loss), found %d",
			    path, l.line, FEM_NCOLS, l.ntok);
		if (t->n == FEM_MAX_POINTS)
			die("%s:%ld: more than %d points", path, l.line, FEM_MAX_POINTS);
		struct fem_point p;
		p.focus = fmt_lines_num(&l, 0, "focus");
		p.dose = fmt_lines_num(&l, 1, "dose");
		p.cd = fmt_lines_num(&l, 2, "cd");
		p.swa = fmt_lines_opt(&l, 3, "swa");
		long c;
		if (!num_parse_count(l.tok[4], 0, 1, &c))
			die("%s:%ld: cleared: expected 1 or 0, found \"%.40s\"", path, l.line, l.tok[4]);
		p.cleared = (int)c;
		p.loss = fmt_lines_opt(&l, 5, "resist_loss");
		if (!(p.dose > 0))
			die("%s:%ld: dose must be positive", path, l.line);
		if (!(p.cd >= 0))
			die("%s:%ld: cd must not be negative", path, l.line);
		if (t->n > 0 && point_cmp(&t->p[t->n - 1], &p) >= 0)
			die("%s:%ld: rows must be in ascending (focus, dose) order, each point once",
			    path, l.line);
		xgrow(&t->p, &cap, (size_t)t->n + 1, sizeof *t->p);
		t->p[t->n++] = p;
	}
	if (!header)
		die("%s:%ld: empty file: expected the header \"# focus dose cd swa cleared resist_loss\"",
		    path, l.line > 0 ? l.line : 1);
	fmt_lines_close(&l);
	return t;
}

static void print_opt(FILE *f, double v)
{
	if (isnan(v))
		fputc('-', f);
	else
		num_print(f, v);
}

void fmt_fem_write(const char *path, const struct fem_table *t)
{
	for (int i = 1; i < t->n; i++)
		if (point_cmp(&t->p[i - 1], &t->p[i]) >= 0)
			die("%s: internal error: points out of order", path);
	struct aout *a = aout_open(path);
	fputc('#', a->f);
	for (int i = 0; i < FEM_NCOLS; i++)
		fprintf(a->f, " %s", fem_cols[i]);
	fputc('\n', a->f);
	for (int i = 0; i < t->n; i++) {
		const struct fem_point *p = &t->p[i];
		num_print(a->f, p->focus);
		fputc(' ', a->f);
		num_print(a->f, p->dose);
		fputc(' ', a->f);
		num_print(a->f, p->cd);
		fputc(' ', a->f);
		print_opt(a->f, p->swa);
		fprintf(a->f, " %d ", p->cleared ? 1 : 0);
		print_opt(a->f, p->loss);
		fputc('\n', a->f);
	}
	aout_commit(a);
}

void fmt_fem_free(struct fem_table *t)
{
	if (!t)
		return;
	free(t->p);
	free(t);
}

static int point_qcmp(const void *a, const void *b)
{
	return point_cmp(a, b);
}

/* The table being read, kept reachable from here: a bad line dies at
 * once, and the leak checker of the sanitizer runs would otherwise count
 * the table as lost (volatile: a store never read back is otherwise
 * dropped). */
static struct fem_table *volatile being_read;

struct fem_table *fmt_fem_read_cds(const char *path)
{
	/* rows in any order: sorted, then a repeated point is a neighbour */
	struct fmt_lines l;
	fmt_lines_open(&l, path);
	struct fem_table *t = being_read = xcalloc(1, sizeof *t);
	size_t cap = 0;
	while (fmt_lines_next(&l)) {
		if (l.ntok == 0 || l.tok[0][0] == '#')
			continue;
		if (l.ntok < 3)
			die("%s:%ld: expected focus dose cd, found %d field%s", path, l.line,
			    l.ntok, l.ntok == 1 ? "" : "s");
		if (t->n == FEM_MAX_POINTS)
			die("%s:%ld: more than %d points", path, l.line, FEM_MAX_POINTS);
		struct fem_point p = {0, 0, 0, NAN, 1, NAN};
		p.focus = fmt_lines_num(&l, 0, "focus");
		p.dose = fmt_lines_num(&l, 1, "dose");
		p.cd = fmt_lines_num(&l, 2, "cd");
		if (!(p.dose > 0))
			die("%s:%ld: dose must be positive", path, l.line);
		if (!(p.cd > 0))
			die("%s:%ld: cd must be positive (a measured CD, um)", path, l.line);
		xgrow(&t->p, &cap, (size_t)t->n + 1, sizeof *t->p);
		t->p[t->n++] = p;
	}
	if (t->n == 0)
		die("%s:%ld: no measured point (rows focus dose cd)", path, l.line > 0 ? l.line : 1);
	qsort(t->p, (size_t)t->n, sizeof *t->p, point_qcmp);
	for (int i = 1; i < t->n; i++)
		if (point_cmp(&t->p[i - 1], &t->p[i]) == 0) {
			char f[NUM_BUFSZ], d[NUM_BUFSZ];
			die("%s: the point focus %s dose %s is given twice", path,
			    num_fmt(f, t->p[i].focus), num_fmt(d, t->p[i].dose));
		}
	fmt_lines_close(&l);
	being_read = NULL;
	return t;
}

void fmt_fem_window_write(const char *path, const struct fem_window_row *r, int n)
{
	struct aout *a = aout_open(path);
	fputc('#', a->f);
	for (int i = 0; i < 4; i++)
		fprintf(a->f, " %s", win_cols[i]);
	fputc('\n', a->f);
	for (int i = 0; i < n; i++) {
		double v[4] = {r[i].el, r[i].dof, r[i].focus, r[i].dose};
		num_print_row(a->f, v, 4);
	}
	aout_commit(a);
}

void fmt_fem_stoch_write(const char *path, const struct fem_stoch_row *r, int n)
{
	struct aout *a = aout_open(path);
	fputs("# focus dose cd cd_3sigma failures seeds\n", a->f);
	for (int i = 0; i < n; i++) {
		double v[6] = {r[i].focus, r[i].dose, r[i].cd, r[i].cd3s, r[i].failures, r[i].seeds};
		num_print_row(a->f, v, 6);
	}
	aout_commit(a);
}
