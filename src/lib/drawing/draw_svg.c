/*
 * draw_svg.c - SVG back end: the same display list as PostScript, pages
 * stacked vertically in one picture, y flipped (SVG's origin is at the
 * top).  Text uses Helvetica/Arial; alignment through text-anchor and a
 * baseline shift, so it matches the PostScript placement closely.
 */
#include "draw.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


static void gray_color(FILE *f, double g)
{
	int v = (int)lround(g * 255);
	fprintf(f, "#%02x%02x%02x", v, v, v);
}

static void stroke_attrs(FILE *f, const struct draw_item *e)
{
	if (!e->linetype) {
		fputs(" stroke=\"none\"", f);
		return;
	}
	fputs(" stroke=\"", f);
	gray_color(f, e->gray);
	fputs("\" stroke-width=\"", f);
	draw_print_coord(f, e->width);
	fputc('"', f);
	double dash[6];
	int n = draw_dash(e->linetype, dash);
	if (n) {
		fputs(" stroke-dasharray=\"", f);
		for (int i = 0; i < n; i++) {
			if (i)
				fputc(' ', f);
			draw_print_coord(f, dash[i]);
		}
		fputc('"', f);
	}
}

static void points(FILE *f, const struct draw_item *e, double yoff, double h)
{
	fputs(" points=\"", f);
	for (int i = 0; i < e->n; i++) {
		if (i)
			fputc(' ', f);
		draw_print_coord(f, e->xy[2 * i]);
		fputc(',', f);
		draw_print_coord(f, yoff + h - e->xy[2 * i + 1]);
	}
	fputc('"', f);
}

static void xml_text(FILE *f, const char *s)
{
	for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
		switch (*p) {
		case '<': fputs("&lt;", f); break;
		case '>': fputs("&gt;", f); break;
		case '&': fputs("&amp;", f); break;
		case '"': fputs("&quot;", f); break;
		default:
			fputc(*p >= 32 && *p < 127 ? *p : '?', f);
		}
	}
}

/* A DRAW_IMAGE as an embedded PNG (8-bit grey, the zlib stream in stored
 * blocks: no compressor is needed, the picture costs 4/3 of its pixels in
 * base64), drawn with xlink:href so SVG 1.1 readers take it.  The CRC is
 * PNG's (ISO 3309, reflected 0xedb88320), the checksum zlib's Adler-32. */
static unsigned long crc_table[256];

static unsigned long png_crc(const unsigned char *p, size_t n)
{
	if (!crc_table[1])
		for (unsigned long k = 0; k < 256; k++) {
			unsigned long c = k;
			for (int j = 0; j < 8; j++)
				c = c & 1 ? 0xedb88320UL ^ (c >> 1) : c >> 1;
			crc_table[k] = c;
		}
	unsigned long c = 0xffffffffUL;
	for (size_t i = 0; i < n; i++)
		c = crc_table[(c ^ p[i]) & 0xff] ^ (c >> 8);
	return c ^ 0xffffffffUL;
}

static void put32(unsigned char *p, unsigned long v)
{
	p[0] = (unsigned char)(v >> 24), p[1] = (unsigned char)(v >> 16);
	p[2] = (unsigned char)(v >> 8), p[3] = (unsigned char)v;
}

/* A chunk of type t and n data bytes at buf + 8: its length, type and CRC
 * written around them; returns the chunk's size. */
static size_t png_chunk(unsigned char *buf, const char *t, size_t n)
{
	put32(buf, (unsigned long)n);
	memcpy(buf + 4, t, 4);
	put32(buf + 8 + n, png_crc(buf + 4, n + 4));
	return n + 12;
}

static void base64(FILE *f, const unsigned char *p, size_t n)
{
	static const char b64[] =
		"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
	for (size_t i = 0; i < n; i += 3) {
		unsigned long v = (unsigned long)p[i] << 16;
		if (i + 1 < n) v |= (unsigned long)p[i + 1] << 8;
		if (i + 2 < n) v |= p[i + 2];
		fputc(b64[v >> 18 & 63], f);
		fputc(b64[v >> 12 & 63], f);
		fputc(i + 1 < n ? b64[v >> 6 & 63] : '=', f);
		fputc(i + 2 < n ? b64[v & 63] : '=', f);
	}
}

/* The x, y, width and height of the item's box (xy: x0 y0 x1 y1 from the
 * page's bottom) as SVG attribute values, y from the top; opened by the
 * caller's x=" and closed by its next quote. */
static void rect_attrs(FILE *f, const struct draw_item *e, double yoff, double H)
{
	draw_print_coord(f, e->xy[0]);
	fputs("\" y=\"", f);
	draw_print_coord(f, yoff + H - e->xy[3]);
	fputs("\" width=\"", f);
	draw_print_coord(f, e->xy[2] - e->xy[0]);
	fputs("\" height=\"", f);
	draw_print_coord(f, e->xy[3] - e->xy[1]);
}

