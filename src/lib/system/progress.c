/* progress.c - see progress.h.  The monotonic clock, so that a change of
 * the wall clock does not stall or flood the lines. */
#include "progress.h"
#include "util.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void progress_begin(struct progress *p, const char *what, int quiet)
{
	p->what = what;
	p->on = !quiet;
	p->every = PROGRESS_SECONDS;
	const char *e = getenv("SAMPLE3D_PROGRESS");
	if (e && *e) {
		char *end;
		double v = strtod(e, &end);
		if (*end == '\0' && v >= 0 && v <= 3600)
			p->every = v;
	}
	p->t0 = p->last = now();
}

void progress_step(struct progress *p, double done, double total)
{
	if (!p->on || !(total > 0))
		return;
	double t = now();
	if (t - p->last < p->every)
		return;
	p->last = t;
	double f = done / total;
	if (f < 0) f = 0;
	if (f > 1) f = 1;
	double left = f > 0 ? (t - p->t0) * (1 - f) / f : 0;
	char buf[32];
	if (left < 120)
		snprintf(buf, sizeof buf, "%.0f s", left);
	else if (left < 7200)
		snprintf(buf, sizeof buf, "%.1f min", left / 60);
	else
		snprintf(buf, sizeof buf, "%.1f h", left / 3600);
	fprintf(stderr, "%s: %s: %.0f%% done, about %s left\n", util_prog(), p->what,
		100 * f, f > 0 ? buf : "? s");
}
