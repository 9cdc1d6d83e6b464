/*
 * progress.h - the progress line of long work: percent done and time
 * left, on stderr, at most every PROGRESS_SECONDS (5 s; the environment
 * variable SAMPLE3D_PROGRESS sets another interval in seconds, 0 for
 * every call, which the tests use).  Nothing is printed for work that
 * ends before the first interval, nor with -q (quiet).
 *
 *   struct progress p;
 *   progress_begin(&p, "TCC pairs", quiet);
 *   for (...) { ...; progress_step(&p, done, total); }
 * prints "splat: TCC pairs: 42% done, about 1.3 min left".
 */
#ifndef S3D_PROGRESS_H
#define S3D_PROGRESS_H

#define PROGRESS_SECONDS 5.0

struct progress {
	const char *what;
	double t0, last, every;
	int on;
};

void progress_begin(struct progress *p, const char *what, int quiet);
/* done of total units (any unit proportional to the work). */
void progress_step(struct progress *p, double done, double total);

#endif
