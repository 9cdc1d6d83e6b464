/*
 * draw.h - the drawing back end of the plot programs.
 *
 * A program draws into a display list (struct draw) in page coordinates:
 * PostScript points (1/72 inch), origin at the bottom left of a portrait
 * page of DRAW_PAGE_W x DRAW_PAGE_H.  The list is then written as
 * PostScript (dataplot.ps), as SVG, or replayed in an X11 window; so the
 * three outputs show the same picture.  Output is deterministic: no
 * dates, coordinates rounded to 0.01 pt, fixed number formats.
 *
 * Line types and marker types are those of drawplot(L):
 *   line types 0-10: none, solid, dashed, dotted, dot dash, double dot,
 *     long dash, dot dash (long), long dots, short dash, dot-dot dash;
 *   markers 0-17: none, point, square, diamond, upright triangle and
 *     upside-down triangle (each white, gray, black), circle (white,
 *     gray, black), x.
 */
#ifndef S3D_DRAW_H
#define S3D_DRAW_H

#include <stdio.h>

#define DRAW_PAGE_W 612.0
#define DRAW_PAGE_H 792.0
#define DRAW_NOFILL (-1.0)

enum { DRAW_NLINETYPES = 11, DRAW_NMARKERS = 18 };
enum { DRAW_LEFT = -1, DRAW_CENTER = 0, DRAW_RIGHT = 1 };      /* halign */
enum { DRAW_BOTTOM = -1, DRAW_MIDDLE = 0, DRAW_TOP = 1 };      /* valign */

enum draw_kind { DRAW_LINE, DRAW_POLY, DRAW_TEXT, DRAW_CLIP, DRAW_UNCLIP, DRAW_IMAGE };

/* The ints side by side: 80 bytes, not 96 (a list holds two items a
 * triangle for pdraw -h). */
struct draw_item {
	enum draw_kind kind;
	int page;
	int linetype;       /* stroke dash pattern, 0 = no stroke */
	int n;              /* points */
	double width;       /* stroke width, points */
	double gray;        /* stroke (or text) gray, 0 black .. 1 white */
	double fill;        /* DRAW_POLY: fill gray or DRAW_NOFILL */
	double *xy;         /* 2n coordinates; DRAW_CLIP: x0 y0 x1 y1 */
	char *text;         /* DRAW_TEXT, at xy[0], xy[1]; DRAW_IMAGE: the pixels */
	double size, angle; /* text size in points, angle in degrees */
	int halign, valign; /* DRAW_IMAGE: columns and rows */
};

struct draw {
	double w, h;        /* page size */
	int npages;
	int nitems;
	struct draw_item *items;
	unsigned long cap;
	/* current state */
	int linetype;
	double width, gray;
};

struct draw *draw_new(void);
void draw_free(struct draw *d);
/* Starts a new page (the first drawing call starts page 1 by itself). */
void draw_page(struct draw *d);
/* Line type 0-10, width in points (default 1, solid, 0.8). */
void draw_set_line(struct draw *d, int linetype, double width);
/* Stroke and text gray level, 0 black (default) .. 1 white. */
void draw_set_gray(struct draw *d, double gray);
void draw_polyline(struct draw *d, int n, const double *xy);
void draw_segment(struct draw *d, double x0, double y0, double x1, double y1);
/* Closed polygon: filled with gray fill (unless DRAW_NOFILL), outlined
 * with the current line if stroke is non-zero. */
void draw_polygon(struct draw *d, int n, const double *xy, double fill, int stroke);
/* Marker 0-17 centred at (x, y), size points across. */
void draw_marker(struct draw *d, int type, double x, double y, double size);
/* Text in Helvetica, size points, rotated angle degrees about (x, y). */
void draw_text(struct draw *d, double x, double y, double size, double angle,
	       int halign, int valign, const char *s);
/* A grey-scale picture of cols x rows pixels (0 black .. 255 white, row
 * by row from the top) stretched over the page rectangle x0 y0 x1 y1:
 * what a drawing of more polygons than pixels is rendered to. */
void draw_image(struct draw *d, double x0, double y0, double x1, double y1,
		int cols, int rows, const unsigned char *pix);
/* Clips later drawing on this page to a rectangle, until draw_unclip. */
void draw_clip(struct draw *d, double x0, double y0, double x1, double y1);
void draw_unclip(struct draw *d);

struct draw_ps_opts {
	double scale;       /* about the page centre, 1 = as drawn */
	int landscape;      /* rotate the page by 90 degrees */
	const char *title;  /* %%Title, may be NULL */
};
void draw_write_ps(const struct draw *d, const char *path, const struct draw_ps_opts *o);
/* SVG: pages stacked top to bottom in one picture. */
void draw_write_svg(const struct draw *d, const char *path);

/* Prints a coordinate for the PostScript and SVG writers: rounded to
 * 0.01 pt, trailing zeros dropped, never "-0", so output is the same
 * everywhere. */
void draw_print_coord(FILE *f, double v);
/* The same text into buf (size bytes, at least 24 for the fast path);
 * returns its length. */
size_t draw_coord_text(char *buf, size_t size, double v);

/* Dash pattern of a line type: fills dash[] (points), returns its length. */
int draw_dash(int linetype, double dash[6]);

#endif
