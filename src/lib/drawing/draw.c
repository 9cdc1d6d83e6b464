/*
 * draw.c - the display list (see draw.h).  Markers are expanded here into
 * polygons and lines, so every back end draws them identically without
 * knowing about markers.
 */
#include "draw.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct draw *draw_new(void)
{
	struct draw *d = xcalloc(1, sizeof *d);
	d->w = DRAW_PAGE_W;
	d->h = DRAW_PAGE_H;
	d->linetype = 1;
	d->width = 0.8;
	d->gray = 0;
	return d;
}

void draw_free(struct draw *d)
{
	if (!d)
		return;
	for (int i = 0; i < d->nitems; i++) {
		free(d->items[i].xy);
		free(d->items[i].text);
	}
	free(d->items);
	free(d);
}

void draw_page(struct draw *d) { d->npages++; }

void draw_set_line(struct draw *d, int linetype, double width)
{
	if (linetype < 0 || linetype >= DRAW_NLINETYPES)
		linetype = 1;
	d->linetype = linetype;
	d->width = width > 0 ? width : 0.8;
}

void draw_set_gray(struct draw *d, double gray)
{
	d->gray = gray < 0 ? 0 : gray > 1 ? 1 : gray;
}

static struct draw_item *add(struct draw *d, enum draw_kind kind, int n, const double *xy)
{
	if (d->npages == 0)
		d->npages = 1;
	size_t cap = d->cap;
	xgrow(&d->items, &cap, (size_t)d->nitems + 1, sizeof *d->items);
	d->cap = cap;
	struct draw_item *it = &d->items[d->nitems++];
	memset(it, 0, sizeof *it);
	it->kind = kind;
	it->page = d->npages - 1;
	it->linetype = d->linetype;
	it->width = d->width;
	it->gray = d->gray;
	it->fill = DRAW_NOFILL;
	it->n = n;
	it->xy = xreallocarray(NULL, (size_t)(n > 0 ? n : 1), 2 * sizeof(double));
	if (n > 0)
		memcpy(it->xy, xy, (size_t)n * 2 * sizeof(double));
	return it;
}

void draw_polyline(struct draw *d, int n, const double *xy)
{
	if (n >= 2 && d->linetype != 0)
		add(d, DRAW_LINE, n, xy);
}

void draw_segment(struct draw *d, double x0, double y0, double x1, double y1)
{
	double xy[4] = {x0, y0, x1, y1};
	draw_polyline(d, 2, xy);
}

void draw_polygon(struct draw *d, int n, const double *xy, double fill, int stroke)
{
	if (n < 3)
		return;
	struct draw_item *it = add(d, DRAW_POLY, n, xy);
	it->fill = fill < 0 ? DRAW_NOFILL : fill > 1 ? 1 : fill;
	if (!stroke)
		it->linetype = 0;
}

void draw_text(struct draw *d, double x, double y, double size, double angle,
	       int halign, int valign, const char *s)
{
	double xy[2] = {x, y};
	struct draw_item *it = add(d, DRAW_TEXT, 1, xy);
	it->text = xstrdup(s);
	it->size = size;
	it->angle = angle;
	it->halign = halign;
	it->valign = valign;
}

void draw_image(struct draw *d, double x0, double y0, double x1, double y1,
		int cols, int rows, const unsigned char *pix)
{
	if (cols < 1 || rows < 1)
		return;
	double xy[4] = {fmin(x0, x1), fmin(y0, y1), fmax(x0, x1), fmax(y0, y1)};
	struct draw_item *it = add(d, DRAW_IMAGE, 2, xy);
	size_t n = (size_t)cols * (size_t)rows;
	it->text = xmalloc(n);
	memcpy(it->text, pix, n);
	it->halign = cols;
	it->valign = rows;
}

void draw_clip(struct draw *d, double x0, double y0, double x1, double y1)
{
	double xy[4] = {fmin(x0, x1), fmin(y0, y1), fmax(x0, x1), fmax(y0, y1)};
	add(d, DRAW_CLIP, 2, xy);
}

void draw_unclip(struct draw *d) { add(d, DRAW_UNCLIP, 0, NULL); }

static void shape(struct draw *d, int n, const double *ux, const double *uy,
		  double x, double y, double r, double fill)
{
	double xy[2 * 32];
	for (int i = 0; i < n; i++) {
		xy[2 * i] = x + r * ux[i];
		xy[2 * i + 1] = y + r * uy[i];
	}
	int lt = d->linetype;
	d->linetype = 1; /* marker outlines are always solid */
	draw_polygon(d, n, xy, fill, 1);
	d->linetype = lt;
}

