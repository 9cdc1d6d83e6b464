/*
 * plot_bsp.c - the hidden-line painter of pdraw -h (plot_bsp.h).
 *
 * A plain depth sort fails for polygons that overlap in depth, so the
 * order comes from a BSP partition (Fuchs, Kedem and Naylor 1980): a
 * polygon's plane splits the others into the pieces behind it and in
 * front of it, recursively, and the pieces are painted far side first.
 * A split piece keeps, per edge, whether it is part of an original edge,
 * so the caller strokes only those and no split seam shows.  Open curves
 * take part as segments that are split but never split others.  The
 * partition runs on an explicit stack, so a deep partition cannot
 * overflow the C stack.
 */
#include "plot_bsp.h"
#include "util.h"
#include "vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Plane-side tolerance, relative to the scene size (unit box): points this
 * close to a plane are on it. */
#define PLANE_EPS 1e-9

/* One allocation a fragment (a triangle is 144 bytes, not three blocks):
 * the painter holds every polygon of a page at once. */
struct plot_frag *plot_frag_new(int n, int curve, int seg)
{
	size_t np = (size_t)n * 3 * sizeof(double);
	struct plot_frag *f = xmalloc(sizeof *f + np + (size_t)n);
	f->n = n;
	f->curve = curve;
	f->seg = (unsigned char)seg;
	f->hasplane = 0;
	f->gray = 1.0;
	memset(f->pl, 0, sizeof f->pl);
	f->orig = (unsigned char *)f->p + np;
	memset(f->orig, 0, (size_t)n);
	return f;
}

void plot_frag_free(struct plot_frag *f)
{
	free(f);
}

/* Newell's normal: robust for any planar polygon. */
void plot_frag_plane(struct plot_frag *f)
{
	double n[3] = {0, 0, 0}, c[3] = {0, 0, 0};
	for (int i = 0; i < f->n; i++) {
		const double *a = f->p + 3 * i, *b = f->p + 3 * ((i + 1) % f->n);
		n[0] += (a[1] - b[1]) * (a[2] + b[2]);
		n[1] += (a[2] - b[2]) * (a[0] + b[0]);
		n[2] += (a[0] - b[0]) * (a[1] + b[1]);
		for (int k = 0; k < 3; k++)
			c[k] += a[k] / f->n;
	}
	double len = sqrt(vec3_dot(n, n));
	f->hasplane = !f->seg && len > 1e-12;
	if (f->hasplane) {
		for (int k = 0; k < 3; k++)
			f->pl[k] = n[k] / len;
		f->pl[3] = -vec3_dot(f->pl, c);
	}
}

static int side(const double *pl, const double *p)
{
	double s = vec3_dot(pl, p) + pl[3];
	return s > PLANE_EPS ? 1 : s < -PLANE_EPS ? -1 : 0;
}

/* The part of f on side sg (+1 or -1) of pl, or NULL if it is empty. */
static struct plot_frag *clip_part(const struct plot_frag *f, const double *pl, const int *sd, int sg)
{
	int cap = f->n * 2 + 2, m = 0;
	struct plot_frag *o = plot_frag_new(cap, f->curve, f->seg);
	o->gray = f->gray;
	int nedge = f->seg ? 1 : f->n;
	for (int i = 0; i < nedge; i++) {
		int j = (i + 1) % f->n;
		const double *a = f->p + 3 * i, *b = f->p + 3 * j;
		int ina = sg * sd[i] >= 0, inb = sg * sd[j] >= 0;
		int opposite = sd[i] * sd[j] < 0;
		if (ina) {
			memcpy(o->p + 3 * m, a, 3 * sizeof *a);
			o->orig[m++] = (inb || opposite) ? f->orig[i] : 0;
		}
		if (opposite) {
			double sa = vec3_dot(pl, a) + pl[3], sb = vec3_dot(pl, b) + pl[3];
			double t = sa / (sa - sb);
			for (int k = 0; k < 3; k++)
				o->p[3 * m + k] = a[k] + t * (b[k] - a[k]);
			o->orig[m++] = inb ? f->orig[i] : 0;
		}
	}
	if (f->seg && sg * sd[1] >= 0) {    /* a segment's far end */
		memcpy(o->p + 3 * m, f->p + 3, 3 * sizeof *f->p);
		o->orig[m++] = 0;
	}
	o->n = m;
	if (m < (f->seg ? 2 : 3)) {
		plot_frag_free(o);
		return NULL;
	}
	o->hasplane = f->hasplane;
	memcpy(o->pl, f->pl, sizeof o->pl);
	return o;
}

static void list_reserve(struct plot_frag_list *l, size_t n)
{
	if (n) {
		l->f = xreallocarray(NULL, n, sizeof *l->f);
		l->cap = n;
	}
}

void plot_frag_list_add(struct plot_frag_list *l, struct plot_frag *f)
{
	xgrow(&l->f, &l->cap, l->n + 1, sizeof *l->f);
	l->f[l->n++] = f;
}

