/*
 * ray_output.c - the files etch writes, one set per print time, through the
 * library's plot writer (fmt_plot.h):
 *
 *   curves.plot     pdraw(1) 3D plot: every triangle as a closed 4-point
 *                   curve (thesis Appendix B, sample3D FILES);
 *   curves.plot.2D  the same triangles projected on the x-y plane;
 *   curves.cut      with -cut x|y v: where the plane x = v (y = v) cuts
 *                   the surface, as 2D curves of (y, z) ((x, z)), for
 *                   comparison with 2D simulations along cutlines
 *                   (thesis Figures 9.14, 9.16).
 *
 * A cut is traced through the mesh rather than triangle by triangle:
 * a node counts as on the positive side if its coordinate is >= v (so a
 * node exactly on the plane never makes a triangle cross it twice), each
 * segment with nodes on both sides gives one point, and each triangle
 * crossed joins its two points; the pieces are then chained into
 * polylines starting at the mesh border, then closed loops.
 */
#include "etch.h"

#include "fmt_plot.h"
#include "util.h"

#include <stdlib.h>
#include <string.h>

struct etch_out {
	struct plot_writer *w3, *w2;
	struct plot_file *cut;          /* all sets, written at the end */
	const char *cutpath;
	int axis;
	double value;
	double b3[6], b2[4], bc[4];
};

struct etch_out *out_open(const struct etch_opts *o, const struct rfield *f)
{
	struct etch_out *w = xcalloc(1, sizeof *w);
	for (int d = 0; d < 3; d++) {
		w->b3[2 * d] = f->lo[d];
		w->b3[2 * d + 1] = f->hi[d];
	}
	memcpy(w->b2, w->b3, sizeof w->b2);
	if (o->out3d)
		w->w3 = fmt_plot_open(o->out3d, 3);
	if (o->out2d)
		w->w2 = fmt_plot_open(o->out2d, 2);
	fmt_plot_labels(w->w3, fmt_labels_std(LABELS_SURFACE));
	fmt_plot_labels(w->w2, fmt_labels_std(LABELS_TOPVIEW));
	if (o->cut_axis >= 0 && o->outcut) {
		int other = 1 - o->cut_axis;
		w->cut = fmt_plot_new(2);
		w->cut->labels = *fmt_labels_std(o->cut_axis == 0 ? LABELS_CUT_X : LABELS_CUT_Y);
		w->cutpath = o->outcut;
		w->axis = o->cut_axis;
		w->value = o->cut_value;
		w->bc[0] = f->lo[other];
		w->bc[1] = f->hi[other];
		w->bc[2] = f->lo[2];
		w->bc[3] = f->hi[2];
	}
	return w;
}

/* Triangle i of the live ones as a closed 4-point curve, in 3D or
 * projected on z = 0 (called from several threads: reads only). */
struct tri_list {
	const struct mesh *m;
	const int *tri;                 /* the live triangles, in order */
};

static void tri_curve3(void *ctx, size_t i, double *p)
{
	const struct tri_list *l = ctx;
	const struct triangle *t = &l->m->tri[l->tri[i]];
	for (int j = 0; j < 4; j++)
		memcpy(p + 3 * j, l->m->node[t->n[j % 3]].p, 3 * sizeof *p);
}

static void tri_curve2(void *ctx, size_t i, double *p)
{
	const struct tri_list *l = ctx;
	const struct triangle *t = &l->m->tri[l->tri[i]];
	for (int j = 0; j < 4; j++) {
		const double *q = l->m->node[t->n[j % 3]].p;
		p[2 * j] = q[0];
		p[2 * j + 1] = q[1];
	}
}

