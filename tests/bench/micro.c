/*
 * micro.c - make bench's micro-benchmarks of library kernels, each against
 * the code it replaced, measured in the same run (CPU time, best of 3):
 *   num_fmt vs num_fmt_ref (printf %.15g / strtod / %.17g), ns per number,
 *     on three mixes: random coordinates in [-1000, 1000] (17 digits),
 *     grid values k * 0.05 (short), and random bit patterns;
 *   fmt_crc32 (slicing by 8) vs the bytewise loop it replaced (a copy of
 *     which is below), GB/s over 64 MB;
 * Built by make as BUILD/tests/bench/micro; tests/bench/micro.sh runs it.
 * Asserts nothing (tests/formats/ checks that the outputs agree).
 */
#include "fmt_rate.h"
#include "num.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double cpu_now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static uint64_t state = 12345;
static uint64_t next(void)
{
	uint64_t z = (state += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

static volatile size_t sink;

/* best-of-3 seconds per call of fmt over v[0..n) */
static double time_fmt(char *(*fmt)(char *, double), const double *v, size_t n)
{
	double best = 1e30;
	for (int rep = 0; rep < 3; rep++) {
		char buf[NUM_BUFSZ];
		size_t s = 0;
		double t0 = cpu_now();
		for (size_t i = 0; i < n; i++)
			s += strlen(fmt(buf, v[i]));
		double t = cpu_now() - t0;
		sink += s;
		if (t < best)
			best = t;
	}
	return best / (double)n;
}

static void bench_num(const char *label, const double *v, size_t n)
{
	double tn = time_fmt(num_fmt, v, n), tr = time_fmt(num_fmt_ref, v, n);
	printf("num_fmt %-28s %7.1f ns  (printf/strtod %7.1f ns, %5.1fx faster)\n",
	       label, tn * 1e9, tr * 1e9, tr / tn);
}

/* the bytewise CRC-32 that fmt_crc32 was before slicing */
static unsigned long crc32_bytewise(unsigned long crc, const void *data, size_t len)
{
	static uint32_t table[256];
	static int ready;
	if (!ready) {
		for (uint32_t n = 0; n < 256; n++) {
			uint32_t c = n;
			for (int k = 0; k < 8; k++)
				c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
			table[n] = c;
		}
		ready = 1;
	}
	const unsigned char *p = data;
	uint32_t c = (uint32_t)crc ^ 0xFFFFFFFFu;
	for (size_t i = 0; i < len; i++)
		c = table[(c ^ p[i]) & 0xFF] ^ (c >> 8);
	return c ^ 0xFFFFFFFFu;
}

static double time_crc(unsigned long (*crc)(unsigned long, const void *, size_t),
		       const unsigned char *p, size_t n)
{
	double best = 1e30;
	for (int rep = 0; rep < 3; rep++) {
		double t0 = cpu_now();
		sink += crc(0, p, n);
		double t = cpu_now() - t0;
		if (t < best)
			best = t;
	}
	return best;
}

static void bench_crc(void)
{
	size_t n = (size_t)64 << 20;
	unsigned char *p = malloc(n);
	if (!p)
		return;
	for (size_t i = 0; i < n; i++)
		p[i] = (unsigned char)next();
	double ts = time_crc(fmt_crc32, p, n), tb = time_crc(crc32_bytewise, p, n);
	printf("fmt_crc32 64 MB                     %7.2f GB/s (bytewise %5.2f GB/s, %5.1fx faster)\n",
	       n / ts * 1e-9, n / tb * 1e-9, tb / ts);
	free(p);
}

int main(void)
{
	enum { N = 400000 };
	double *v = malloc(N * sizeof *v);
	if (!v)
		return 1;
	for (size_t i = 0; i < N; i++)
		v[i] = ((double)(next() >> 11) / 9007199254740992.0 - 0.5) * 2000;
	bench_num("random coordinates", v, N);
	for (size_t i = 0; i < N; i++)
		v[i] = -2.5 + (double)(i % 2000) * 0.05;
	bench_num("grid values k*0.05", v, N);
	for (size_t i = 0; i < N; i++) {
		uint64_t u = next();
		memcpy(&v[i], &u, 8);
		if (v[i] != v[i] || v[i] - v[i] != 0)
			v[i] = 1;
	}
	bench_num("random bit patterns", v, N);
	free(v);
	bench_crc();
	return 0;
}
