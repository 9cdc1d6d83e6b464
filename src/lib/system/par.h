/*
 * par.h - threads: a parallel-for over index ranges on a small pool of
 * POSIX threads, shared by the programs (one pool, not threads spread
 * through every program).
 *
 * Determinism is the caller's part of the contract: par_for splits [0, n)
 * into contiguous ranges, one per worker, fixed by n and the thread count
 * alone, and fn must give the same result for an index whichever range
 * holds it (no floating-point sums across ranges, no shared output order).
 * Then output is byte-identical for every thread count; the programs'
 * thread tests compare 1, 2 and 3 threads.
 *
 * Thread count: par_set_threads (the programs' -threads N), else the
 * environment variable SAMPLE3D_THREADS, else every online core.
 */
#ifndef S3D_PAR_H
#define S3D_PAR_H

#include <stddef.h>

enum { PAR_MAX_THREADS = 256 };

/* Sets the thread count (1 to PAR_MAX_THREADS; 0 means the default). */
void par_set_threads(int n);
/* The thread count in use (reads SAMPLE3D_THREADS on the first call;
 * dies with a one-line message if it is not an integer in range). */
int par_threads(void);
/* Calls fn(ctx, lo, hi, worker) on contiguous ranges covering [0, n), at
 * most one range per thread, each at least min_chunk long (fewer ranges
 * when n is small).  worker is the number of the range, counted from 0 in
 * order of lo, and below par_threads(): per-worker scratch can be indexed
 * by it, and per-range results combined in order.  Returns when all are
 * done.  Called from inside fn, runs the whole range in the calling
 * thread.  One thread at a time may call it (the programs' main). */
void par_for(size_t n, size_t min_chunk,
	     void (*fn)(void *ctx, size_t lo, size_t hi, int worker), void *ctx);

#endif
