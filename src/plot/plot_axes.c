/*
 * plot_axes.c - axes of the 2D plot programs: round tick steps (1, 2, 5
 * times a power of ten, the usual "nice numbers" rule), linear and log
 * axes, tick labels, and the frame around a plot.  The guides ask for
 * xticks/yticks divisions and an autorange that "tries to select the
 * best axis-scales possible" (drawplot(L)); log axes put ticks at the
 * decades, evenly spaced.
 */
#include "plot_common.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Relative slack when snapping a range to tick multiples: values within
 * this fraction of a step of a multiple count as on it (rounding noise of
 * printed data, e.g. 0.30000000000000004). */
#define SNAP_TOL 1e-9

/* The narrowest axis range, relative to its largest value and absolute:
 * far below any plotted detail, far above the denormals whose tick steps
 * underflow. */
static const double AXIS_MIN_REL = 1e-12, AXIS_MIN_ABS = 1e-280;

double plot_nice_step(double lo, double hi, int ndiv)
{
	double span = fabs(hi - lo);
	if (ndiv < 1)
		ndiv = 1;
	if (!(span > 0) || !isfinite(span))
		span = fabs(lo) > 0 ? fabs(lo) : 1;
	double raw = span / ndiv;
	double p = pow(10, floor(log10(raw)));
	double m = raw / p;
	double nice = m < 1.5 ? 1 : m < 3 ? 2 : m < 7 ? 5 : 10;
	return nice * p;
}

void plot_axis_linear(struct plot_axis *ax, double lo, double hi, int ndiv, int autorange)
{
	memset(ax, 0, sizeof *ax);
	if (ndiv < 1)
		ndiv = 1;
	if (ndiv > PLOT_MAXTICKS - 1)
		ndiv = PLOT_MAXTICKS - 1;
	if (hi < lo) {
		double t = lo; lo = hi; hi = t;
	}
	if (!(hi > lo)) {       /* a flat range: open it around the value */
		double w = fabs(lo) > 0 ? fabs(lo) * 0.1 : 1;
		lo -= w;
		hi += w;
	}
	/* a range narrower than the numbers resolve (a denormal width such
	 * as 0 to 5e-324 would make the tick step NaN): open it to
	 * AXIS_MIN_REL of its magnitude, and at least AXIS_MIN_ABS */
	double minw = fmax(fmax(fabs(lo), fabs(hi)) * AXIS_MIN_REL, AXIS_MIN_ABS);
	if (!(hi - lo >= minw)) {
		double mid = lo / 2 + hi / 2;
		lo = mid - minw / 2;
		hi = mid + minw / 2;
	}
	if (autorange) {
		double step = plot_nice_step(lo, hi, ndiv);
		double a = floor(lo / step + SNAP_TOL), b = ceil(hi / step - SNAP_TOL);
		while (b - a > PLOT_MAXTICKS - 1) {     /* cannot happen with sane ndiv */
			step *= 2;
			a = floor(lo / step + SNAP_TOL), b = ceil(hi / step - SNAP_TOL);
		}
		ax->lo = a * step;
		ax->hi = b * step;
		ax->nticks = (int)(b - a) + 1;
		for (int k = 0; k < ax->nticks; k++)
			ax->tick[k] = (a + k) * step;
	} else {
		/* the range as given, ticks at the round multiples inside it
		 * (a 1, 2, 5 step near (hi - lo) / ndiv; a finer one while
		 * fewer than two fall inside) */
		ax->lo = lo;
		ax->hi = hi;
		double step = plot_nice_step(lo, hi, ndiv), a, b;
		for (;;) {
			a = ceil(lo / step - SNAP_TOL), b = floor(hi / step + SNAP_TOL);
			if (b - a >= 1 || !(step > 0))
				break;
			step = plot_nice_step(lo, hi, (int)lround((hi - lo) / step * 2) + 1);
		}
		while (b - a > PLOT_MAXTICKS - 1) {
			step *= 2;
			a = ceil(lo / step - SNAP_TOL), b = floor(hi / step + SNAP_TOL);
		}
		ax->nticks = b >= a ? (int)(b - a) + 1 : 0;
		for (int k = 0; k < ax->nticks; k++)
			ax->tick[k] = (a + k) * step;
	}
	plot_axis_labels(ax);
}

