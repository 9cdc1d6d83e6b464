/*
 * crc32.c - fmt_crc32 (src/lib/fmt_rate.c, slicing by 8) against
 *  1. the published check values of CRC-32/ISO-HDLC (zlib's crc32):
 *     "123456789" -> 0xCBF43926, "" -> 0, "a" -> 0xE8B7BE43,
 *     "The quick brown fox jumps over the lazy dog" -> 0x414FA339;
 *  2. an independent bit-at-a-time CRC (no table) over random buffers of
 *     every length 0..300 at every start alignment 0..7, and a 1 MB buffer
 *     fed in random pieces (the running CRC continues across calls, as
 *     the binary rate writer uses it).
 * Exact equality.
 */
#include "fmt_rate.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint32_t crc_bitwise(uint32_t crc, const unsigned char *p, size_t n)
{
	crc = ~crc;
	for (size_t i = 0; i < n; i++) {
		crc ^= p[i];
		for (int k = 0; k < 8; k++)
			crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1)));
	}
	return ~crc;
}

static int nfail;

static void expect(const char *what, unsigned long got, unsigned long want)
{
	if (got != want && nfail++ < 20)
		fprintf(stderr, "crc32: %s: got %08lx, want %08lx\n", what, got, want);
}

int main(void)
{
	const struct { const char *s; unsigned long crc; } known[] = {
		{"123456789", 0xCBF43926u},
		{"", 0},
		{"a", 0xE8B7BE43u},
		{"The quick brown fox jumps over the lazy dog", 0x414FA339u},
	};
	for (size_t i = 0; i < sizeof known / sizeof known[0]; i++)
		expect(known[i].s, fmt_crc32(0, known[i].s, strlen(known[i].s)), known[i].crc);

	enum { BIG = 1 << 20 };
	unsigned char *buf = malloc(BIG);
	if (!buf)
		return 1;
	uint32_t x = 2463534242u;
	for (size_t i = 0; i < BIG; i++) {
		x ^= x << 13, x ^= x >> 17, x ^= x << 5;
		buf[i] = (unsigned char)x;
	}
	for (size_t off = 0; off < 8; off++)
		for (size_t n = 0; n <= 300; n++) {
			char what[64];
			snprintf(what, sizeof what, "offset %zu length %zu", off, n);
			expect(what, fmt_crc32(0, buf + off, n), crc_bitwise(0, buf + off, n));
		}
	unsigned long c = 0;
	for (size_t at = 0; at < BIG;) {
		x ^= x << 13, x ^= x >> 17, x ^= x << 5;
		size_t n = x % 5000;
		if (n > BIG - at)
			n = BIG - at;
		c = fmt_crc32(c, buf + at, n);
		at += n;
	}
	expect("1 MB in pieces", c, crc_bitwise(0, buf, BIG));
	free(buf);
	return nfail != 0;
}
