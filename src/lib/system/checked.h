/*
 * checked.h - checked arithmetic for every size and count derived from
 * input values (grid sides, order counts, step counts, byte counts).
 *
 * A size computed from numbers in a file must never wrap or be cast from
 * a double that does not fit: the result would be a small buffer written
 * far out of bounds, or a loop that never ends.  These helpers either
 * return the exact result or die with one line naming what was being
 * counted ("prog: mask orders: 1e+30 is too large").
 */
#ifndef S3D_CHECKED_H
#define S3D_CHECKED_H

#include <stddef.h>

/* a * b and a + b, dying if the result does not fit in a size_t. */
size_t ck_mul(size_t a, size_t b, const char *what);
size_t ck_add(size_t a, size_t b, const char *what);
/* a * b * c, the same. */
size_t ck_mul3(size_t a, size_t b, size_t c, const char *what);
/* The same without dying: 1 and *out set if it fits, else 0. */
int ck_mul_ok(size_t a, size_t b, size_t *out);

/* A double (already rounded as the caller wants: floor, ceil) as an int
 * or a long in [lo, hi]; dies if it is NaN, infinite or out of range,
 * instead of the undefined behaviour of a plain cast. */
int ck_int(double v, int lo, int hi, const char *what);
long ck_long(double v, long lo, long hi, const char *what);
/* 1 if v (not NaN) lies in [lo, hi], so that (long)v is defined. */
int ck_fits(double v, double lo, double hi);

#endif
