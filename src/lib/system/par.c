/*
 * par.c - see par.h.  The pool: par_threads() - 1 workers started on the
 * first par_for that needs them, parked on a condition variable between
 * jobs (a job is one par_for: its ranges are handed out by a generation
 * number, the calling thread takes range 0 and waits for the rest).
 * Starting threads per call would cost tens of microseconds each, which
 * etch's per-step loops would feel.
 */
#include "par.h"
#include "util.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int nthreads;            /* 0: not chosen yet */

void par_set_threads(int n)
{
	if (n < 0 || n > PAR_MAX_THREADS)
		die("internal error: %d threads", n);
	nthreads = n;
}

int par_threads(void)
{
	if (nthreads > 0)
		return nthreads;
	const char *e = getenv("SAMPLE3D_THREADS");
	if (e && *e) {
		char *end;
		long v = strtol(e, &end, 10);
		if (*end || v < 1 || v > PAR_MAX_THREADS)
			die("SAMPLE3D_THREADS: expected a thread count from 1 to %d, got \"%s\"",
			    PAR_MAX_THREADS, e);
		nthreads = (int)v;
	} else {
		long c = sysconf(_SC_NPROCESSORS_ONLN);
		nthreads = c < 1 ? 1 : c > PAR_MAX_THREADS ? PAR_MAX_THREADS : (int)c;
	}
	return nthreads;
}

static struct {
	pthread_mutex_t mu;
	pthread_cond_t go, done;
	int started;                    /* workers running */
	unsigned long gen;              /* job number */
	int pending;                    /* ranges of the job not finished */
	/* the job */
	void (*fn)(void *, size_t, size_t, int);
	void *ctx;
	size_t n;
	int nranges;
} pool = {PTHREAD_MUTEX_INITIALIZER, PTHREAD_COND_INITIALIZER, PTHREAD_COND_INITIALIZER,
	  0, 0, 0, NULL, NULL, 0, 0};

static _Thread_local int in_par;

/* range r of nr over [0, n) */
static void range(size_t n, int r, int nr, size_t *lo, size_t *hi)
{
	*lo = (size_t)((unsigned long long)n * (unsigned)r / (unsigned)nr);
	*hi = (size_t)((unsigned long long)n * (unsigned)(r + 1) / (unsigned)nr);
}

static void *worker(void *arg)
{
	int id = (int)(size_t)arg;     /* 1 .. nthreads-1 */
	in_par = 1;
	unsigned long seen = 0;
	pthread_mutex_lock(&pool.mu);
	for (;;) {
		while (pool.gen == seen)
			pthread_cond_wait(&pool.go, &pool.mu);
		seen = pool.gen;
		if (id >= pool.nranges)
			continue;
		void (*fn)(void *, size_t, size_t, int) = pool.fn;
		void *ctx = pool.ctx;
		size_t lo, hi;
		range(pool.n, id, pool.nranges, &lo, &hi);
		pthread_mutex_unlock(&pool.mu);
		fn(ctx, lo, hi, id);
		pthread_mutex_lock(&pool.mu);
		if (--pool.pending == 0)
			pthread_cond_signal(&pool.done);
	}
	return NULL;
}

void par_for(size_t n, size_t min_chunk,
	     void (*fn)(void *ctx, size_t lo, size_t hi, int worker), void *ctx)
{
	if (n == 0)
		return;
	if (min_chunk < 1)
		min_chunk = 1;
	int nt = par_threads();
	size_t most = n / min_chunk;
	int nr = most < (size_t)nt ? (int)(most ? most : 1) : nt;
	if (nr == 1 || in_par) {
		int outer = in_par;
		in_par = 1;             /* a par_for inside fn stays in this thread */
		fn(ctx, 0, n, 0);
		in_par = outer;
		return;
	}
	pthread_mutex_lock(&pool.mu);
	while (pool.started < nt - 1) {
		pthread_t th;
		pthread_attr_t at;
		pthread_attr_init(&at);
		pthread_attr_setdetachstate(&at, PTHREAD_CREATE_DETACHED);
		int err = pthread_create(&th, &at, worker, (void *)(size_t)(pool.started + 1));
		pthread_attr_destroy(&at);
		if (err) {
			pthread_mutex_unlock(&pool.mu);
			/* no more threads: what the pool has must do */
			if (pool.started == 0) {
				in_par = 1;
				fn(ctx, 0, n, 0);
				in_par = 0;
				return;
			}
			pthread_mutex_lock(&pool.mu);
			break;
		}
		pool.started++;
	}
	if (nr > pool.started + 1)
		nr = pool.started + 1;
	pool.fn = fn;
	pool.ctx = ctx;
	pool.n = n;
	pool.nranges = nr;
	pool.pending = nr - 1;
	pool.gen++;
	pthread_cond_broadcast(&pool.go);
	pthread_mutex_unlock(&pool.mu);
	in_par = 1;
	size_t lo, hi;
	range(n, 0, nr, &lo, &hi);
	fn(ctx, lo, hi, 0);
	in_par = 0;
	pthread_mutex_lock(&pool.mu);
	while (pool.pending > 0)
		pthread_cond_wait(&pool.done, &pool.mu);
	pthread_mutex_unlock(&pool.mu);
}
