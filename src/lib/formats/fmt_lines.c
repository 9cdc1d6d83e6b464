/*
 * fmt_lines.c - line tables with a '#' header (fmt_lines.h).
 */
#include "fmt_lines.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void fmt_lines_open(struct fmt_lines *l, const char *path)
{
	memset(l, 0, sizeof *l);
	l->path = path;
	l->buf = lex_slurp(path, &l->len);
	if (memchr(l->buf, '\0', l->len))
		die("%s:1: not a text file (NUL byte)", path);
}

int fmt_lines_next(struct fmt_lines *l)
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
		if (l->ntok == FMT_LINES_MAXTOK)
			die("%s:%ld: more than %d fields", l->path, l->line, FMT_LINES_MAXTOK);
		l->tok[l->ntok++] = t;
	}
	return 1;
}

double fmt_lines_num(struct fmt_lines *l, int i, const char *what)
{
	double v;
	if (!num_parse(l->tok[i], &v))
		die("%s:%ld: %s: expected a number, found \"%.40s\"", l->path, l->line,
		    what, l->tok[i]);
	return v;
}

double fmt_lines_opt(struct fmt_lines *l, int i, const char *what)
{
	if (strcmp(l->tok[i], "-") == 0)
		return NAN;
	return fmt_lines_num(l, i, what);
}

void fmt_lines_close(struct fmt_lines *l)
{
	free(l->buf);
	l->buf = NULL;
}