static void svg_image(FILE *f, const struct draw_item *e, double yoff, double H)
{
	size_t cols = (size_t)e->halign, rows = (size_t)e->valign;
	const unsigned char *px = (const unsigned char *)e->text;
	size_t raw = rows * (cols + 1), nblk = raw / 65535 + 1;
	size_t idat = 2 + raw + 5 * nblk + 4;
	unsigned char *png = xmalloc(8 + 25 + 12 + idat + 12);
	memcpy(png, "\x89PNG\r\n\x1a\n", 8);
	size_t at = 8;
	unsigned char *ih = png + at + 8;
	put32(ih, (unsigned long)cols);
	put32(ih + 4, (unsigned long)rows);
	ih[8] = 8, ih[9] = 0, ih[10] = 0, ih[11] = 0, ih[12] = 0;  /* 8-bit grey */
	at += png_chunk(png + at, "IHDR", 13);
	unsigned char *z = png + at + 8;
	size_t zn = 0, left = raw, r = 0, c = 0;
	unsigned long s1 = 1, s2 = 0;           /* Adler-32 */
	z[zn++] = 0x78, z[zn++] = 0x01;
	while (left > 0 || zn == 2) {
		size_t len = left < 65535 ? left : 65535;
		z[zn++] = left == len;          /* BFINAL, stored */
		z[zn++] = (unsigned char)len, z[zn++] = (unsigned char)(len >> 8);
		z[zn++] = (unsigned char)~len, z[zn++] = (unsigned char)(~len >> 8);
		for (size_t k = 0; k < len; k++) {
			/* each row: filter type 0, then its pixels */
			unsigned char v = c == 0 ? 0 : px[r * cols + c - 1];
			if (++c == cols + 1)
				c = 0, r++;
			z[zn++] = v;
			s1 = (s1 + v) % 65521;
			s2 = (s2 + s1) % 65521;
		}
		left -= len;
	}
	put32(z + zn, s2 << 16 | s1);
	zn += 4;
	at += png_chunk(png + at, "IDAT", zn);
	at += png_chunk(png + at, "IEND", 0);
	fputs("<image xmlns:xlink=\"http://www.w3.org/1999/xlink\" x=\"", f);
	rect_attrs(f, e, yoff, H);
	fputs("\" preserveAspectRatio=\"none\" xlink:href=\"data:image/png;base64,", f);
	base64(f, png, at);
	fputs("\"/>\n", f);
	free(png);
}

void draw_write_svg(const struct draw *d, const char *path)
{
	struct aout *a = aout_open(path);
	FILE *f = a->f;
	int npages = d->npages ? d->npages : 1;
	/* d->w x d->h: a landscape picture is drawn on a wide page */
	double W = d->w, H = d->h;
	fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n", f);
	fputs("<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"", f);
	fprintf(f, " width=\"%dpt\" height=\"%dpt\" viewBox=\"0 0 %d %d\">\n",
		(int)W, (int)H * npages, (int)W, (int)H * npages);
	fputs("<g stroke-linejoin=\"round\" stroke-linecap=\"round\">\n", f);
	int clipid = 0, inclip = 0;
	for (int i = 0; i < d->nitems; i++) {
		const struct draw_item *e = &d->items[i];
		double yoff = H * e->page;
		if (i > 0 && d->items[i - 1].page != e->page && inclip) {
			fputs("</g>\n", f);
			inclip = 0;
		}
		switch (e->kind) {
		case DRAW_LINE:
			fputs("<polyline fill=\"none\"", f);
			stroke_attrs(f, e);
			points(f, e, yoff, H);
			fputs("/>\n", f);
			break;
		case DRAW_POLY:
			fputs("<polygon fill=\"", f);
			if (e->fill >= 0)
				gray_color(f, e->fill);
			else
				fputs("none", f);
			fputc('"', f);
			stroke_attrs(f, e);
			points(f, e, yoff, H);
			fputs("/>\n", f);
			break;
		case DRAW_TEXT: {
			static const char *anchor[3] = {"start", "middle", "end"};
			double x = e->xy[0], y = yoff + H - e->xy[1];
			/* the PostScript places the baseline at -0.36 (1 + va) size */
			double dy = e->size * 0.36 * (1 + e->valign);
			fputs("<text x=\"", f);
			draw_print_coord(f, x);
			fputs("\" y=\"", f);
			draw_print_coord(f, y);
			fputs("\" font-family=\"Helvetica, Arial, sans-serif\" font-size=\"", f);
			draw_print_coord(f, e->size);
			fprintf(f, "\" text-anchor=\"%s\" fill=\"", anchor[e->halign + 1]);
			gray_color(f, e->gray);
			fputc('"', f);
			if (e->angle != 0 || dy != 0) {
				fputs(" transform=\"rotate(", f);
				draw_print_coord(f, -e->angle);
				fputc(' ', f);
				draw_print_coord(f, x);
				fputc(' ', f);
				draw_print_coord(f, y);
				fputs(") translate(0 ", f);
				draw_print_coord(f, dy);
				fputs(")\"", f);
			}
			fputc('>', f);
			xml_text(f, e->text);
			fputs("</text>\n", f);
			break;
		}
		case DRAW_CLIP:
			if (inclip)
				fputs("</g>\n", f);
			clipid++;
			fprintf(f, "<clipPath id=\"c%d\"><rect x=\"", clipid);
			rect_attrs(f, e, yoff, H);
			fprintf(f, "\"/></clipPath>\n<g clip-path=\"url(#c%d)\">\n", clipid);
			inclip = 1;
			break;
		case DRAW_IMAGE:
			svg_image(f, e, yoff, H);
			break;
		case DRAW_UNCLIP:
			if (inclip)
				fputs("</g>\n", f);
			inclip = 0;
			break;
		}
	}
	if (inclip)
		fputs("</g>\n", f);
	fputs("</g>\n</svg>\n", f);
	aout_commit(a);
}