void out_write(struct etch_out *w, const struct mesh *m)
{
	if (w->w3 || w->w2) {
		int *tri = xreallocarray(NULL, m->ntri + 1, sizeof *tri);
		size_t n = 0;
		for (size_t t = 0; t < m->ntri; t++)
			if (m->tri[t].alive)
				tri[n++] = (int)t;
		struct tri_list l = {m, tri};
		/* the text of large sets is formatted on several threads */
		if (w->w3) {
			fmt_plot_begin_set(w->w3, w->b3, (long)n);
			fmt_plot_curves(w->w3, n, 4, tri_curve3, &l);
		}
		if (w->w2) {
			fmt_plot_begin_set(w->w2, w->b2, (long)n);
			fmt_plot_curves(w->w2, n, 4, tri_curve2, &l);
		}
		free(tri);
	}
	if (w->cut)
		out_cut(m, w->axis, w->value, w->cut, w->bc);
}

void out_close(struct etch_out *w)
{
	if (w->w3)
		fmt_plot_close(w->w3);
	if (w->w2)
		fmt_plot_close(w->w2);
	if (w->cut) {
		fmt_plot_write(w->cutpath, w->cut);
		fmt_plot_free(w->cut);
	}
	free(w);
}

void out_cut(const struct mesh *m, int axis, double value, struct plot_file *pf,
	     const double *bounds)
{
	int other = 1 - axis;
	size_t ns = m->nseg;
	double *pt = xreallocarray(NULL, ns + 1, 2 * sizeof *pt);
	int *link = xreallocarray(NULL, ns + 1, 2 * sizeof *link);
	char *cross = xcalloc(ns + 1, 1), *used = xcalloc(ns + 1, 1);
	for (size_t s = 0; s < ns; s++) {
		link[2 * s] = link[2 * s + 1] = -1;
		if (!m->seg[s].alive)
			continue;
		const double *a = m->node[m->seg[s].n[0]].p, *b = m->node[m->seg[s].n[1]].p;
		int sa = a[axis] >= value, sb = b[axis] >= value;
		if (sa == sb)
			continue;
		double t = (value - a[axis]) / (b[axis] - a[axis]);
		cross[s] = 1;
		pt[2 * s] = a[other] + t * (b[other] - a[other]);
		pt[2 * s + 1] = a[2] + t * (b[2] - a[2]);
	}
	for (size_t t = 0; t < m->ntri; t++) {
		if (!m->tri[t].alive)
			continue;
		int c[2], k = 0;
		for (int j = 0; j < 3; j++)
			if (cross[m->tri[t].s[j]] && k < 2)
				c[k++] = m->tri[t].s[j];
		if (k != 2)
			continue;
		for (int j = 0; j < 2; j++) {
			int s = c[j], o = c[1 - j];
			if (link[2 * s] < 0)
				link[2 * s] = o;
			else
				link[2 * s + 1] = o;
		}
	}
	struct plot_set *set = fmt_plot_add_set(pf, bounds);
	double *poly = xreallocarray(NULL, ns + 2, 2 * sizeof *poly);
	/* open chains first (from a segment with one link), then loops */
	for (int pass = 0; pass < 2; pass++)
		for (size_t s0 = 0; s0 < ns; s0++) {
			if (!cross[s0] || used[s0])
				continue;
			if (pass == 0 && link[2 * s0 + 1] >= 0)
				continue;
			int n = 0, prev = -1, s = (int)s0;
			while (s >= 0 && !used[s]) {
				used[s] = 1;
				poly[2 * n] = pt[2 * s];
				poly[2 * n + 1] = pt[2 * s + 1];
				n++;
				int nx = link[2 * s] != prev ? link[2 * s] : link[2 * s + 1];
				prev = s;
				s = nx;
			}
			if (s == (int)s0 && n > 2) {        /* closed loop */
				poly[2 * n] = poly[0];
				poly[2 * n + 1] = poly[1];
				n++;
			}
			if (n >= 2)
				fmt_plot_add_curve(pf, set, n, poly);
		}
	free(poly);
	free(pt);
	free(link);
	free(cross);
	free(used);
}
