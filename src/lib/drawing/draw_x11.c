/*
 * draw_x11.c - X11 preview (see draw_x11.h).  The display list is in page
 * points with y up; the window maps the page, keeping its aspect ratio,
 * onto its current size with y down.  Grays go through a small cache of
 * allocated colours; dash patterns are those of draw_dash, so line types
 * look as on paper.  Text is drawn unrotated in the chosen font (X core
 * fonts cannot rotate); alignment follows the PostScript placement.
 */
#include "draw_x11.h"
#include "util.h"

#ifndef HAVE_X11

int draw_x11_built(void) { return 0; }

int draw_x11_show(const struct draw_x11_opts *o, draw_x11_render render,
		  draw_x11_key key, void *ctx, const char **why)
{
	(void)o, (void)render, (void)key, (void)ctx;
	*why = "built without X11";
	return -1;
}

#else

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/keysym.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int draw_x11_built(void) { return 1; }

struct xwin {
	Display *dpy;
	Window win;
	GC gc;
	XFontStruct *font;
	Colormap cmap;
	unsigned long gray_px[33];
	int gray_ok[33];
	int reverse;
	unsigned long fg, bg;
	int have_fg, have_bg;
	int width, height;
	double sc, ox, oy;      /* page point -> pixel */
	double pw, ph;          /* page size of the picture */
};

static unsigned long gray_pixel(struct xwin *x, double g)
{
	/* 0 is the foreground colour, 1 the background, as on paper */
	if (x->reverse)
		g = 1 - g;
	if (g <= 0.0 && x->have_fg)
		return x->fg;
	if (g >= 1.0 && x->have_bg)
		return x->bg;
	int k = (int)lround(g * 32);
	if (k < 0) k = 0;
	if (k > 32) k = 32;
	if (!x->gray_ok[k]) {
		XColor c;
		c.red = c.green = c.blue = (unsigned short)(k * 65535 / 32);
		c.flags = DoRed | DoGreen | DoBlue;
		if (XAllocColor(x->dpy, x->cmap, &c))
			x->gray_px[k] = c.pixel;
		else
			x->gray_px[k] = k >= 16 ? WhitePixel(x->dpy, DefaultScreen(x->dpy))
						: BlackPixel(x->dpy, DefaultScreen(x->dpy));
		x->gray_ok[k] = 1;
	}
	return x->gray_px[k];
}

static int named_color(struct xwin *x, const char *name, unsigned long *px)
{
	XColor c, exact;
	if (!name)
		return 0;
	if (!XAllocNamedColor(x->dpy, x->cmap, name, &c, &exact)) {
		warn("X11: unknown colour \"%.40s\", ignored", name);
		return 0;
	}
	*px = c.pixel;
	return 1;
}

static void map_pt(const struct xwin *x, double px, double py, short *sx, short *sy)
{
	double X = x->ox + px * x->sc, Y = x->oy + (x->ph - py) * x->sc;
	if (X < -30000) X = -30000;
	if (X > 30000) X = 30000;
	if (Y < -30000) Y = -30000;
	if (Y > 30000) Y = 30000;
	*sx = (short)lround(X);
	*sy = (short)lround(Y);
}

static void set_line(struct xwin *x, const struct draw_item *e)
{
	double dash[6];
	int n = draw_dash(e->linetype, dash);
	int w = (int)lround(e->width * x->sc);
	if (w < 1)
		w = 0;      /* thin (fast) line */
	if (n > 0) {
		char dl[6];
		for (int i = 0; i < n; i++) {
			long v = lround(dash[i] * x->sc);
			dl[i] = (char)(v < 1 ? 1 : v > 127 ? 127 : v);
		}
		XSetDashes(x->dpy, x->gc, 0, dl, n);
		XSetLineAttributes(x->dpy, x->gc, (unsigned)w, LineOnOffDash, CapRound, JoinRound);
	} else {
		XSetLineAttributes(x->dpy, x->gc, (unsigned)w, LineSolid, CapRound, JoinRound);
	}
	XSetForeground(x->dpy, x->gc, gray_pixel(x, e->gray));
}

