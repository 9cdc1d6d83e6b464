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

/* A DRAW_IMAGE as rectangles, one a run of equal grey along a row (white
 * runs left out): plain SVG 1.1, no embedded bitmap. */
static void svg_image(FILE *f, const struct draw_item *e, double yoff, double H)
{
	int cols = e->halign, rows = e->valign;
	const unsigned char *px = (const unsigned char *)e->text;
	double pw = (e->xy[2] - e->xy[0]) / cols, ph = (e->xy[3] - e->xy[1]) / rows;
	for (int r = 0; r < rows; r++)
		for (int i = 0; i < cols;) {
			const unsigned char *row = px + (size_t)r * (size_t)cols;
			int n = 1;
			while (i + n < cols && row[i + n] == row[i])
				n++;
			if (row[i] != 255) {
				fputs("<rect x=\"", f);
				draw_print_coord(f, e->xy[0] + i * pw);
				fputs("\" y=\"", f);
				draw_print_coord(f, yoff + H - e->xy[3] + r * ph);
				fputs("\" width=\"", f);
				draw_print_coord(f, n * pw);
				fputs("\" height=\"", f);
				draw_print_coord(f, ph);
				fputs("\" fill=\"", f);
				gray_color(f, row[i] / 255.0);
				fputs("\"/>\n", f);
			}
			i += n;
		}
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
			draw_print_coord(f, e->xy[0]);
			fputs("\" y=\"", f);
			draw_print_coord(f, yoff + H - e->xy[3]);
			fputs("\" width=\"", f);
			draw_print_coord(f, e->xy[2] - e->xy[0]);
			fputs("\" height=\"", f);
			draw_print_coord(f, e->xy[3] - e->xy[1]);
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