void draw_marker(struct draw *d, int type, double x, double y, double size)
{
	static const double sqx[] = {-1, 1, 1, -1}, sqy[] = {-1, -1, 1, 1};
	static const double dix[] = {0, 1, 0, -1}, diy[] = {-1, 0, 1, 0};
	static const double utx[] = {-1, 1, 0}, uty[] = {-0.8, -0.8, 1};
	static const double dtx[] = {-1, 0, 1}, dty[] = {0.8, -1, 0.8};
	static const double fills[3] = {1.0, 0.5, 0.0};
	double r = size / 2;
	if (type <= 0 || type >= DRAW_NMARKERS)
		return;
	if (type == 1) { /* point: a small black dot */
		double cx[12], cy[12];
		for (int i = 0; i < 12; i++)
			cx[i] = cos(2 * M_PI * i / 12), cy[i] = sin(2 * M_PI * i / 12);
		shape(d, 12, cx, cy, x, y, r * 0.25, 0.0);
	} else if (type <= 4) {
		shape(d, 4, sqx, sqy, x, y, r * 0.8, fills[type - 2]);
	} else if (type <= 7) {
		shape(d, 4, dix, diy, x, y, r, fills[type - 5]);
	} else if (type <= 10) {
		shape(d, 3, utx, uty, x, y, r, fills[type - 8]);
	} else if (type <= 13) {
		shape(d, 3, dtx, dty, x, y, r, fills[type - 11]);
	} else if (type <= 16) {
		double cx[24], cy[24];
		for (int i = 0; i < 24; i++)
			cx[i] = cos(2 * M_PI * i / 24), cy[i] = sin(2 * M_PI * i / 24);
		shape(d, 24, cx, cy, x, y, r, fills[type - 14]);
	} else { /* 17: x marks the spot */
		int lt = d->linetype;
		d->linetype = 1;
		draw_segment(d, x - r, y - r, x + r, y + r);
		draw_segment(d, x - r, y + r, x + r, y - r);
		d->linetype = lt;
	}
}

/* The definition of draw_print_coord's text (printf "%.2f" of the value
 * rounded to 0.01, trailing zeros and point dropped, "-0" folded), used
 * for values too large for the integer form below. */
static void coord_ref(char *buf, size_t size, double v)
{
	double r = round(v * 100) / 100;
	if (fabs(r) < 0.005)
		r = 0;
	snprintf(buf, size, "%.2f", r);
	char *dot = strchr(buf, '.');
	if (dot) {
		char *e = buf + strlen(buf) - 1;
		while (e > dot && *e == '0')
			*e-- = '\0';
		if (e == dot)
			*e = '\0';
	}
}

/* Below this many hundredths the value rounded to 0.01 prints, under
 * "%.2f", as exactly the integer round(v * 100) over 100: the double
 * nearest N / 100 is far closer to it than the 0.005 to a rounding edge. */
#define COORD_INT_MAX 1e15

size_t draw_coord_text(char *buf, size_t size, double v)
{
	double n = round(v * 100);
	if (!(fabs(n) < COORD_INT_MAX) || size < 24) {
		coord_ref(buf, size, v);
		return strlen(buf);
	}
	long long q = (long long)fabs(n);
	char *p = buf;
	if (n < 0)
		*p++ = '-';
	char dig[24];
	int nd = 0;
	long long ip = q / 100;
	do {
		dig[nd++] = (char)('0' + ip % 10);
		ip /= 10;
	} while (ip);
	while (nd)
		*p++ = dig[--nd];
	int c = (int)(q % 100);
	if (c) {
		*p++ = '.';
		*p++ = (char)('0' + c / 10);
		if (c % 10)
			*p++ = (char)('0' + c % 10);
	}
	*p = '\0';
	return (size_t)(p - buf);
}

void draw_print_coord(FILE *f, double v)
{
	char buf[40];
	draw_coord_text(buf, sizeof buf, v);
	fputs(buf, f);
}

int draw_dash(int linetype, double dash[6])
{
	static const double pat[DRAW_NLINETYPES][6] = {
		{0}, {0}, {6, 3}, {1, 3}, {6, 3, 1, 3}, {1, 2, 1, 6},
		{12, 4}, {9, 3, 2, 3}, {1, 6}, {3, 3}, {6, 3, 1, 3, 1, 3},
	};
	static const int len[DRAW_NLINETYPES] = {0, 0, 2, 2, 4, 4, 2, 4, 2, 2, 6};
	if (linetype < 0 || linetype >= DRAW_NLINETYPES)
		return 0;
	memcpy(dash, pat[linetype], sizeof pat[0]);
	return len[linetype];
}
