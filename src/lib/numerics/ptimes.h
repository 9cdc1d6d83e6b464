/*
 * ptimes.h - the print times of a development: every pt seconds and the
 * end, et.  etch and etch2d write one set per print time, and sample3D
 * asks etch (-print-times) for the same list to label its pictures, so
 * the rule is written once, here.
 */
#ifndef S3D_PTIMES_H
#define S3D_PTIMES_H

/* A multiple of pt within this fraction of et below it is the end itself:
 * a -pt that divides -et must not add a set a rounding error before the
 * last (0.1 * 3 is 0.30000000000000004).  Relative, so that it holds at
 * any time scale; etch's rule (etch2d had an absolute 1e-9 s, which gives
 * the same times on every test and example). */
#define PTIMES_TOL 1e-12

/* The print times k pt (k = 1, 2, ...) up to et, the last replaced by et
 * when it comes within PTIMES_TOL of it or passes it, and et itself; only
 * et when pt <= 0.  et > 0.  Returns an allocated array of *n times,
 * increasing. */
double *ptimes_make(double et, double pt, int *n);

/* The number of whole intervals pt in et (1 if pt <= 0): ptimes_make
 * gives this many times or one more, so a caller can refuse a run of too
 * many sets before making the list. */
double ptimes_count(double et, double pt);

#endif