/* A DRAW_IMAGE as filled rectangles, one a run of equal grey along a row
 * (white runs left out: the window is cleared to white). */
static void x11_image(struct xwin *x, const struct draw_item *e)
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
				short ax, ay, bx, by;
				map_pt(x, e->xy[0] + i * pw, e->xy[3] - r * ph, &ax, &ay);
				map_pt(x, e->xy[0] + (i + n) * pw, e->xy[3] - (r + 1) * ph, &bx, &by);
				XSetForeground(x->dpy, x->gc, gray_pixel(x, row[i] / 255.0));
				XFillRectangle(x->dpy, x->win, x->gc, ax, ay,
					       (unsigned)(bx > ax ? bx - ax : 1),
					       (unsigned)(by > ay ? by - ay : 1));
			}
			i += n;
		}
}

static void paint(struct xwin *x, const struct draw *d, int page)
{
	x->pw = d->w;
	x->ph = d->h;
	double sx = x->width / d->w, sy = x->height / d->h;
	x->sc = sx < sy ? sx : sy;
	x->ox = (x->width - d->w * x->sc) / 2;
	x->oy = (x->height - d->h * x->sc) / 2;
	XSetClipMask(x->dpy, x->gc, None);
	XSetForeground(x->dpy, x->gc, gray_pixel(x, 1.0));
	XFillRectangle(x->dpy, x->win, x->gc, 0, 0, (unsigned)x->width, (unsigned)x->height);
	XPoint *pts = NULL;
	size_t cap = 0;
	for (int i = 0; i < d->nitems; i++) {
		const struct draw_item *e = &d->items[i];
		if (e->page != page)
			continue;
		xgrow(&pts, &cap, (size_t)e->n + 1, sizeof *pts);
		for (int k = 0; k < e->n; k++)
			map_pt(x, e->xy[2 * k], e->xy[2 * k + 1], &pts[k].x, &pts[k].y);
		switch (e->kind) {
		case DRAW_LINE:
			set_line(x, e);
			XDrawLines(x->dpy, x->win, x->gc, pts, e->n, CoordModeOrigin);
			break;
		case DRAW_POLY:
			if (e->fill >= 0) {
				XSetForeground(x->dpy, x->gc, gray_pixel(x, e->fill));
				XFillPolygon(x->dpy, x->win, x->gc, pts, e->n, Complex, CoordModeOrigin);
			}
			if (e->linetype) {
				set_line(x, e);
				pts[e->n] = pts[0];
				XDrawLines(x->dpy, x->win, x->gc, pts, e->n + 1, CoordModeOrigin);
			}
			break;
		case DRAW_TEXT: {
			int len = (int)strlen(e->text);
			int tw = x->font ? XTextWidth(x->font, e->text, len) : 6 * len;
			int asc = x->font ? x->font->ascent : 10;
			int X = pts[0].x - (e->halign + 1) * tw / 2;
			int Y = pts[0].y + (e->valign + 1) * asc / 2;
			XSetForeground(x->dpy, x->gc, gray_pixel(x, e->gray));
			XDrawString(x->dpy, x->win, x->gc, X, Y, e->text, len);
			break;
		}
		case DRAW_CLIP: {
			short ax, ay, bx, by;
			map_pt(x, e->xy[0], e->xy[1], &ax, &ay);
			map_pt(x, e->xy[2], e->xy[3], &bx, &by);
			XRectangle r = {ax, by, (unsigned short)(bx - ax + 1),
					(unsigned short)(ay - by + 1)};
			XSetClipRectangles(x->dpy, x->gc, 0, 0, &r, 1, Unsorted);
			break;
		}
		case DRAW_IMAGE:
			x11_image(x, e);
			break;
		case DRAW_UNCLIP:
			XSetClipMask(x->dpy, x->gc, None);
			break;
		}
	}
	free(pts);
	XFlush(x->dpy);
}

