/*
 * fuzz_gds.c - the GDSII reader under mutated input.
 *
 * LLVMFuzzerTestOneInput is the libFuzzer entry point for the hardening
 * harness: build with clang -fsanitize=fuzzer,address,undefined
 * -DS3D_LIBFUZZER, the library sources and -lm.  It runs in process: the reader's
 * _try functions report bad input as a message (no exit) and free what
 * they allocated, so the sanitizers' leak check stays on.  It reads the
 * input, then flattens layer 1 of the top cell twice (all of it, and
 * culled to a window), with the flattening limit lowered to 1e6 elements
 * so that no input can take long.
 *
 * Without S3D_LIBFUZZER this is a test of make check (and make asan): a
 * deterministic mini-fuzz of tests/gds/data/refs.gds (references, arrays,
 * paths): every truncation and three byte mutations at every offset,
 * about 3 600 inputs; the unmutated file must read and give shapes.
 */
#include "fmt_gds.h"
#include "util.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* 0: read and flattened, 1: an error reported, with the message in err */
static int run_one(const uint8_t *data, size_t size, char *err, size_t errlen, long *nshapes)
{
	struct gds_lib *g = fmt_gds_read_mem("fuzz.gds", data, size, err, errlen);
	*nshapes = 0;
	if (!g)
		return 1;
	fmt_gds_set_max_visit(g, 1000000);
	struct poly_set s;
	memset(&s, 0, sizeof s);
	double win[4] = {-1, 1, -1, 1};
	long a = fmt_gds_shapes_try(g, NULL, 1, -1, NULL, &s, err, errlen);
	long b = a < 0 ? -1 : fmt_gds_shapes_try(g, NULL, 1, 0, win, &s, err, errlen);
	*nshapes = s.n;
	poly_set_free(&s);
	fmt_gds_free(g);
	return a < 0 || b < 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char err[640];
	long n;
	run_one(data, size, err, sizeof err, &n);
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
	char err[640];
	long shapes;
	int bad = 0, inputs = 0, errors = 0;
	if (run_one(buf, n, err, sizeof err, &shapes) != 0 || shapes == 0) {
		printf("FAIL: the unmutated seed does not read: %s\n", err);
		bad++;
	}
	for (size_t k = 0; k < n; k++) {
		inputs++;
		if (run_one(buf, k, err, sizeof err, &shapes) == 1) {
			errors++;
			if (strchr(err, '\n') || !strstr(err, "fuzz.gds: byte ")) {
				printf("FAIL: truncation at %zu: bad message \"%s\"\n", k, err);
				bad++;
			}
		}
	}
	for (size_t k = 0; k < n; k++)
		for (int v = 0; v < 3; v++) {
			memcpy(m, buf, n);
			m[k] = v == 0 ? 0x00 : v == 1 ? (uint8_t)(buf[k] ^ 0x80) : (uint8_t)(buf[k] + 1);
			inputs++;
			if (run_one(m, n, err, sizeof err, &shapes) == 1) {
				errors++;
				if (strchr(err, '\n') || !strstr(err, "fuzz.gds: byte ")) {
					printf("FAIL: byte %zu set to 0x%02x: bad message \"%s\"\n", k,
					       m[k], err);
					bad++;
				}
			}
		}
	printf("%d mutated inputs: %d one-line errors, %d read\n", inputs, errors, inputs - errors);
	return bad ? 1 : 0;
}
#endif
