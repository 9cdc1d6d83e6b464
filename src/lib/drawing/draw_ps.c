/*
 * draw_ps.c - PostScript back end: a DSC-conforming file (one %%Page per
 * page) that ghostscript and printers accept.  Coordinates are printed
 * with two decimals through one function, so output is identical
 * everywhere; no %%CreationDate is written.
 */
#include "draw.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <string.h>


static void ps_string(FILE *f, const char *s)
{
	fputc('(', f);
	for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
		if (*p == '(' || *p == ')' || *p == '\\')
			fprintf(f, "\\%c", *p);
		else if (*p < 32 || *p > 126)
			fprintf(f, "\\%03o", *p);
		else
			fputc(*p, f);
	}
	fputc(')', f);
}

static void set_style(FILE *f, const struct draw_item *it, int *cur_lt,
		      double *cur_w, double *cur_g)
{
	if (it->linetype != *cur_lt) {
		double dash[6];
		int n = draw_dash(it->linetype, dash);
		fputc('[', f);
		for (int i = 0; i < n; i++) {
			if (i)
				fputc(' ', f);
			draw_print_coord(f, dash[i]);
		}
		fputs("] 0 setdash\n", f);
		*cur_lt = it->linetype;
	}
	if (it->width != *cur_w) {
		draw_print_coord(f, it->width);
		fputs(" setlinewidth\n", f);
		*cur_w = it->width;
	}
	if (it->gray != *cur_g) {
		draw_print_coord(f, it->gray);
		fputs(" setgray\n", f);
		*cur_g = it->gray;
	}
}

/* One byte as two hex digits, 32 bytes to a line. */
static void hex_byte(FILE *f, unsigned v, int *col)
{
	static const char hx[] = "0123456789abcdef";
	fputc(hx[v >> 4 & 15], f);
	fputc(hx[v & 15], f);
	if (++*col == 32) {
		fputc('\n', f);
		*col = 0;
	}
}

/* A DRAW_IMAGE: 8-bit grey through RunLengthDecode (runs of one grey, the
 * margins and walls, shrink to two bytes a run of 128) and ASCIIHexDecode,
 * both PostScript level 2 filters. */
static void ps_image(FILE *f, const struct draw_item *e)
{
	int cols = e->halign, rows = e->valign, col = 0;
	const unsigned char *px = (const unsigned char *)e->text;
	fputs("gsave ", f);
	draw_print_coord(f, e->xy[0]); fputc(' ', f);
	draw_print_coord(f, e->xy[1]); fputs(" translate ", f);
	draw_print_coord(f, e->xy[2] - e->xy[0]); fputc(' ', f);
	draw_print_coord(f, e->xy[3] - e->xy[1]); fputs(" scale\n", f);
	fprintf(f, "%d %d 8 [%d 0 0 -%d 0 %d]\n", cols, rows, cols, rows, rows);
	fputs("currentfile /ASCIIHexDecode filter /RunLengthDecode filter image\n", f);
	for (int r = 0; r < rows; r++) {
		const unsigned char *row = px + (size_t)r * (size_t)cols;
		int i = 0;
		while (i < cols) {
			int run = 1;
			while (i + run < cols && run < 128 && row[i + run] == row[i])
				run++;
			if (run >= 3) {
				hex_byte(f, (unsigned)(257 - run), &col);
				hex_byte(f, row[i], &col);
				i += run;
				continue;
			}
			/* a literal stretch, up to the next run of three */
			int n = 0;
			while (i + n < cols && n < 128 &&
			       !(i + n + 2 < cols && row[i + n] == row[i + n + 1] &&
				 row[i + n] == row[i + n + 2]))
				n++;
			if (n == 0)
				n = 1;
			hex_byte(f, (unsigned)(n - 1), &col);
			for (int k = 0; k < n; k++)
				hex_byte(f, row[i + k], &col);
			i += n;
		}
	}
	hex_byte(f, 128, &col);     /* RunLengthDecode's end of data */
	fputs(">\ngrestore\n", f);
}

/* A path's text is made line by line (six points) in a buffer and
 * written at once: the same bytes as a fputs per coordinate, a quarter of
 * pdraw -h's writing time less. */
static void path(FILE *f, const struct draw_item *it)
{
	char line[6 * (2 * 40 + 4)];
	size_t len = 0;
	for (int i = 0; i < it->n; i++) {
		for (int k = 0; k < 2; k++) {
			len += draw_coord_text(line + len, 40, it->xy[2 * i + k]);
			line[len++] = ' ';
		}
		line[len++] = i == 0 ? 'm' : 'l';
		if (i % 6 == 5 || i == it->n - 1) {
			line[len++] = '\n';
			fwrite(line, 1, len, f);
			len = 0;
		} else {
			line[len++] = ' ';
		}
	}
}