int plot_axis_log(struct plot_axis *ax, double lo, double hi, int autorange)
{
	memset(ax, 0, sizeof *ax);
	if (hi < lo) {
		double t = lo; lo = hi; hi = t;
	}
	if (!(lo > 0) || !(hi > 0))
		return 0;
	double a = log10(lo), b = log10(hi);
	if (autorange || !(b > a)) {
		a = floor(a + SNAP_TOL);
		b = ceil(b - SNAP_TOL);
		if (b <= a)
			b = a + 1;
	}
	ax->log = 1;
	ax->lo = a;
	ax->hi = b;
	/* decades; if there are too many, every k-th */
	double first = ceil(a - SNAP_TOL), last = floor(b + SNAP_TOL);
	int every = 1;
	while ((last - first) / every + 1 > 12)
		every++;
	for (double e = first; e <= last + SNAP_TOL && ax->nticks < PLOT_MAXTICKS; e += every)
		ax->tick[ax->nticks++] = e;
	/* minor ticks at 2..9 times each decade, when decades are shown */
	if (every == 1)
		for (double e = floor(a) ; e < b; e++)
			for (int m = 2; m <= 9; m++) {
				double v = e + log10(m);
				if (v > a && v < b && ax->nminor < PLOT_MAXTICKS * 9)
					ax->minor[ax->nminor++] = v;
			}
	for (int k = 0; k < ax->nticks; k++) {
		double e = ax->tick[k];
		if (e >= -3 && e <= 4)
			snprintf(ax->label[k], sizeof ax->label[k], "%g", pow(10, e));
		else
			snprintf(ax->label[k], sizeof ax->label[k], "1e%d", (int)lround(e));
	}
	return 1;
}

/* Tries one printf format for every label: 1 if they all read back
 * within a thousandth of a step and no two are equal. */
static int try_labels(struct plot_axis *ax, int fixed, int prec, double step)
{
	for (int k = 0; k < ax->nticks; k++) {
		double v = ax->tick[k];
		if (fabs(v) < step * 1e-6)
			v = 0;      /* no "-1.38778e-17" for a zero tick */
		snprintf(ax->label[k], sizeof ax->label[k], fixed ? "%.*f" : "%.*g", prec, v);
		if (fabs(strtod(ax->label[k], NULL) - v) > step * 1e-3)
			return 0;
		if (k > 0 && strcmp(ax->label[k], ax->label[k - 1]) == 0)
			return 0;
	}
	return 1;
}

void plot_axis_labels(struct plot_axis *ax)
{
	double span = fabs(ax->hi - ax->lo);
	double step = ax->nticks > 1 ? fabs(ax->tick[1] - ax->tick[0]) : span;
	double big = fmax(fabs(ax->lo), fabs(ax->hi));
	int done = 0;
	/* plain decimals for ordinary magnitudes (0.001 .. 99999), else %g */
	if (big < 1e5 && step >= 1e-4)
		for (int prec = 0; prec <= 8 && !done; prec++)
			done = try_labels(ax, 1, prec, step);
	for (int prec = 1; prec <= 17 && !done; prec++)
		done = try_labels(ax, 0, prec, step);
	for (int k = 0; k < ax->nticks; k++)
		if (strcmp(ax->label[k], "-0") == 0 || strspn(ax->label[k], "-0.") == strlen(ax->label[k]))
			strcpy(ax->label[k], "0");
}

struct draw *plot_new_page(int landscape)
{
	struct draw *d = draw_new();
	if (landscape) {
		d->w = DRAW_PAGE_H;
		d->h = DRAW_PAGE_W;
	}
	return d;
}

/* Page layout: margins leave room for tick labels, axis labels and the
 * top label (points). */
#define MARGIN_L 90.0
#define MARGIN_R 40.0
#define MARGIN_B 80.0
#define MARGIN_T 80.0
#define FONT_TICK 10.0
#define FONT_LABEL 13.0
#define FONT_TOP 16.0
#define TICK_LEN 6.0

void plot_frame_place(struct plot_frame *f, const struct draw *d, int equal)
{
	double w = d->w - MARGIN_L - MARGIN_R, h = d->h - MARGIN_B - MARGIN_T;
	/* portrait: a square-ish plot in the upper part of the page, as the
	 * thesis' plots are laid out; landscape uses the whole page */
	if (d->h > d->w && h > w)
		h = w;
	double cx = MARGIN_L + (d->w - MARGIN_L - MARGIN_R) / 2;
	double cy = d->h - MARGIN_T - h / 2;
	if (equal) {
		double dx = f->xa->hi - f->xa->lo, dy = f->ya->hi - f->ya->lo;
		if (dx > 0 && dy > 0) {
			if (dy / dx > h / w)
				w = h * dx / dy;
			else
				h = w * dy / dx;
		}
	}
	f->x0 = cx - w / 2;
	f->x1 = cx + w / 2;
	f->y0 = cy - h / 2;
	f->y1 = cy + h / 2;
}

