/*
 * mkgds - test tool: writes a large GDSII file for make bench and the
 * reader's tests, without Python: a cell TOP holding an n x n grid of
 * square BOUNDARY elements on layer 1 (side `size`, pitch `pitch`,
 * micrometres, nanometre database unit) and, with decoys, as many again
 * on layer 2.
 *
 *   mkgds n pitch size [decoys] OUT.gds
 */
#include "util.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static FILE *out;

static void rec(int type, int dtype, const void *data, size_t len)
{
	unsigned char h[4] = {(unsigned char)((len + 4) >> 8), (unsigned char)(len + 4),
			      (unsigned char)type, (unsigned char)dtype};
	fwrite(h, 1, 4, out);
	if (len)
		fwrite(data, 1, len, out);
}

static void i16(int type, int v)
{
	unsigned char d[2] = {(unsigned char)(v >> 8), (unsigned char)v};
	rec(type, 2, d, 2);
}

static void put32(unsigned char *p, int32_t v)
{
	uint32_t u = (uint32_t)v;
	p[0] = (unsigned char)(u >> 24); p[1] = (unsigned char)(u >> 16);
	p[2] = (unsigned char)(u >> 8); p[3] = (unsigned char)u;
}

static void box(int layer, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
	rec(0x08, 0, NULL, 0);
	i16(0x0D, layer);
	i16(0x0E, 0);
	int32_t v[10] = {x0, y0, x1, y0, x1, y1, x0, y1, x0, y0};
	unsigned char d[40];
	for (int i = 0; i < 10; i++)
		put32(d + 4 * i, v[i]);
	rec(0x10, 3, d, 40);
	rec(0x11, 0, NULL, 0);
}

int main(int argc, char **argv)
{
	util_setprog(argv[0]);
	if (argc != 5 && argc != 6) {
		fputs("usage: mkgds n pitch size [decoys] OUT.gds\n", stderr);
		return EXIT_USAGE;
	}
	long n = atol(argv[1]);
	double pitch = atof(argv[2]), size = atof(argv[3]);
	int decoys = argc == 6 && strcmp(argv[4], "decoys") == 0;
	const char *path = argv[argc - 1];
	struct aout *a = aout_open(path);
	out = a->f;
	i16(0x00, 600);
	unsigned char z[24] = {0};
	rec(0x01, 2, z, 24);
	rec(0x02, 6, "BENCH", 6);
	/* 1e-3 user units per dbu, 1e-9 metres per dbu, excess-64 reals */
	static const unsigned char units[16] = {0x3e, 0x41, 0x89, 0x37, 0x4b, 0xc6, 0xa7, 0xf0,
						0x39, 0x44, 0xb8, 0x2f, 0xa0, 0x9b, 0x5a, 0x54};
	rec(0x03, 5, units, 16);
	rec(0x05, 2, z, 24);
	rec(0x06, 6, "TOP", 4);
	int32_t p = (int32_t)(pitch * 1000 + 0.5), s = (int32_t)(size * 1000 + 0.5);
	for (long j = 0; j < n; j++)
		for (long i = 0; i < n; i++) {
			box(1, (int32_t)i * p, (int32_t)j * p, (int32_t)i * p + s, (int32_t)j * p + s);
			if (decoys)
				box(2, (int32_t)i * p, (int32_t)j * p, (int32_t)i * p + s, (int32_t)j * p + s);
		}
	rec(0x07, 0, NULL, 0);
	rec(0x04, 0, NULL, 0);
	aout_commit(a);
	return 0;
}
