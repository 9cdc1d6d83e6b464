/*
 * util.c - see util.h.  The list of open temporaries is a small array:
 * a program has at most a handful of outputs open at once.  The signal
 * handler reads that array, so every change to it is made with the
 * signals blocked, and the handler calls only unlink, signal and raise
 * (async-signal-safe).
 */
#include "util.h"

#include <errno.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *progname = "sample3d";
static int die_code = EXIT_RUNTIME;

void util_set_die_status(int status) { die_code = status; }

static void (*die_hook)(int);
void util_set_die_hook(void (*hook)(int status)) { die_hook = hook; }

enum { MAX_TEMPS = 32 };
static char *volatile temps[MAX_TEMPS];
/* aout_defer: committed temporaries waiting for aout_finish */
static int deferring;
static char *pend_tmp[MAX_TEMPS], *pend_path[MAX_TEMPS];
static int npend;

static const int catch_sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
enum { NCATCH = sizeof catch_sigs / sizeof catch_sigs[0] };

/* aout_keep_on_signal: what the marked units are ("print times"), NULL
 * when an interrupted output is removed whole; per temporary, its target
 * and the length and unit count of its last aout_mark. */
static const char *volatile keep_what;
static char *volatile keep_path[MAX_TEMPS];
static volatile off_t keep_len[MAX_TEMPS];
static volatile long keep_units[MAX_TEMPS];

/* write(2) of a string and of a count, for the signal handler (no stdio) */
static void put_s(const char *s)
{
	ssize_t r = write(2, s, strlen(s));
	(void)r;
}

static void put_l(long v)
{
	char b[24];
	int n = (int)sizeof b;
	do
		b[--n] = (char)('0' + v % 10);
	while ((v /= 10) > 0 && n > 0);
	ssize_t r = write(2, b + n, sizeof b - (size_t)n);
	(void)r;
}

/* The kept outputs of an interrupted run (aout_keep_on_signal): each
 * marked temporary is cut back to its last mark and renamed over its
 * target, and one line says so.  Only async-signal-safe calls. */
static void keep_marked(void)
{
	int first = -1;
	mode_t m = umask(0);
	umask(m);
	for (int i = 0; i < MAX_TEMPS; i++)
		if (temps[i] && keep_path[i] && keep_units[i] > 0 &&
		    truncate(temps[i], keep_len[i]) == 0 && chmod(temps[i], 0666 & ~m) == 0 &&
		    rename(temps[i], keep_path[i]) == 0) {
			temps[i] = NULL;
			if (first < 0)
				first = i;
		}
	put_s(progname);
	if (first < 0) {
		put_s(": interrupted before the first of the ");
		put_s(keep_what);
		put_s(": nothing written\n");
		return;
	}
	put_s(": interrupted: ");
	put_s(keep_path[first]);
	put_s(" keeps the ");
	put_l(keep_units[first]);
	put_s(" ");
	put_s(keep_what);
	put_s(" finished\n");
}

static void on_signal(int sig)
{
	if (keep_what && sig != SIGPIPE)
		keep_marked();
	for (int i = 0; i < MAX_TEMPS; i++)
		if (temps[i])
			unlink(temps[i]);
	signal(sig, SIG_DFL);
	raise(sig);
}