static const char prolog[] =
	"%%BeginProlog\n"
	"/m {moveto} bind def /l {lineto} bind def\n"
	"/S {stroke} bind def\n"
	"% gray F: fill the current path with a gray, keeping the path\n"
	"/F {gsave setgray fill grestore} bind def\n"
	"% str x y size angle halign valign T: aligned, rotated text\n"
	"/T {/va exch def /ha exch def /an exch def /sz exch def\n"
	"  gsave translate an rotate /Helvetica findfont sz scalefont setfont\n"
	"  dup stringwidth pop ha 1 add 2 div neg mul\n"
	"  sz 0.72 mul va 1 add 2 div neg mul moveto show grestore} bind def\n"
	"1 setlinejoin 1 setlinecap\n"
	"%%EndProlog\n";

void draw_write_ps(const struct draw *d, const char *path_name, const struct draw_ps_opts *o)
{
	struct aout *a = aout_open(path_name);
	FILE *f = a->f;
	double scale = o && o->scale > 0 ? o->scale : 1.0;
	int land = o && o->landscape;
	int npages = d->npages ? d->npages : 1;
	fputs("%!PS-Adobe-3.0\n", f);
	fputs("%%Creator: sample3d\n", f);
	if (o && o->title) {
		fputs("%%Title: ", f);
		for (const char *p = o->title; *p; p++)
			fputc((*p >= 32 && *p < 127) ? *p : '?', f);
		fputc('\n', f);
	}
	fprintf(f, "%%%%BoundingBox: 0 0 %d %d\n", (int)DRAW_PAGE_W, (int)DRAW_PAGE_H);
	fprintf(f, "%%%%Pages: %d\n", npages);
	fprintf(f, "%%%%Orientation: %s\n", land ? "Landscape" : "Portrait");
	fputs("%%EndComments\n", f);
	fputs(prolog, f);
	int it = 0;
	for (int p = 0; p < npages; p++) {
		fprintf(f, "%%%%Page: %d %d\n", p + 1, p + 1);
		fputs("save\n", f);
		if (land) {
			/* the drawing's page (w x h) is laid on its side */
			draw_print_coord(f, DRAW_PAGE_W);
			fputs(" 0 translate 90 rotate\n", f);
		}
		if (scale != 1.0) {
			double cw = land ? DRAW_PAGE_H : DRAW_PAGE_W;
			double ch = land ? DRAW_PAGE_W : DRAW_PAGE_H;
			draw_print_coord(f, cw / 2 * (1 - scale));
			fputc(' ', f);
			draw_print_coord(f, ch / 2 * (1 - scale));
			fputs(" translate ", f);
			fprintf(f, "%.4f dup scale\n", scale);
		}
		int lt = -1, clipped = 0;
		double w = -1, g = -1;
		for (; it < d->nitems && d->items[it].page == p; it++) {
			const struct draw_item *e = &d->items[it];
			switch (e->kind) {
			case DRAW_LINE:
				set_style(f, e, &lt, &w, &g);
				path(f, e);
				fputs("S\n", f);
				break;
			case DRAW_POLY:
				path(f, e);
				fputs("closepath", f);
				if (e->fill >= 0) {
					fputc(' ', f);
					draw_print_coord(f, e->fill);
					fputs(" F", f);
				}
				if (e->linetype) {
					fputc('\n', f);
					set_style(f, e, &lt, &w, &g);
					fputs("S\n", f);
				} else {
					fputs(" newpath\n", f);
				}
				break;
			case DRAW_TEXT:
				set_style(f, e, &lt, &w, &g);
				ps_string(f, e->text);
				fputc(' ', f);
				draw_print_coord(f, e->xy[0]);
				fputc(' ', f);
				draw_print_coord(f, e->xy[1]);
				fputc(' ', f);
				draw_print_coord(f, e->size);
				fputc(' ', f);
				draw_print_coord(f, e->angle);
				fprintf(f, " %d %d T\n", e->halign, e->valign);
				break;
			case DRAW_CLIP:
				if (clipped) {
					/* grestore brings back the style of before the
					 * clip: force it out again */
					fputs("grestore\n", f);
					lt = -1, w = -1, g = -1;
				}
				fputs("gsave newpath ", f);
				draw_print_coord(f, e->xy[0]); fputc(' ', f);
				draw_print_coord(f, e->xy[1]); fputc(' ', f);
				draw_print_coord(f, e->xy[2] - e->xy[0]); fputc(' ', f);
				draw_print_coord(f, e->xy[3] - e->xy[1]);
				fputs(" rectclip\n", f);
				clipped = 1;
				break;
			case DRAW_IMAGE:
				ps_image(f, e);
				break;
			case DRAW_UNCLIP:
				if (clipped) {
					fputs("grestore\n", f);
					clipped = 0;
					lt = -1, w = -1, g = -1;
				}
				break;
			}
		}
		if (clipped)
			fputs("grestore\n", f);
		fputs("restore\nshowpage\n", f);
	}
	fputs("%%Trailer\n%%EOF\n", f);
	aout_commit(a);
}
