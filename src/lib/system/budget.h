/*
 * budget.h - the estimate of work and memory made before any heavy work,
 * and the refusal of work beyond the documented limits.
 *
 * A small input can ask for an enormous run (a 2000 um window at NA 0.99
 * is 10^8 diffraction orders; a rate of 10^6 um/s is 10^9 time steps).
 * Each program estimates, from its input alone, the memory and the
 * seconds of work it is about to spend and calls budget_check.  Beyond
 * the limits - more memory than the machine has, or more than about an
 * hour of work (BUDGET_SECONDS) - it refuses with one line giving the
 * estimate and the way to run it anyway: the program's -big option or
 * the environment variable SAMPLE3D_BIG=1.
 */
#ifndef S3D_BUDGET_H
#define S3D_BUDGET_H

/* The work limit, seconds of one core of this machine: the programs'
 * estimates count the seconds of one core (their constants are measured
 * that way; make bench prints each beside a run, tests/bench/estimate.sh),
 * so that with several threads a run ends sooner than its estimate. */
#define BUDGET_SECONDS 3600.0

/* -big given: budget_check only reports. */
void budget_allow_big(void);
/* 1 if -big was given or SAMPLE3D_BIG is set: for a reader that refuses
 * by itself, in its own words, what budget_check would. */
int budget_big(void);
/* The memory limit: the machine's physical memory, bytes, or less if the
 * process's address space is limited (ulimit -v) or the environment
 * variable SAMPLE3D_MEMORY gives a smaller byte count (a shared machine;
 * tests of a refusal with small inputs). */
double budget_memory(void);
/* Dies "where: what needs about S s and B of memory (...): use -big ..."
 * if seconds or bytes are beyond the limits and neither -big nor
 * SAMPLE3D_BIG is set.  what says what the estimate counts, e.g.
 * "1.2e+09 TCC pairs". */
void budget_check(const char *where, const char *what, double seconds, double bytes);

/* "3.9 GB", "12 MB": a byte count for messages (buf of 16 bytes). */
const char *budget_bytes(char *buf, double bytes);

#endif
