/*
 * lex.c - see lex.h.  Compressed input goes through a child "gzip -dc"
 * started with fork/exec (no shell, so any file name is safe); its exit
 * status is checked so that a corrupt archive is an error, not a short
 * file.  Its size is known only as it comes: the decompressed bytes are
 * counted while reading and the read stops, in one line, past the memory
 * limit (budget.h) or LEX_MAX_TEXT, so that a small archive cannot inflate
 * into gigabytes first.
 */
#include "lex.h"
#include "budget.h"
#include "fmt_kind.h"
#include "num.h"
#include "util.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

struct lex {
	char *name;
	char *buf;
	size_t len;
	size_t pos;
	long line;
	long nextline;
	char *tok;
	size_t tokcap;
	/* lex_line state */
	char **ltok;
	int *lquoted;
	size_t lcap;
	char *lbuf;
	size_t lbufcap;
	const char *expect;     /* lex_expect's pages, or NULL */
};

static int ends_with(const char *s, const char *suffix)
{
	size_t n = strlen(s), m = strlen(suffix);
	return n > m && strcmp(s + n - m, suffix) == 0;
}

/* The most a compressed file or stdin may give: max bytes (0: the
 * default, LEX_MAX_TEXT), and without -big no more than the memory
 * limit. */
static double stream_cap(double max)
{
	if (max <= 0)
		max = LEX_MAX_TEXT;
	if (!budget_big())
		max = fmin(max, budget_memory());
	return max;
}

/* Reads fd to its end, or until more than cap bytes (0: no limit) have
 * come: then *over is set and the buffer holds what came. */
static char *read_fd(int fd, const char *name, size_t *len, double cap, int *over)
{
	size_t cap0 = 0, n = 0;
	char *buf = NULL;
	*over = 0;
	for (;;) {
		if (cap > 0 && (double)n > cap) {
			*over = 1;
			break;
		}
		xgrow(&buf, &cap0, n + 65536 + 1, 1);
		ssize_t r = read(fd, buf + n, cap0 - n - 1);
		if (r < 0) {
			if (errno == EINTR)
				continue;
			die("%s: read error:", name);
		}
		if (r == 0)
			break;
		n += (size_t)r;
	}
	buf[n] = '\0';
	*len = n;
	return buf;
}

static _Noreturn void too_big(const char *ctx, const char *name, double cap)
{
	char b[16];
	die("%s%s%s: decompresses or streams to more than %s, beyond %s: use -big or "
	    "SAMPLE3D_BIG=1 to read it anyway", ctx ? ctx : "", ctx ? ": " : "", name,
	    budget_bytes(b, cap),
	    cap < LEX_MAX_TEXT ? "the memory limit" : "what a reader holds");
}

/* Starts "gzip -dc path" writing into *fd. */
static pid_t start_gzip(const char *path, int *fd)
{
	int pfd[2];
	if (pipe(pfd) != 0)
		die("%s: cannot make a pipe:", path);
	fflush(NULL);
	pid_t pid = fork();
	if (pid < 0)
		die("%s: cannot fork gzip:", path);
	if (pid == 0) {
		close(pfd[0]);
		if (dup2(pfd[1], 1) < 0)
			_exit(126);
		close(pfd[1]);
		execlp("gzip", "gzip", "-dc", "--", path, (char *)NULL);
		_exit(127);
	}
	close(pfd[1]);
	*fd = pfd[0];
	return pid;
}

/* Waits for gzip; stopped (the reader had enough) is not an error. */
static int wait_gzip(const char *path, pid_t pid, int stopped)
{
	if (stopped)
		kill(pid, SIGTERM);
	int st;
	while (waitpid(pid, &st, 0) < 0)
		if (errno != EINTR)
			die("%s: waiting for gzip:", path);
	if (stopped)
		return 0;
	if (WIFEXITED(st) && WEXITSTATUS(st) == 127)
		die("%s: cannot run gzip to read a compressed file", path);
	if (!WIFEXITED(st) || WEXITSTATUS(st) != 0)
		die("%s: gzip -dc failed: corrupt or not a compressed file", path);
	return 0;
}

static char *read_gzip(const char *path, const char *ctx, size_t *len, double cap)
{
	int fd, over;
	pid_t pid = start_gzip(path, &fd);
	char *buf = read_fd(fd, path, len, cap, &over);
	close(fd);
	wait_gzip(path, pid, over);
	if (over) {
		free(buf);
		too_big(ctx, path, cap);
	}
	return buf;
}

double lex_gz_scan(const char *path, double max,
		   void (*fn)(void *ctx, const char *buf, size_t n), void *ctx)
{
	int fd;
	pid_t pid = start_gzip(path, &fd);
	static char chunk[65536];
	double total = 0;
	int over = 0;
	for (;;) {
		ssize_t r = read(fd, chunk, sizeof chunk);
		if (r < 0 && errno == EINTR)
			continue;
		if (r <= 0)
			break;
		fn(ctx, chunk, (size_t)r);
		total += (double)r;
		if (total > max) {
			over = 1;
			break;
		}
	}
	close(fd);
	/* a corrupt archive is the reader's to report */
	if (over)
		kill(pid, SIGTERM);
	int st;
	while (waitpid(pid, &st, 0) < 0 && errno == EINTR)
		;
	return total;
}

