/*
 * fmt_fem.c - fem.dat, window.dat and the reading of measure(1)'s table
 * (see fmt_fem.h and man/man5/fem.5).
 *
 * These are line tables whose header is a '#' line, so they are read line
 * by line here (lex_line would drop the header as a comment): the whole
 * file is slurped through the library reader, split at newlines and each
 * line at blanks, with the line number kept for messages.
 */
#include "fmt_fem.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAXTOK = 64 };

static const char *const fem_cols[] = {
	"focus", "dose", "cd", "swa", "cleared", "resist_loss"
};
enum { FEM_NCOLS = 6 };

static const char *const win_cols[] = {
	"el", "dof", "focus_centre", "dose_centre"
};

/* A slurped file and a cursor over its lines. */
struct lines {
	const char *path;
	char *buf;
	size_t len, pos;
	long line;
	char *tok[MAXTOK];
	int ntok;
};

static void lines_open(struct lines *l, const char *path)
{
	memset(l, 0, sizeof *l);
	l->path = path;
	l->buf = lex_slurp(path, &l->len);
	if (memchr(l->buf, '\0', l->len))
		die("%s:1: not a text file (NUL byte)", path);
}

/* Splits the next line into l->tok; returns 0 at the end of the file.
 * Blank lines are returned with ntok 0. */
static int lines_next(struct lines *l)
{
	if (l->pos >= l->len)
		return 0;
	char *s = l->buf + l->pos;
	char *e = memchr(s, '\n', l->len - l->pos);
	if (e) {
		*e = '\0';
		l->pos = (size_t)(e - l->buf) + 1;
	} else {
		/* the buffer has one spare byte past the end (lex_slurp) */
		l->buf[l->len] = '\0';
		l->pos = l->len;
	}
	l->line++;
	l->ntok = 0;
	for (char *t = strtok(s, " \t\r"); t; t = strtok(NULL, " \t\r")) {
		if (l->ntok == MAXTOK)
			die("%s:%ld: more than %d fields", l->path, l->line, MAXTOK);
		l->tok[l->ntok++] = t;
	}
	return 1;
}

static double field_num(struct lines *l, int i, const char *what)
{
	double v;
	if (!num_parse(l->tok[i], &v))
		die("%s:%ld: %s: expected a number, found \"%.40s\"", l->path, l->line,
		    what, l->tok[i]);
	return v;
}

/* A number or "-" (absent, NAN). */
static double field_opt(struct lines *l, int i, const char *what)
{
	if (strcmp(l->tok[i], "-") == 0)
		return NAN;
	return field_num(l, i, what);
}

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
	struct lines l;
	lines_open(&l, path);
	struct fem_table *t = xcalloc(1, sizeof *t);
	size_t cap = 0;
	int header = 0;
	while (lines_next(&l)) {
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
		p.focus = field_num(&l, 0, "focus");
		p.dose = field_num(&l, 1, "dose");
		p.cd = field_num(&l, 2, "cd");
		p.swa = field_opt(&l, 3, "swa");
		long c;
		if (!num_parse_count(l.tok[4], 0, 1, &c))
			die("%s:%ld: cleared: expected 1 or 0, found \"%.40s\"", path, l.line, l.tok[4]);
		p.cleared = (int)c;
		p.loss = field_opt(&l, 5, "resist_loss");
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
	free(l.buf);
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

/* measure(1): "# z cd ..." then rows, then "# swa DEG" ("-" where the
 * angle is undefined), "# resist_loss UM", "# cleared yes|no"; other
 * comment lines are skipped. */
void fmt_fem_read_measure(const char *path, struct fem_measure *m)
{
	struct lines l;
	lines_open(&l, path);
	int ncols = 0, rows = 0, have_cleared = 0;
	m->swa = m->loss = NAN;
	m->z = m->cd = 0;
	m->cleared = 0;
	while (lines_next(&l)) {
		if (l.ntok == 0)
			continue;
		if (ncols == 0) {
			if (l.ntok < 3 || strcmp(l.tok[0], "#") != 0 ||
			    strcmp(l.tok[1], "z") != 0 || strcmp(l.tok[2], "cd") != 0)
				die("%s:%ld: not a measure table: expected a header \"# z cd ...\"",
				    path, l.line);
			ncols = l.ntok - 1;
			continue;
		}
		if (l.tok[0][0] == '#') {
			const char *key = l.tok[0][1] ? l.tok[0] + 1 : (l.ntok > 1 ? l.tok[1] : "");
			int vi = l.tok[0][1] ? 1 : 2;
			int known = strcmp(key, "swa") == 0 || strcmp(key, "resist_loss") == 0 ||
				    strcmp(key, "cleared") == 0;
			if (!known)
				continue;
			if (l.ntok <= vi)
				die("%s:%ld: # %s: missing value", path, l.line, key);
			if (strcmp(key, "cleared") == 0) {
				if (strcmp(l.tok[vi], "yes") == 0)
					m->cleared = 1;
				else if (strcmp(l.tok[vi], "no") == 0)
					m->cleared = 0;
				else
					die("%s:%ld: # cleared: expected yes or no, found \"%.40s\"",
					    path, l.line, l.tok[vi]);
				have_cleared = 1;
			} else if (strcmp(key, "swa") == 0) {
				m->swa = field_opt(&l, vi, "swa");
			} else {
				m->loss = field_opt(&l, vi, "resist_loss");
			}
			continue;
		}
		if (l.ntok != ncols)
			die("%s:%ld: expected %d fields as the header names, found %d", path,
			    l.line, ncols, l.ntok);
		double z = field_num(&l, 0, "z"), cd = field_num(&l, 1, "cd");
		for (int i = 2; i < ncols; i++)
			(void)field_num(&l, i, "value");
		if (rows++ == 0) {
			m->z = z;
			m->cd = cd;
		}
	}
	if (ncols == 0)
		die("%s:%ld: empty: not a measure table", path, l.line > 0 ? l.line : 1);
	if (rows == 0)
		die("%s:%ld: measure table without rows", path, l.line);
	if (!have_cleared)
		die("%s:%ld: measure table without a \"# cleared yes|no\" line", path, l.line);
	if (!(m->cd >= 0))
		die("%s: negative cd", path);
	free(l.buf);
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