/* Work of the painter: a list to partition, or fragments to paint. */
struct work { int paint; struct plot_frag_list l; };

static int count_splits(const struct plot_frag *s, struct plot_frag *const *f, size_t n)
{
	int splits = 0;
	size_t step = n > 64 ? n / 64 : 1;
	for (size_t i = 0; i < n; i += step) {
		int pos = 0, neg = 0;
		for (int k = 0; k < f[i]->n; k++) {
			int v = side(s->pl, f[i]->p + 3 * k);
			pos |= v > 0, neg |= v < 0;
		}
		splits += pos && neg;
	}
	return splits;
}

/* The splitter: of a few candidates spread over the list, the one that
 * splits the fewest of a sample (fewer pieces, same picture).  A
 * candidate met twice (short lists) is counted once, a lone candidate not
 * at all, and none can beat one that splits nothing: the choice is the
 * same, most nodes of the partition being short lists. */
static long choose(struct plot_frag *const *f, size_t n)
{
	size_t cand[5];
	int nc = 0;
	for (int c = 0; c < 5; c++) {
		size_t i = n * (size_t)c / 5;
		while (i < n && !f[i]->hasplane)
			i++;
		if (i >= n)
			continue;
		if (nc && cand[nc - 1] == i)
			continue;       /* candidates only grow: a repeat is the last */
		cand[nc++] = i;
	}
	if (nc <= 1)
		return nc ? (long)cand[0] : -1;
	long best = -1;
	int bests = 0;
	for (int c = 0; c < nc && !(best >= 0 && bests == 0); c++) {
		int s = count_splits(f[cand[c]], f, n);
		if (best < 0 || s < bests)
			best = (long)cand[c], bests = s;
	}
	return best;
}

void plot_bsp_paint(struct plot_frag_list all, plot_bsp_paint_fn paint, void *ctx)
{
	struct work *stack = NULL;
	size_t ns = 0, cap = 0;
	unsigned char *cls = NULL;      /* a list's sides of the splitter */
	size_t clscap = 0;
	xgrow(&stack, &cap, 1, sizeof *stack);
	stack[ns++] = (struct work){0, all};
	while (ns > 0) {
		struct work w = stack[--ns];
		long si = w.paint ? -1 : choose(w.l.f, w.l.n);
		if (si < 0) {
			/* nothing left to split by: paint (segments only, or the
			 * polygons of one plane in file order) */
			for (size_t i = 0; i < w.l.n; i++) {
				paint(ctx, w.l.f[i]);
				plot_frag_free(w.l.f[i]);
			}
			free(w.l.f);
			continue;
		}
		const struct plot_frag *s = w.l.f[si];
		struct plot_frag_list pos = {0}, neg = {0}, co = {0};
		int *sd = NULL;
		size_t sdcap = 0;
		/* sides first, so that the lists are allocated once at their
		 * size (0 on the plane, 1 in front, 2 behind, 3 split) */
		xgrow(&cls, &clscap, w.l.n, 1);
		size_t count[4] = {0, 0, 0, 0};
		for (size_t i = 0; i < w.l.n; i++) {
			const struct plot_frag *f = w.l.f[i];
			int p = 0, q = 0;
			if ((long)i != si)
				for (int k = 0; k < f->n; k++) {
					int v = side(s->pl, f->p + 3 * k);
					p |= v > 0, q |= v < 0;
				}
			cls[i] = (unsigned char)(p | q << 1);
			count[cls[i]]++;
		}
		list_reserve(&co, count[0]);
		list_reserve(&pos, count[1] + count[3]);
		list_reserve(&neg, count[2] + count[3]);
		for (size_t i = 0; i < w.l.n; i++) {
			struct plot_frag *f = w.l.f[i];
			if (cls[i] == 0)
				plot_frag_list_add(&co, f);
			else if (cls[i] == 1)
				plot_frag_list_add(&pos, f);
			else if (cls[i] == 2)
				plot_frag_list_add(&neg, f);
			else {
				xgrow(&sd, &sdcap, (size_t)f->n, sizeof *sd);
				for (int k = 0; k < f->n; k++)
					sd[k] = side(s->pl, f->p + 3 * k);
				struct plot_frag *a = clip_part(f, s->pl, sd, 1);
				struct plot_frag *b = clip_part(f, s->pl, sd, -1);
				if (a) plot_frag_list_add(&pos, a);
				if (b) plot_frag_list_add(&neg, b);
				plot_frag_free(f);
			}
		}
		free(sd);
		free(w.l.f);
		/* the eye is on the + side when the normal points to it (D up) */
		int eye_pos = s->pl[2] >= 0;
		struct plot_frag_list nearl = eye_pos ? pos : neg, farl = eye_pos ? neg : pos;
		xgrow(&stack, &cap, ns + 3, sizeof *stack);
		stack[ns++] = (struct work){0, nearl};
		stack[ns++] = (struct work){1, co};
		stack[ns++] = (struct work){0, farl};
	}
	free(stack);
	free(cls);
}
