/*
 * fmmcheck.h - the failure count of the fast-marching tests
 * (tests/etch/fmm_exact.c, fmm_smooth.c): CHECK prints a failed
 * condition's file, line and message and counts it; main returns
 * check_status(), which prints the count if any failed.
 */
#ifndef FMMCHECK_H
#define FMMCHECK_H

#include <stdio.h>

static int failures;

#define CHECK(cond, ...) do { \
	if (!(cond)) { \
		failures++; \
		printf("FAIL %s:%d: ", __FILE__, __LINE__); \
		printf(__VA_ARGS__); \
		printf("\n"); \
	} \
} while (0)

/* The test's exit status: 1 (after a line with the count) if a CHECK
 * failed, else 0. */
static inline int check_status(void)
{
	if (failures)
		printf("%d failures\n", failures);
	return failures != 0;
}

#endif
