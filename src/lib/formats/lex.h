/*
 * lex.h - the one input reader behind every file format.
 *
 * A whole input is read into memory first (a file, "-" for stdin, or a
 * .gz/.Z file through "gzip -dc"), so that readers can check sizes against
 * what the input really holds before allocating.  Two ways to consume it:
 *   - tokens (numeric formats): whitespace and commas separate fields;
 *   - lines (keyword formats): '#' starts a comment, "quoted strings" are
 *     one token.
 * Every error names the file and line: "prog: file:line: what is wrong".
 */
#ifndef S3D_LEX_H
#define S3D_LEX_H

#include <stddef.h>

struct lex;     /* opaque */

/* The name shown in messages and the line of the last token returned. */
const char *lex_name(const struct lex *lx);
long lex_lineno(const struct lex *lx);

/* Reads all of path ("-" is stdin); dies if it cannot. */
struct lex *lex_open(const char *path);
/* Wraps a memory buffer (copied); name is used in messages. */
struct lex *lex_from_memory(const char *name, const void *data, size_t len);
void lex_close(struct lex *lx);

/* Reads the whole of path into a malloc'd buffer (gzip-aware); the caller
 * frees it.  Used for binary formats.  A compressed file or stdin is
 * counted as it comes and refused in one line past LEX_MAX_TEXT bytes or,
 * without -big, past the memory limit (budget.h); lex_slurp_max lowers
 * the first to max bytes (0: LEX_MAX_TEXT) and puts "ctx: " (if not
 * NULL) before the file in its messages.  lex_open reads the same way. */
#define LEX_MAX_TEXT 4e9
void *lex_slurp(const char *path, size_t *len);
void *lex_slurp_max(const char *path, const char *ctx, size_t *len, double max);
/* 1 if path names a compressed file (.gz, .Z). */
int lex_compressed(const char *path);
/* Streams the decompressed bytes of compressed file path to fn, chunk by
 * chunk, holding none of them, and stops once more than max bytes have
 * come; returns the bytes seen.  A corrupt archive just ends early (the
 * reader reports it).  For estimates made before a read. */
double lex_gz_scan(const char *path, double max,
		   void (*fn)(void *ctx, const char *buf, size_t n), void *ctx);

/* Next whitespace/comma-separated token, or NULL at end of input. */
const char *lex_token(struct lex *lx);
/* 1 if only whitespace remains. */
int lex_at_end(struct lex *lx);
/* Next token as a finite number; dies "expected WHAT" otherwise. */
double lex_number(struct lex *lx, const char *what);
/* The same, WHAT given as a printf format that is only formatted for the
 * error message (for readers of millions of numbers). */
double lex_numberf(struct lex *lx, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* Next token as a count in [min, max] ("4.0" accepted). */
long lex_count(struct lex *lx, const char *what, long min, long max);

/* Next non-empty line split into tokens (comments stripped, quotes
 * removed from quoted tokens).  Returns the token count, 0 at end of
 * input.  The pointers stay valid until the next call.  quoted[i] tells
 * whether token i was quoted (NULL allowed). */
int lex_line(struct lex *lx, char ***tokens, const int **quoted);

/* Token readers: if the next non-blank input starts with '#', the rest
 * of that line after the '#' (valid until the next call; the line is
 * consumed and becomes the current line); NULL otherwise, nothing
 * consumed.  For the comment lines a numeric format allows at its head. */
const char *lex_comment(struct lex *lx);

/* Names the manual pages of the kinds the reader takes ("plot3d(5)",
 * "stack(5) or contour(5)"): lex_error then first checks the kind of the
 * input from its first bytes (fmt_kind.h), and when the input is of
 * another kind says so instead, "prog: file:1: this is a rate file
 * (rval(5)); prog reads plot3d(5)". */
void lex_expect(struct lex *lx, const char *pages);

/* Dies with "prog: file:line: message" at the current line. */
_Noreturn void lex_error(const struct lex *lx, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));

#endif