int lex_compressed(const char *path)
{
	return ends_with(path, ".gz") || ends_with(path, ".Z");
}

void *lex_slurp_max(const char *path, const char *ctx, size_t *len, double max)
{
	double cap = stream_cap(max);
	int over;
	if (strcmp(path, "-") == 0) {
		char *buf = read_fd(0, "stdin", len, cap, &over);
		if (over) {
			free(buf);
			too_big(ctx, "stdin", cap);
		}
		return buf;
	}
	if (lex_compressed(path)) {
		FILE *t = fopen(path, "rb");
		if (!t)
			die("%s: cannot open:", path);
		fclose(t);
		return read_gzip(path, ctx, len, cap);
	}
	FILE *f = fopen(path, "rb");
	if (!f)
		die("%s: cannot open:", path);
	char *buf = read_fd(fileno(f), path, len, 0, &over);
	fclose(f);
	return buf;
}

void *lex_slurp(const char *path, size_t *len)
{
	return lex_slurp_max(path, NULL, len, 0);
}

static struct lex *lex_new(const char *name, char *buf, size_t len)
{
	struct lex *lx = xcalloc(1, sizeof *lx);
	lx->name = xstrdup(name);
	lx->buf = buf;
	lx->len = len;
	lx->line = 1;
	lx->nextline = 1;
	return lx;
}

struct lex *lex_open(const char *path)
{
	size_t len;
	char *buf = lex_slurp(path, &len);
	return lex_new(strcmp(path, "-") == 0 ? "stdin" : path, buf, len);
}

struct lex *lex_from_memory(const char *name, const void *data, size_t len)
{
	char *buf = xmalloc(len + 1);
	memcpy(buf, data, len);
	buf[len] = '\0';
	return lex_new(name, buf, len);
}

void lex_close(struct lex *lx)
{
	if (!lx)
		return;
	free(lx->name);
	free(lx->buf);
	free(lx->tok);
	free(lx->ltok);
	free(lx->lquoted);
	free(lx->lbuf);
	free(lx);
}

const char *lex_name(const struct lex *lx) { return lx->name; }
long lex_lineno(const struct lex *lx) { return lx->line; }

void lex_expect(struct lex *lx, const char *pages)
{
	lx->expect = pages;
}

void lex_error(const struct lex *lx, const char *fmt, ...)
{
	if (lx->expect) {
		const struct fmt_kind *k = fmt_kind_of(lx->buf, lx->len);
		if (k && !strstr(lx->expect, k->page))
			die("%s:1: this is %s (%s); %s reads %s", lx->name, k->what, k->page,
			    util_prog(), lx->expect);
	}
	char msg[512];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	die("%s:%ld: %s", lx->name, lx->line, msg);
}

static int is_sep(int c)
{
	return c == ' ' || c == '\t' || c == '\n' || c == '\r' ||
	       c == '\f' || c == '\v' || c == ',';
}

static void skip_sep(struct lex *lx)
{
	while (lx->pos < lx->len && is_sep((unsigned char)lx->buf[lx->pos])) {
		if (lx->buf[lx->pos] == '\n')
			lx->nextline++;
		lx->pos++;
	}
}

const char *lex_token(struct lex *lx)
{
	skip_sep(lx);
	if (lx->pos >= lx->len)
		return NULL;
	size_t start = lx->pos;
	while (lx->pos < lx->len && !is_sep((unsigned char)lx->buf[lx->pos]))
		lx->pos++;
	size_t n = lx->pos - start;
	xgrow(&lx->tok, &lx->tokcap, n + 1, 1);
	memcpy(lx->tok, lx->buf + start, n);
	lx->tok[n] = '\0';
	lx->line = lx->nextline;
	/* a NUL would silently end the token: "80\0 9" must not read as 80 */
	if (memchr(lx->buf + start, '\0', n))
		lex_error(lx, "NUL byte in the input (a binary file?)");
	return lx->tok;
}

int lex_at_end(struct lex *lx)
{
	skip_sep(lx);
	return lx->pos >= lx->len;
}

const char *lex_comment(struct lex *lx)
{
	skip_sep(lx);
	if (lx->pos >= lx->len || lx->buf[lx->pos] != '#')
		return NULL;
	size_t start = ++lx->pos;
	while (lx->pos < lx->len && lx->buf[lx->pos] != '\n')
		lx->pos++;
	size_t n = lx->pos - start;
	lx->line = lx->nextline;
	if (memchr(lx->buf + start, '\0', n))
		lex_error(lx, "NUL byte in the line (a binary file?)");
	xgrow(&lx->lbuf, &lx->lbufcap, n + 1, 1);
	memcpy(lx->lbuf, lx->buf + start, n);
	lx->lbuf[n] = '\0';
	return lx->lbuf;
}

