/*
 * util.h - error reporting, checked allocation, stream shutdown and
 * atomic output files, shared by every program of the suite.
 *
 * Design: programs are one-shot filters, so a fatal error simply prints
 * one line and exits (netpbm's pm_error, suckless' eprintf).  Output files
 * are written to a temporary beside the target and renamed on success;
 * die() removes every temporary still open, so a failure never leaves a
 * half-written file nor destroys the previous one.
 */
#ifndef S3D_UTIL_H
#define S3D_UTIL_H

#include <stddef.h>
#include <stdio.h>

/* Exit statuses: 1 for a run-time failure, 2 for a usage error. */
enum { EXIT_RUNTIME = 1, EXIT_USAGE = 2 };

/* Sets the name used as the "prog: " prefix of every message. */
void util_setprog(const char *argv0);
const char *util_prog(void);

/* The status die() exits with (default EXIT_RUNTIME); programs whose exit
 * 1 means something else (plotdiff: "files differ") set another. */
void util_set_die_status(int status);

/* For fuzzing harnesses only (tests/fuzz/): called by die() after the
 * message and the removal of temporaries, instead of exit; it must not
 * return (a longjmp back into the harness).  NULL restores exit. */
void util_set_die_hook(void (*hook)(int status));

/* "prog: message\n" on stderr and exit(1).  A format ending in ':'
 * appends strerror(errno). */
_Noreturn void die(const char *fmt, ...)
	__attribute__((format(printf, 1, 2)));
/* The same with an explicit exit status (EXIT_USAGE for usage errors). */
_Noreturn void die_status(int status, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* "prog: message\n" on stderr, no exit. */
void warn(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

void *xmalloc(size_t size);
void *xcalloc(size_t count, size_t size);
/* realloc of count * size bytes, dying on overflow or exhaustion. */
void *xreallocarray(void *p, size_t count, size_t size);
char *xstrdup(const char *s);
/* Grows *p (holding *cap elements of size) to at least need elements,
 * doubling; dies on overflow. */
void xgrow(void *pp, size_t *cap, size_t need, size_t size);

/* Flushes and closes f, dying with "name: write error:" if anything
 * failed on the way (full disk, broken pipe).  stdout is flushed and
 * checked but not closed. */
void fshut(FILE *f, const char *name);

/* Atomic output file: writes go to a temporary beside path; aout_commit
 * checks every write and the close, then renames over path.
 * A target that exists and is not a regular file (a device such as
 * /dev/null, a FIFO, or a symbolic link to one) is written in place: it
 * is never renamed over.
 * The first aout_open installs handlers for SIGINT, SIGTERM, SIGHUP and
 * SIGPIPE (unless ignored) that remove every temporary and then die of
 * the same signal, so the shell sees the usual status 128+n. */
struct aout {
	FILE *f;        /* write here */
	char *path;     /* the target ("-" for stdout) */
	char *tmp;      /* the temporary, NULL for stdout or in place */
	int inplace;    /* 1: the target itself is written (not a regular file) */
};
struct aout *aout_open(const char *path);
void aout_commit(struct aout *a);   /* dies on any error; frees a */
void aout_abort(struct aout *a);    /* removes the temporary; frees a */

/* A program with several outputs commits none until all succeed: after
 * aout_defer, aout_commit checks and closes the temporary but leaves the
 * rename to aout_finish, which renames every output held so far (a die()
 * before it removes them all, and every old target stays as it was). */
void aout_defer(void);
void aout_finish(void);

/* A long run that writes its results as it goes (etch's print times)
 * keeps them when interrupted: after aout_keep_on_signal("print times"),
 * SIGINT, SIGTERM or SIGHUP cut every temporary back to its last
 * aout_mark, rename it over its target and say in one line what was kept
 * ("etch: interrupted: curves.plot keeps the 2 print times finished"),
 * before dying of the signal as usual.  aout_mark(a, n): what a holds so
 * far is n whole units (flushed; a writer calls it between units). */
void aout_keep_on_signal(const char *what);
void aout_mark(struct aout *a, long units);

#endif
