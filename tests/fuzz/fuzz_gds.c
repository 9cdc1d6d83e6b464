/*
 * fuzz_gds.c - the GDSII reader under mutated input.
 *
 * LLVMFuzzerTestOneInput is the libFuzzer entry point for the hardening
 * harness: build with clang -fsanitize=fuzzer,address,undefined
 * -DS3D_LIBFUZZER and the library.  The reader reports bad input by
 * die(), which exits, so each input runs in a forked child; a child
 * killed by a signal or stopped by a sanitizer (exit status 90 and up, as
 * tests/run.sh sets ASAN_OPTIONS and UBSAN_OPTIONS) aborts the parent,
 * which libFuzzer records as a crash.  A one-line error (exit 1) or a
 * clean read (exit 0) is a pass.
 *
 * Without S3D_LIBFUZZER this is a test of make check (and make asan): a
 * deterministic mini-fuzz of tests/gds/data/refs.gds (references, arrays,
 * paths): every 3rd truncation and three byte mutations at every 5th
 * offset, about a thousand inputs; the unmutated file must read.
 */
#include "fmt_gds.h"
#include "util.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static char path[64] = "";

/* 0: read, 1: one-line error, 2: crash or sanitizer report */
static int run_one(const uint8_t *data, size_t size)
{
	if (!path[0]) {
		snprintf(path, sizeof path, "/tmp/fuzz_gds.%ld.gds", (long)getpid());
	}
	FILE *f = fopen(path, "wb");
	if (!f)
		die("%s:", path);
	if (size)
		fwrite(data, 1, size, f);
	fshut(f, path);
	fflush(NULL);
	pid_t pid = fork();
	if (pid < 0)
		die("fork:");
	if (pid == 0) {
		/* the child: quiet, read, flatten two ways, free */
		if (!freopen("/dev/null", "w", stderr))
			_exit(3);
		struct gds_lib *g = fmt_gds_read(path, "fuzz");
		struct poly_set s;
		memset(&s, 0, sizeof s);
		double win[4] = {-1, 1, -1, 1};
		fmt_gds_shapes(g, NULL, 1, -1, NULL, &s);
		fmt_gds_shapes(g, NULL, 1, 0, win, &s);
		poly_set_free(&s);
		fmt_gds_free(g);
		exit(0);
	}
	int st;
	while (waitpid(pid, &st, 0) < 0)
		;
	if (WIFSIGNALED(st) || (WIFEXITED(st) && WEXITSTATUS(st) >= 90))
		return 2;
	return WIFEXITED(st) && WEXITSTATUS(st) == 0 ? 0 : 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (run_one(data, size) == 2)
		abort();
	return 0;
}

#ifndef S3D_LIBFUZZER
int main(void)
{
	util_setprog("fuzz_gds");
	const char *top = getenv("TOP");
	char seed[4096];
	snprintf(seed, sizeof seed, "%s/tests/gds/data/refs.gds", top ? top : ".");
	FILE *f = fopen(seed, "rb");
	if (!f)
		die("%s:", seed);
	static uint8_t buf[65536], m[65536];
	size_t n = fread(buf, 1, sizeof buf, f);
	fclose(f);
	int bad = 0, inputs = 0, errors = 0;
	int r = run_one(buf, n);
	if (r != 0) {
		printf("FAIL: the unmutated seed does not read (%d)\n", r);
		bad++;
	}
	for (size_t k = 0; k < n; k += 3) {
		r = run_one(buf, k);
		inputs++;
		errors += r == 1;
		if (r == 2) {
			printf("FAIL: crash on the first %zu bytes\n", k);
			bad++;
		}
	}
	static const uint8_t val[3] = {0x00, 0xff, 0x7f};
	for (size_t k = 0; k < n; k += 5)
		for (int v = 0; v < 3; v++) {
			memcpy(m, buf, n);
			m[k] = k % 2 ? (uint8_t)(m[k] ^ 0x80) : val[v];
			if (v == 2)
				m[k] = (uint8_t)(buf[k] + 1);
			r = run_one(m, n);
			inputs++;
			errors += r == 1;
			if (r == 2) {
				printf("FAIL: crash with byte %zu set to 0x%02x\n", k, m[k]);
				bad++;
			}
		}
	unlink(path);
	printf("%d mutated inputs: %d one-line errors, %d read, %d crashes\n", inputs, errors,
	       inputs - errors - bad, bad);
	return bad ? 1 : 0;
}
#endif