/* A token quoted for a message: printable, at most 24 characters. */
static const char *shown(const char *t, char *out, size_t cap)
{
	size_t j = 0;
	for (size_t i = 0; t[i] && j + 4 < cap && i < 24; i++)
		out[j++] = (t[i] >= 32 && t[i] < 127) ? t[i] : '?';
	if (strlen(t) > 24 && j + 4 < cap)
		out[j++] = '.', out[j++] = '.', out[j++] = '.';
	out[j] = '\0';
	return out;
}

/* lex_number and lex_numberf: the description of the field is only
 * formatted when it goes into an error message. */
static double number(struct lex *lx, const char *fmt, va_list ap)
{
	/* fast path: strtod in place, accepted only when the number ends at
	 * a separator or the end of the input and is finite, exactly what
	 * num_parse accepts of a token; anything else takes the token path,
	 * which also makes the message */
	skip_sep(lx);
	if (lx->pos < lx->len) {
		const char *p = lx->buf + lx->pos;
		char *end;
		double v = strtod(p, &end);
		if (end > p && (end == lx->buf + lx->len || is_sep((unsigned char)*end)) &&
		    isfinite(v)) {
			lx->pos = (size_t)(end - lx->buf);
			lx->line = lx->nextline;
			return v;
		}
	}
	const char *t = lex_token(lx);
	double v;
	if (t && num_parse(t, &v))
		return v;
	char what[160];
	vsnprintf(what, sizeof what, fmt, ap);
	if (!t) {
		lx->line = lx->nextline;
		lex_error(lx, "expected %s, found end of file", what);
	}
	char s[40];
	lex_error(lx, "expected %s (a finite number), found \"%s\"",
		  what, shown(t, s, sizeof s));
}

double lex_number(struct lex *lx, const char *what)
{
	return lex_numberf(lx, "%s", what);
}

double lex_numberf(struct lex *lx, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	double v = number(lx, fmt, ap);
	va_end(ap);
	return v;
}

long lex_count(struct lex *lx, const char *what, long min, long max)
{
	const char *t = lex_token(lx);
	if (!t) {
		lx->line = lx->nextline;
		lex_error(lx, "expected %s, found end of file", what);
	}
	long v;
	if (!num_parse_count(t, min, max, &v)) {
		char s[40];
		lex_error(lx, "expected %s (a whole number from %ld to %ld), found \"%s\"",
			  what, min, max, shown(t, s, sizeof s));
	}
	return v;
}

int lex_line(struct lex *lx, char ***tokens, const int **quoted)
{
	for (;;) {
		if (lx->pos >= lx->len)
			return 0;
		size_t start = lx->pos;
		while (lx->pos < lx->len && lx->buf[lx->pos] != '\n')
			lx->pos++;
		size_t n = lx->pos - start;
		if (lx->pos < lx->len)
			lx->pos++; /* the newline */
		lx->line = lx->nextline++;
		/* a NUL would silently end the line: "dose 80\0 9" is an error,
		 * as "dose 80 9" is */
		if (memchr(lx->buf + start, '\0', n))
			lex_error(lx, "NUL byte in the line (a binary file?)");
		xgrow(&lx->lbuf, &lx->lbufcap, n + 1, 1);
		memcpy(lx->lbuf, lx->buf + start, n);
		lx->lbuf[n] = '\0';

		size_t nt = 0;
		char *p = lx->lbuf;
		for (;;) {
			while (*p == ' ' || *p == '\t' || *p == '\r' ||
			       *p == '\f' || *p == '\v')
				p++;
			if (!*p || *p == '#')
				break;
			int q = *p == '"';
			char *t = q ? ++p : p;
			if (q) {
				while (*p && *p != '"')
					p++;
				if (!*p)
					lex_error(lx, "unterminated quoted string");
			} else {
				while (*p && *p != ' ' && *p != '\t' && *p != '\r' &&
				       *p != '\f' && *p != '\v' && *p != '#')
					p++;
			}
			char c = *p;
			*p = '\0';
			xgrow(&lx->ltok, &lx->lcap, nt + 1, sizeof *lx->ltok);
			size_t qcap = lx->lcap;
			lx->lquoted = xreallocarray(lx->lquoted, qcap, sizeof *lx->lquoted);
			lx->ltok[nt] = t;
			lx->lquoted[nt] = q;
			nt++;
			if (q)
				p++;
			else if (c == '#')
				break; /* a comment right after a word */
			else if (c)
				p++;
			else
				break;
		}
		if (nt == 0)
			continue;
		*tokens = lx->ltok;
		if (quoted)
			*quoted = lx->lquoted;
		return (int)nt;
	}
}
