/*
 * fuzz_reader.c - the libFuzzer target of one file reader, chosen at
 * build time with -DREADER=NAME (make fuzz builds one binary per reader:
 * splat, bleach, contour, stack, plot2d, plot3d, options, template,
 * rate_ascii, rate_binary).  The input goes to a private temporary file and through
 * the library's reader exactly as a program reads it; die() is turned
 * into a longjmp (util_set_die_hook), so an input the reader rejects is
 * an ordinary return, and only a crash, a sanitizer report, a hang or
 * too much memory is a finding.  A rejected input would leak what the
 * reader had allocated (the programs exit there, so the readers need not
 * free): the library is linked with -Wl,--wrap for malloc, calloc,
 * realloc and free, every live block is tracked here, and whatever is
 * left after a reader returns or dies is freed, so a long campaign does
 * not grow.
 *
 * Build by hand:
 *   clang -g -O1 -fsanitize=fuzzer,address,undefined -DREADER_NAME='"splat"' \
 *     -Isrc/lib/* (each layer) tests/fuzz/targets/fuzz_reader.c (the library sources) -lm
 *
 * Not a test of its own: tests/fuzz/002-targets.sh builds every target
 * and runs it over its corpus once.
 */
#include "fmt_bleach.h"
#include "fmt_contour.h"
#include "fmt_options.h"
#include "fmt_plot.h"
#include "fmt_rate.h"
#include "fmt_splat.h"
#include "fmt_stack.h"
#include "fmt_template.h"
#include "util.h"

#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The library's allocations (linked with -Wl,--wrap=malloc,...): an
 * open-addressing set of the live blocks. */
void *__real_malloc(size_t n);
void *__real_calloc(size_t n, size_t m);
void *__real_realloc(void *p, size_t n);
void __real_free(void *p);
void *__wrap_malloc(size_t n);
void *__wrap_calloc(size_t n, size_t m);
void *__wrap_realloc(void *p, size_t n);
void __wrap_free(void *p);

static void **live;
static size_t live_cap, live_n;
#define TOMB ((void *)1)

static size_t slot(void *p)
{
	return ((uintptr_t)p >> 4) * 0x9E3779B97F4A7C15ull & (live_cap - 1);
}

static void track(void *p);

static void grow(void)
{
	void **old = live;
	size_t oc = live_cap;
	live_cap = oc ? 2 * oc : 1024;
	live = __real_calloc(live_cap, sizeof *live);
	if (!live)
		abort();
	live_n = 0;
	for (size_t i = 0; i < oc; i++)
		if (old[i] && old[i] != TOMB)
			track(old[i]);
	__real_free(old);
}

static void track(void *p)
{
	if (!p)
		return;
	if (2 * (live_n + 1) > live_cap)
		grow();
	size_t i = slot(p);
	while (live[i] && live[i] != TOMB)
		i = (i + 1) & (live_cap - 1);
	live[i] = p;
	live_n++;
}

static void untrack(void *p)
{
	if (!p || !live_cap)
		return;
	for (size_t i = slot(p), k = 0; live[i] && k < live_cap; i = (i + 1) & (live_cap - 1), k++)
		if (live[i] == p) {
			live[i] = TOMB;
			return;
		}
}

void *__wrap_malloc(size_t n) { void *p = __real_malloc(n); track(p); return p; }
void *__wrap_calloc(size_t n, size_t m) { void *p = __real_calloc(n, m); track(p); return p; }
void __wrap_free(void *p) { untrack(p); __real_free(p); }
void *__wrap_realloc(void *p, size_t n)
{
	void *q = __real_realloc(p, n);
	if (q) {
		untrack(p);
		track(q);
	}
	return q;
}

/* Frees every block the reader left. */
static void free_all(void)
{
	for (size_t i = 0; i < live_cap; i++) {
		if (live[i] && live[i] != TOMB)
			__real_free(live[i]);
		live[i] = NULL;
	}
	live_n = 0;
}

static jmp_buf back;
static char path[64];

static void on_die(int status)
{
	longjmp(back, status ? status : 1);
}

#ifndef FUZZ_NO_ENTRY  /* fuzz_args.c reuses the tracking and the jump above */
/* every kind of option, with ranges like the plot programs' */
static const struct opt_spec spec[] = {
	{"flag", OPT_ONOFF, 0, 0, NULL},
	{"num", OPT_NUM, -1e6, 1e6, NULL},
	{"xticks", OPT_INT, 1, 20, NULL},
	{"label", OPT_STRING, 0, 0, NULL},
	{"font", OPT_WORD, 0, 0, "times|helvetica|courier"},
	{NULL, 0, 0, 0, NULL},
};

static void read_it(void)
{
#define R(name) (strcmp(#name, READER_NAME) == 0)
	if (R(splat)) {
		fmt_splat_free(fmt_splat_read(path));
	} else if (R(bleach)) {
		struct bleach_input in;
		fmt_bleach_read(path, &in);
	} else if (R(contour)) {
		fmt_contour_free(fmt_contour_read(path, 0));
	} else if (R(stack)) {
		fmt_stack_free(fmt_stack_read(path));
	} else if (R(plot2d)) {
		fmt_plot_free(fmt_plot_read(path, 2));
	} else if (R(plot3d)) {
		fmt_plot_free(fmt_plot_read(path, 3));
	} else if (R(options)) {
		struct opt_value val[sizeof spec / sizeof spec[0]];
		memset(val, 0, sizeof val);
		fmt_options_read(path, spec, val);
		fmt_options_free(spec, val);
	} else if (R(template)) {
		fmt_template_free(fmt_template_read(path));
	} else if (R(rate_ascii) || R(rate_binary)) {
		fmt_rate_free(fmt_rate_read(path));
	} else {
		fprintf(stderr, "fuzz_reader: unknown reader %s\n", READER_NAME);
		abort();
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (!path[0]) {
		util_setprog("fuzz");
		snprintf(path, sizeof path, "/tmp/s3dfuzz-%s-%ld", READER_NAME, (long)getpid());
		util_set_die_hook(on_die);
		/* the readers' messages are silenced by make fuzz with
		 * -close_fd_mask=2 (crash reports still reach the log) */
	}
	FILE *f = fopen(path, "wb");
	if (!f)
		abort();
	if (size && fwrite(data, 1, size, f) != size)
		abort();
	fclose(f);
	if (setjmp(back) == 0)
		read_it();
	free_all();
	unlink(path);
	return 0;
}
#endif
