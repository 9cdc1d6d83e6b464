/*
 * util.c - see util.h.  The list of open temporaries is a small array:
 * a program has at most a handful of outputs open at once.
 */
#include "util.h"

#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *progname = "sample3d";
static int die_code = EXIT_RUNTIME;

void util_set_die_status(int status) { die_code = status; }

enum { MAX_TEMPS = 32 };
static char *temps[MAX_TEMPS];

void util_setprog(const char *argv0)
{
	const char *s = strrchr(argv0, '/');
	progname = s ? s + 1 : argv0;
}

const char *util_prog(void) { return progname; }

static void remove_temps(void)
{
	for (int i = 0; i < MAX_TEMPS; i++)
		if (temps[i]) {
			remove(temps[i]);
			free(temps[i]);
			temps[i] = NULL;
		}
}

static void vmsg(const char *fmt, va_list ap)
{
	int saved = errno;
	fflush(stdout);
	fprintf(stderr, "%s: ", progname);
	vfprintf(stderr, fmt, ap);
	size_t n = strlen(fmt);
	if (n > 0 && fmt[n - 1] == ':')
		fprintf(stderr, " %s", strerror(saved));
	fputc('\n', stderr);
}

void die(const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vmsg(fmt, ap);
	va_end(ap);
	remove_temps();
	exit(die_code);
}

void die_status(int status, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vmsg(fmt, ap);
	va_end(ap);
	remove_temps();
	exit(status);
}

void warn(const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vmsg(fmt, ap);
	va_end(ap);
}

void *xmalloc(size_t size)
{
	void *p = malloc(size ? size : 1);
	if (!p)
		die("out of memory (%zu bytes)", size);
	return p;
}

void *xcalloc(size_t count, size_t size)
{
	void *p = calloc(count ? count : 1, size ? size : 1);
	if (!p)
		die("out of memory (%zu x %zu bytes)", count, size);
	return p;
}

void *xreallocarray(void *p, size_t count, size_t size)
{
	if (size && count > SIZE_MAX / size)
		die("out of memory (%zu x %zu bytes overflows)", count, size);
	size_t n = count * size;
	void *q = realloc(p, n ? n : 1);
	if (!q)
		die("out of memory (%zu bytes)", n);
	return q;
}

char *xstrdup(const char *s)
{
	size_t n = strlen(s) + 1;
	char *p = xmalloc(n);
	memcpy(p, s, n);
	return p;
}

void xgrow(void *pp, size_t *cap, size_t need, size_t size)
{
	void **p = pp;
	if (need <= *cap)
		return;
	size_t c = *cap ? *cap : 16;
	while (c < need) {
		if (c > SIZE_MAX / 2)
			die("out of memory (array of %zu elements)", need);
		c *= 2;
	}
	*p = xreallocarray(*p, c, size);
	*cap = c;
}

void fshut(FILE *f, const char *name)
{
	int bad = fflush(f) != 0;
	bad |= ferror(f) != 0;
	if (f != stdout && f != stderr)
		bad |= fclose(f) != 0;
	if (bad)
		die("%s: write error:", name);
}

static int add_temp(const char *tmp)
{
	for (int i = 0; i < MAX_TEMPS; i++)
		if (!temps[i]) {
			temps[i] = xstrdup(tmp);
			return i;
		}
	die("too many output files open at once");
}

static void drop_temp(const char *tmp)
{
	for (int i = 0; i < MAX_TEMPS; i++)
		if (temps[i] && strcmp(temps[i], tmp) == 0) {
			free(temps[i]);
			temps[i] = NULL;
			return;
		}
}

struct aout *aout_open(const char *path)
{
	struct aout *a = xcalloc(1, sizeof *a);
	a->path = xstrdup(path);
	if (strcmp(path, "-") == 0) {
		a->f = stdout;
		return a;
	}
	size_t n = strlen(path) + 16;
	a->tmp = xmalloc(n);
	snprintf(a->tmp, n, "%s.tmpXXXXXX", path);
	int fd = mkstemp(a->tmp);
	if (fd < 0)
		die("%s: cannot create:", path);
	add_temp(a->tmp);
	a->f = fdopen(fd, "w");
	if (!a->f)
		die("%s: cannot open:", path);
	return a;
}

void aout_commit(struct aout *a)
{
	if (!a->tmp) {
		fshut(a->f, "stdout");
	} else {
		fshut(a->f, a->path);
		/* mkstemp made the file 0600; give it the usual mode */
		mode_t m = umask(0);
		umask(m);
		if (chmod(a->tmp, 0666 & ~m) != 0)
			die("%s: cannot set mode:", a->path);
		if (rename(a->tmp, a->path) != 0)
			die("%s: cannot rename:", a->path);
		drop_temp(a->tmp);
	}
	free(a->tmp);
	free(a->path);
	free(a);
}

void aout_abort(struct aout *a)
{
	if (a->tmp) {
		fclose(a->f);
		remove(a->tmp);
		drop_temp(a->tmp);
	}
	free(a->tmp);
	free(a->path);
	free(a);
}
