/*
 * splattest.h - what splat's C tests share: a failure count with CHECK,
 * which prints a failed condition's message and counts it, and input(),
 * a splat(5) text written to t.in and read back.
 */
#ifndef SPLATTEST_H
#define SPLATTEST_H

#include "fmt_splat.h"
#include "util.h"

#include <stdio.h>

static int failures;

#define CHECK(cond, ...) do { if (!(cond)) { printf("FAIL: " __VA_ARGS__); \
	printf("\n"); failures++; } } while (0)

/* Writes text to t.in and reads it as a splat input. */
static inline struct splat_input *input(const char *text)
{
	FILE *f = fopen("t.in", "w");
	if (!f)
		die("t.in:");
	fputs(text, f);
	fshut(f, "t.in");
	return fmt_splat_read("t.in");
}

#endif
