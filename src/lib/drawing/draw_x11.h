/*
 * draw_x11.h - the X11 preview of the plot programs: a window that replays
 * a display list (struct draw), so the screen shows the same picture as
 * dataplot.ps.  The real code is compiled only with -DHAVE_X11 (the
 * Makefile defines it when libX11 is found); otherwise draw_x11_show
 * reports that the preview is not available and the programs behave as
 * with -noplot.
 *
 * Keys: q, Q, Escape or closing the window end the preview; space, n and
 * p page through a multi-page picture; every other key is passed to the
 * program's key function (pdraw rotates its view with them), which
 * returns 1 when the picture must be rebuilt.
 */
#ifndef S3D_DRAW_X11_H
#define S3D_DRAW_X11_H

#include "draw.h"

/* The X options of the thesis' guides (pdraw(L), contour(L), ...). */
struct draw_x11_opts {
	const char *display;    /* host:display, NULL for $DISPLAY */
	const char *geometry;   /* =WxH+X+Y */
	int reverse;            /* -rv */
	int border_width;       /* -bw, pixels (-1: default) */
	const char *border;     /* -bd color */
	const char *fg, *bg;    /* -fg, -bg colors */
	const char *font;       /* -fn */
	const char *title;      /* window name */
};

/* Builds the picture to show (the caller's draw_free is done here). */
typedef struct draw *(*draw_x11_render)(void *ctx);
/* A key other than the page and quit keys; returns 1 to rebuild. */
typedef int (*draw_x11_key)(void *ctx, int key);

/* 1 if the library was built with X11. */
int draw_x11_built(void);

/* Opens the window and runs until the user ends it.  Returns 0 after a
 * preview, -1 if none could be shown (no X11 in the build, no display);
 * *why then says why, for a one-line note. */
int draw_x11_show(const struct draw_x11_opts *o, draw_x11_render render,
		  draw_x11_key key, void *ctx, const char **why);

#endif