/* A tick on the frame's edge needs no grid line. */
static int on_edge(const struct plot_axis *ax, double v)
{
	double tol = SNAP_TOL * fabs(ax->hi - ax->lo);
	return fabs(v - ax->lo) <= tol || fabs(v - ax->hi) <= tol;
}

static double axis_pos(const struct plot_axis *ax, double v, double p0, double p1)
{
	return p0 + (v - ax->lo) / (ax->hi - ax->lo) * (p1 - p0);
}

int plot_frame_map(const struct plot_frame *f, double x, double y, double *px, double *py)
{
	if (f->xa->log) {
		if (!(x > 0))
			return 0;
		x = log10(x);
	}
	if (f->ya->log) {
		if (!(y > 0))
			return 0;
		y = log10(y);
	}
	*px = axis_pos(f->xa, x, f->x0, f->x1);
	*py = axis_pos(f->ya, y, f->y0, f->y1);
	return isfinite(*px) && isfinite(*py);
}

void plot_frame_draw(struct draw *d, const struct plot_frame *f, int grid,
		     const char *top, const char *xl, const char *yl)
{
	const struct plot_axis *xa = f->xa, *ya = f->ya;
	double box[8] = {f->x0, f->y0, f->x1, f->y0, f->x1, f->y1, f->x0, f->y1};
	draw_set_gray(d, 0);
	draw_set_line(d, 1, 1.0);
	draw_polygon(d, 4, box, DRAW_NOFILL, 1);
	for (int k = 0; k < xa->nticks; k++) {
		double x = axis_pos(xa, xa->tick[k], f->x0, f->x1);
		draw_set_line(d, 1, 0.8);
		draw_segment(d, x, f->y0, x, f->y0 + TICK_LEN);
		draw_segment(d, x, f->y1, x, f->y1 - TICK_LEN);
		if (grid && !on_edge(xa, xa->tick[k])) {
			draw_set_line(d, 3, 0.5);
			draw_segment(d, x, f->y0, x, f->y1);
		}
		draw_text(d, x, f->y0 - 6, FONT_TICK, 0, DRAW_CENTER, DRAW_TOP, xa->label[k]);
	}
	for (int k = 0; k < ya->nticks; k++) {
		double y = axis_pos(ya, ya->tick[k], f->y0, f->y1);
		draw_set_line(d, 1, 0.8);
		draw_segment(d, f->x0, y, f->x0 + TICK_LEN, y);
		draw_segment(d, f->x1, y, f->x1 - TICK_LEN, y);
		if (grid && !on_edge(ya, ya->tick[k])) {
			draw_set_line(d, 3, 0.5);
			draw_segment(d, f->x0, y, f->x1, y);
		}
		draw_text(d, f->x0 - 6, y, FONT_TICK, 0, DRAW_RIGHT, DRAW_MIDDLE, ya->label[k]);
	}
	draw_set_line(d, 1, 0.5);
	for (int k = 0; k < xa->nminor; k++) {
		double x = axis_pos(xa, xa->minor[k], f->x0, f->x1);
		draw_segment(d, x, f->y0, x, f->y0 + TICK_LEN / 2);
		draw_segment(d, x, f->y1, x, f->y1 - TICK_LEN / 2);
	}
	for (int k = 0; k < ya->nminor; k++) {
		double y = axis_pos(ya, ya->minor[k], f->y0, f->y1);
		draw_segment(d, f->x0, y, f->x0 + TICK_LEN / 2, y);
		draw_segment(d, f->x1, y, f->x1 - TICK_LEN / 2, y);
	}
	draw_set_line(d, 1, 0.8);
	if (xl && *xl)
		draw_text(d, (f->x0 + f->x1) / 2, f->y0 - 30, FONT_LABEL, 0,
			  DRAW_CENTER, DRAW_TOP, xl);
	if (yl && *yl)
		draw_text(d, f->x0 - 55, (f->y0 + f->y1) / 2, FONT_LABEL, 90,
			  DRAW_CENTER, DRAW_BOTTOM, yl);
	if (top && *top)
		draw_text(d, (f->x0 + f->x1) / 2, f->y1 + 24, FONT_TOP, 0,
			  DRAW_CENTER, DRAW_BOTTOM, top);
}
