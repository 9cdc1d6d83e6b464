/*
 * fmt_lines.h - the reader of line tables whose header is a '#' line
 * (fem.dat, measure's table): lex's line reader would drop that header
 * as a comment, so the whole file is slurped through the library reader
 * (lex_slurp), split at newlines and each line at blanks, with the line
 * number kept for messages.  Used by fmt_fem.c and fmt_measure.c.
 */
#ifndef S3D_FMT_LINES_H
#define S3D_FMT_LINES_H

#include <stddef.h>

enum { FMT_LINES_MAXTOK = 64 };

/* A slurped file and a cursor over its lines. */
struct fmt_lines {
	const char *path;
	char *buf;
	size_t len, pos;
	long line;                      /* of the line last split */
	char *tok[FMT_LINES_MAXTOK];
	int ntok;
};

/* Reads path whole; dies if it cannot or if it holds a NUL byte. */
void fmt_lines_open(struct fmt_lines *l, const char *path);
/* Splits the next line into l->tok; returns 0 at the end of the file.
 * Blank lines are returned with ntok 0; more than FMT_LINES_MAXTOK
 * fields die. */
int fmt_lines_next(struct fmt_lines *l);
/* Field i as a finite number; dies "file:line: what: expected a number". */
double fmt_lines_num(struct fmt_lines *l, int i, const char *what);
/* A number or "-" (absent: NAN). */
double fmt_lines_opt(struct fmt_lines *l, int i, const char *what);
void fmt_lines_close(struct fmt_lines *l);

#endif