static void catch_signals(void)
{
	static int done;
	if (done)
		return;
	done = 1;
	for (int i = 0; i < NCATCH; i++) {
		struct sigaction sa, old;
		if (sigaction(catch_sigs[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
			continue;   /* nohup, or a parent that ignores SIGPIPE */
		memset(&sa, 0, sizeof sa);
		sa.sa_handler = on_signal;
		sigemptyset(&sa.sa_mask);
		sigaction(catch_sigs[i], &sa, NULL);
	}
}

/* Blocks (on = 1) or restores the caught signals around changes to temps. */
static void block(int on, sigset_t *saved)
{
	if (on) {
		sigset_t s;
		sigemptyset(&s);
		for (int i = 0; i < NCATCH; i++)
			sigaddset(&s, catch_sigs[i]);
		sigprocmask(SIG_BLOCK, &s, saved);
	} else {
		sigprocmask(SIG_SETMASK, saved, NULL);
	}
}

void util_setprog(const char *argv0)
{
	const char *s = strrchr(argv0, '/');
	progname = s ? s + 1 : argv0;
}

const char *util_prog(void) { return progname; }

static void remove_temps(void)
{
	sigset_t saved;
	block(1, &saved);
	for (int i = 0; i < MAX_TEMPS; i++)
		if (temps[i]) {
			char *t = temps[i];
			remove(t);
			temps[i] = NULL;
			free(t);
		}
	/* the deferred commits were of these temporaries: none is left to
	 * commit (a die hook that returns to its caller, as the fuzz
	 * harness does, must not have aout_finish rename freed names) */
	npend = 0;
	deferring = 0;
	block(0, &saved);
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
	if (die_hook)
		die_hook(die_code);
	exit(die_code);
}

void die_status(int status, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vmsg(fmt, ap);
	va_end(ap);
	remove_temps();
	if (die_hook)
		die_hook(status);
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
	char *copy = xstrdup(tmp);
	sigset_t saved;
	block(1, &saved);
	for (int i = 0; i < MAX_TEMPS; i++)
		if (!temps[i]) {
			temps[i] = copy;
			block(0, &saved);
			return i;
		}
	block(0, &saved);
	free(copy);
	die("too many output files open at once");
}

static void drop_temp(const char *tmp)
{
	sigset_t saved;
	block(1, &saved);
	for (int i = 0; i < MAX_TEMPS; i++)
		if (temps[i] && strcmp(temps[i], tmp) == 0) {
			char *t = temps[i], *k = keep_path[i];
			temps[i] = NULL;
			keep_path[i] = NULL;
			keep_units[i] = 0;
			free(t);
			free(k);
			break;
		}
	block(0, &saved);
}

void aout_keep_on_signal(const char *what)
{
	keep_what = what;
}

void aout_mark(struct aout *a, long units)
{
	if (!keep_what || !a->tmp || fflush(a->f) != 0)
		return;     /* a write error is reported at the commit */
	off_t len = ftello(a->f);
	if (len < 0)
		return;
	for (int i = 0; i < MAX_TEMPS; i++)
		if (temps[i] && strcmp(temps[i], a->tmp) == 0) {
			char *k = keep_path[i] ? NULL : xstrdup(a->path);
			sigset_t saved;
			block(1, &saved);
			if (k)
				keep_path[i] = k;
			keep_len[i] = len;
			keep_units[i] = units;
			block(0, &saved);
			return;
		}
}

/* Renames the temporary over the target, with the signals blocked so
 * that a signal cannot remove a file that is already the target. */
static void rename_temp(const char *tmp, const char *path)
{
	sigset_t saved;
	block(1, &saved);
	if (rename(tmp, path) != 0) {
		block(0, &saved);
		die("%s: cannot rename:", path);
	}
	drop_temp(tmp);
	block(0, &saved);
}

/* 1 if path exists and is not a regular file (a device, a FIFO, or a
 * link to one): such a target is written in place, never replaced. */
static int special_target(const char *path)
{
	struct stat st;
	return stat(path, &st) == 0 && !S_ISREG(st.st_mode);
}

struct aout *aout_open(const char *path)
{
	struct aout *a = xcalloc(1, sizeof *a);
	if (!*path)
		die("an output file with an empty name");
	/* a symbolic link to a file: the file is replaced and the link
	 * stays (renaming onto the link would replace the link itself) */
	struct stat ls;
	char *real = NULL;
	if (lstat(path, &ls) == 0 && S_ISLNK(ls.st_mode))
		real = realpath(path, NULL);
	a->path = xstrdup(real ? real : path);
	free(real);
	path = a->path;
	if (strcmp(path, "-") == 0) {
		a->f = stdout;
		return a;
	}
	catch_signals();
	if (special_target(path)) {
		if (!(a->f = fopen(path, "w")))
			die("%s: cannot open:", path);
		a->inplace = 1;
		return a;
	}
	size_t n = strlen(path) + 16;
	a->tmp = xmalloc(n);
	snprintf(a->tmp, n, "%s.tmpXXXXXX", path);
	sigset_t saved;
	block(1, &saved);   /* no signal between creating and listing it */
	int fd = mkstemp(a->tmp);
	if (fd < 0) {
		block(0, &saved);
		die("%s: cannot create:", path);
	}
	add_temp(a->tmp);
	block(0, &saved);
	a->f = fdopen(fd, "w");
	if (!a->f)
		die("%s: cannot open:", path);
	return a;
}

void aout_commit(struct aout *a)
{
	if (a->inplace) {
		fshut(a->f, a->path);
	} else if (!a->tmp) {
		fshut(a->f, "stdout");
	} else {
		fshut(a->f, a->path);
		/* mkstemp made the file 0600; give it the usual mode */
		mode_t m = umask(0);
		umask(m);
		if (chmod(a->tmp, 0666 & ~m) != 0)
			die("%s: cannot set mode:", a->path);
		if (deferring) {
			if (npend >= MAX_TEMPS)
				die("too many output files held at once");
			pend_tmp[npend] = a->tmp;
			pend_path[npend++] = a->path;
			free(a);
			return;
		}
		rename_temp(a->tmp, a->path);
	}
	free(a->tmp);
	free(a->path);
	free(a);
}

void aout_defer(void)
{
	deferring = 1;
}

void aout_finish(void)
{
	for (int i = 0; i < npend; i++) {
		rename_temp(pend_tmp[i], pend_path[i]);
		free(pend_tmp[i]);
		free(pend_path[i]);
	}
	npend = 0;
	deferring = 0;
}

void aout_abort(struct aout *a)
{
	if (a->inplace) {
		fclose(a->f);
	} else if (a->tmp) {
		fclose(a->f);
		remove(a->tmp);
		drop_temp(a->tmp);
	}
	free(a->tmp);
	free(a->path);
	free(a);
}
