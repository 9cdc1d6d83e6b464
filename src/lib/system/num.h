/*
 * num.h - reading and printing numbers reproducibly.
 *
 * Every number a program writes goes through num_fmt, so output is the
 * same byte for byte on every machine: the shortest of %.15g and %.17g
 * that reads back to the same double (Lua's approach), "-0" printed as
 * "0".  The programs never call setlocale, so the C locale holds.
 * num_fmt computes that form without printf or strtod (see num.c);
 * num_fmt_ref is the printf/strtod definition it must match, kept for the
 * cases num_fmt hands back to it and for the tests and benchmarks.
 */
#ifndef S3D_NUM_H
#define S3D_NUM_H

#include <stdio.h>

enum { NUM_BUFSZ = 32 };

/* Parses the whole of s as a finite double.  Returns 1 on success. */
int num_parse(const char *s, double *out);
/* Parses the whole of s as a decimal integer in [min, max]; counts may be
 * written as "4.0" (contour(L) writes them so).  Returns 1 on success. */
int num_parse_count(const char *s, long min, long max, long *out);
/* Formats v into buf (NUM_BUFSZ bytes); returns buf. */
char *num_fmt(char *buf, double v);
/* The same, returning the end of the text (its NUL). */
char *num_put(char *buf, double v);
/* The same by printf("%.15g"), strtod and printf("%.17g"): the definition
 * of the output, about ten times slower. */
char *num_fmt_ref(char *buf, double v);
/* Prints v to f in the same form. */
void num_print(FILE *f, double v);
/* Prints n values separated by single spaces and ends the line. */
void num_print_row(FILE *f, const double *v, int n);

#endif
