/*
 * plot_window.c - pdraw -window: 3D plot sets cut to an x-y window, so a
 * large mask's developed surface can be drawn for a part of it.  The
 * polygons are clipped side by side (Sutherland-Hodgman), the new points
 * lying exactly on the window's sides, where -walls looks for the border
 * of the surface.
 */
#include "plot_window.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Sutherland-Hodgman: the polygon p (n points, not repeated at the end)
 * cut to the side of coordinate k that is >= v (dir 1) or <= v (dir -1),
 * into q (room for 2n points); a new point gets exactly v as its k-th
 * coordinate, so -walls finds it on the window's side.  Returns its
 * point count. */
static int clip_side(const double *p, int n, int k, double v, int dir, double *q)
{
	int m = 0;
	for (int i = 0; i < n; i++) {
		const double *a = p + 3 * i, *b = p + 3 * ((i + 1) % n);
		int ina = dir * (a[k] - v) >= 0, inb = dir * (b[k] - v) >= 0;
		if (ina)
			memcpy(q + 3 * m++, a, 3 * sizeof *q);
		if (ina != inb) {
			double t = (v - a[k]) / (b[k] - a[k]);
			for (int j = 0; j < 3; j++)
				q[3 * m + j] = a[j] + t * (b[j] - a[j]);
			q[3 * m + k] = v;
			m++;
		}
	}
	return m;
}

static int inside_win(const double *p, const double *w)
{
	return p[0] >= w[0] && p[0] <= w[1] && p[1] >= w[2] && p[1] <= w[3];
}

struct plot_file *plot_window_sets(const struct plot_set *const *sets, int nsets,
				   const double *w)
{
	struct plot_file *pf = fmt_plot_new(3);
	for (int si = 0; si < nsets; si++) {
		const struct plot_set *st = sets[si];
		double b[6];
		memcpy(b, st->bounds, sizeof b);
		for (int k = 0; k < 2; k++)
			if (b[2 * k + 1] > b[2 * k]) {
				b[2 * k] = fmax(b[2 * k], w[2 * k]);
				b[2 * k + 1] = fmin(b[2 * k + 1], w[2 * k + 1]);
			} else {
				b[2 * k] = w[2 * k], b[2 * k + 1] = w[2 * k + 1];
			}
		struct plot_set *out = fmt_plot_add_set(pf, b);
		for (int c = 0; c < st->ncurves; c++) {
			const struct plot_curve *cv = &st->curves[c];
			if (cv->npts >= 4 && memcmp(cv->p, cv->p + 3 * (cv->npts - 1),
						    3 * sizeof *cv->p) == 0) {
				int n = cv->npts - 1;
				double *p = xreallocarray(NULL, (size_t)n * 16 + 3, 3 * sizeof *p);
				double *q = xreallocarray(NULL, (size_t)n * 16 + 3, 3 * sizeof *q);
				memcpy(p, cv->p, (size_t)n * 3 * sizeof *p);
				for (int e = 0; e < 4 && n > 0; e++) {
					n = clip_side(p, n, e / 2, b[e], e % 2 ? -1 : 1, q);
					double *t = p; p = q; q = t;
				}
				if (n >= 3) {
					memcpy(p + 3 * n, p, 3 * sizeof *p);
					fmt_plot_add_curve(pf, out, n + 1, p);
				}
				free(p);
				free(q);
				continue;
			}
			for (int i = 0; i < cv->npts;) {
				int j = i;
				while (j < cv->npts && inside_win(cv->p + 3 * j, b))
					j++;
				if (j - i >= 2)
					fmt_plot_add_curve(pf, out, j - i, cv->p + 3 * i);
				i = j > i ? j : i + 1;
			}
		}
	}
	return pf;
}