int draw_x11_show(const struct draw_x11_opts *o, draw_x11_render render,
		  draw_x11_key key, void *ctx, const char **why)
{
	struct xwin x;
	memset(&x, 0, sizeof x);
	x.dpy = XOpenDisplay(o->display);
	if (!x.dpy) {
		*why = "cannot open the X display";
		return -1;
	}
	int scr = DefaultScreen(x.dpy);
	x.cmap = DefaultColormap(x.dpy, scr);
	x.reverse = o->reverse;
	x.have_fg = named_color(&x, o->fg, &x.fg);
	x.have_bg = named_color(&x, o->bg, &x.bg);
	struct draw *d = render(ctx);

	/* default size: the page at about 0.9 pixel per point */
	int gx = 0, gy = 0;
	unsigned gw = (unsigned)(d->w * 0.9), gh = (unsigned)(d->h * 0.9);
	if (o->geometry)
		XParseGeometry(o->geometry, &gx, &gy, &gw, &gh);
	unsigned long bd = BlackPixel(x.dpy, scr);
	named_color(&x, o->border, &bd);
	unsigned bw = o->border_width >= 0 ? (unsigned)o->border_width : 1;
	x.win = XCreateSimpleWindow(x.dpy, RootWindow(x.dpy, scr), gx, gy, gw, gh, bw,
				    bd, gray_pixel(&x, 1.0));
	x.width = (int)gw;
	x.height = (int)gh;
	const char *title = o->title ? o->title : util_prog();
	XStoreName(x.dpy, x.win, title);
	Atom wm_delete = XInternAtom(x.dpy, "WM_DELETE_WINDOW", False);
	XSetWMProtocols(x.dpy, x.win, &wm_delete, 1);
	XSelectInput(x.dpy, x.win, ExposureMask | KeyPressMask | StructureNotifyMask);
	x.gc = XCreateGC(x.dpy, x.win, 0, NULL);
	if (o->font && !(x.font = XLoadQueryFont(x.dpy, o->font)))
		warn("X11: cannot load font \"%.60s\", using the default", o->font);
	if (!x.font)
		x.font = XLoadQueryFont(x.dpy, "fixed");
	if (x.font)
		XSetFont(x.dpy, x.gc, x.font->fid);
	XMapWindow(x.dpy, x.win);

	int page = 0, done = 0, destroyed = 0;
	while (!done) {
		XEvent ev;
		XNextEvent(x.dpy, &ev);
		switch (ev.type) {
		case Expose:
			if (ev.xexpose.count == 0)
				paint(&x, d, page);
			break;
		case ConfigureNotify:
			if (ev.xconfigure.width != x.width || ev.xconfigure.height != x.height) {
				x.width = ev.xconfigure.width;
				x.height = ev.xconfigure.height;
				paint(&x, d, page);
			}
			break;
		case ClientMessage:
			if ((Atom)ev.xclient.data.l[0] == wm_delete)
				done = 1;
			break;
		case DestroyNotify:
			done = destroyed = 1;
			break;
		case KeyPress: {
			char buf[8];
			KeySym ks;
			int n = XLookupString(&ev.xkey, buf, sizeof buf, &ks, NULL);
			int c = n == 1 ? (unsigned char)buf[0] : 0;
			if (ks == XK_Escape || c == 'q' || c == 'Q') {
				done = 1;
			} else if (c == ' ' || c == 'n' || ks == XK_Next) {
				if (page + 1 < d->npages)
					paint(&x, d, ++page);
			} else if (c == 'p' || ks == XK_Prior) {
				if (page > 0)
					paint(&x, d, --page);
			} else if (c && key && key(ctx, c)) {
				draw_free(d);
				d = render(ctx);
				if (page >= d->npages)
					page = d->npages > 0 ? d->npages - 1 : 0;
				paint(&x, d, page);
			}
			break;
		}
		default:
			break;
		}
	}
	draw_free(d);
	if (x.font)
		XFreeFont(x.dpy, x.font);
	XFreeGC(x.dpy, x.gc);
	if (!destroyed)
		XDestroyWindow(x.dpy, x.win);
	XCloseDisplay(x.dpy);
	return 0;
}

#endif
