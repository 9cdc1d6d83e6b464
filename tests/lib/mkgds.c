/*
 * mkgds - test tool: writes GDSII files for make bench and the reader's
 * malformed-input tests, without Python (nanometre database unit):
 *
 *   mkgds grid n pitch size [decoys] OUT.gds
 *       a cell TOP holding an n x n grid of square BOUNDARY elements on
 *       layer 1 (side and pitch in micrometres) and, with decoys, as many
 *       again on layer 2;
 *   mkgds chain n OUT.gds
 *       cells C0 .. C(n-1), each referencing the next, the last holding a
 *       box: references nested n deep;
 *   mkgds array cols rows OUT.gds
 *       TOP holding an AREF of cols x rows copies of LEAF (one box).
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

static void str(int type, const char *s)
{
	size_t n = strlen(s);
	char b[64] = {0};
	memcpy(b, s, n < 62 ? n : 62);
	rec(type, 6, b, (n + 1) & ~(size_t)1);
}

static void xy(const int32_t *v, int n)
{
	unsigned char d[80];
	for (int i = 0; i < 2 * n; i++)
		put32(d + 4 * i, v[i]);
	rec(0x10, 3, d, 8 * (size_t)n);
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

static const char usage[] = "usage: mkgds grid n pitch size [decoys] OUT.gds\n"
	"       mkgds chain n OUT.gds\n       mkgds array cols rows OUT.gds\n";

int main(int argc, char **argv)
{
	util_setprog(argv[0]);
	if (argc < 4) {
		fputs(usage, stderr);
		return EXIT_USAGE;
	}
	const char *mode = argv[1];
	const char *path = argv[argc - 1];
	struct aout *a = aout_open(path);
	out = a->f;
	unsigned char z[24] = {0};
	if (strcmp(mode, "grid") != 0) {
		i16(0x00, 600);
		rec(0x01, 2, z, 24);
		str(0x02, "TEST");
		static const unsigned char u[16] = {0x3e, 0x41, 0x89, 0x37, 0x4b, 0xc6, 0xa7, 0xf0,
						    0x39, 0x44, 0xb8, 0x2f, 0xa0, 0x9b, 0x5a, 0x54};
		rec(0x03, 5, u, 16);
		char name[32], next[32];
		if (strcmp(mode, "chain") == 0 && argc == 4) {
			long n = atol(argv[2]);
			for (long i = 0; i < n; i++) {
				rec(0x05, 2, z, 24);
				snprintf(name, sizeof name, "C%ld", i);
				snprintf(next, sizeof next, "C%ld", i + 1);
				str(0x06, name);
				if (i + 1 < n) {
					rec(0x0A, 0, NULL, 0);
					str(0x12, next);
					xy((int32_t[]){10, 0}, 1);
					rec(0x11, 0, NULL, 0);
				} else {
					box(1, 0, 0, 100, 100);
				}
				rec(0x07, 0, NULL, 0);
			}
		} else if (strcmp(mode, "array") == 0 && argc == 5) {
			int c = atoi(argv[2]), r = atoi(argv[3]);
			rec(0x05, 2, z, 24);
			str(0x06, "LEAF");
			box(1, 0, 0, 100, 100);
			rec(0x07, 0, NULL, 0);
			rec(0x05, 2, z, 24);
			str(0x06, "TOP");
			rec(0x0B, 0, NULL, 0);
			str(0x12, "LEAF");
			unsigned char cr[4] = {(unsigned char)(c >> 8), (unsigned char)c,
					       (unsigned char)(r >> 8), (unsigned char)r};
			rec(0x13, 2, cr, 4);
			xy((int32_t[]){0, 0, 200 * c, 0, 0, 200 * r}, 3);
			rec(0x11, 0, NULL, 0);
			rec(0x07, 0, NULL, 0);
		} else {
			aout_abort(a);
			fputs(usage, stderr);
			return EXIT_USAGE;
		}
		rec(0x04, 0, NULL, 0);
		aout_commit(a);
		return 0;
	}
	if (argc != 6 && argc != 7) {
		aout_abort(a);
		fputs(usage, stderr);
		return EXIT_USAGE;
	}
	long n = atol(argv[2]);
	double pitch = atof(argv[3]), size = atof(argv[4]);
	int decoys = argc == 7 && strcmp(argv[5], "decoys") == 0;
	i16(0x00, 600);
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
