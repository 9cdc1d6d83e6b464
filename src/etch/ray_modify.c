/*
 * ray_modify.c - mesh modification after every step (thesis 8.4.1): segments
 * longer than S_max are cut, segments shorter than S_min merged, by the
 * triangle-based procedure of 8.4.1.3 (each triangle in list order: cut
 * its longest segment if too long, else merge its shortest if too short),
 * which keeps the cut triangles from turning obtuse.
 *
 * New nodes go on the arc defined by the two nodes' rays (Figure 7.6b,
 * 8.3): the surface between nodes A and B is taken to be the circle
 * through them whose normals there are the rays, so its curvature along
 * the chord d = B - A is k = (sB - sA) . d / |d|^2 (exact for a sphere
 * and, along any chord, for a cylinder's normal section), and the new
 * node lies at the chord's middle raised by the sagitta
 * h^2 k / (1 + sqrt(1 - h^2 k^2)) (h = |d| / 2) along the mean ray.
 * On a sphere grown from a seed this puts the node exactly on the sphere;
 * -linear leaves it on the chord, which falls short (Figure 8.3).
 */
#include "etch.h"

#include <math.h>

/* Cut and merge operations allowed per call, per triangle present at the
 * start: cutting halves a segment each time, so a pass needs a few per
 * triangle; the cap only guards against cut/merge cycles when S_min is
 * close to S_max / 2 (the thesis' footnote to 8.4.1.3 avoids the same). */
#define OPS_PER_TRI 8

void interp_node(const struct node *a, const struct node *b, int linear,
		 double p[3], double r[3])
{
	double d[3], ds[3], dd = 0, k = 0;
	for (int i = 0; i < 3; i++) {
		p[i] = 0.5 * (a->p[i] + b->p[i]);
		r[i] = a->s[i] + b->s[i];
		d[i] = b->p[i] - a->p[i];
		ds[i] = b->s[i] - a->s[i];
		dd += d[i] * d[i];
	}
	double rl = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
	if (rl < 1e-12) {
		/* opposite rays: no mean direction; keep a's */
		for (int i = 0; i < 3; i++)
			r[i] = a->s[i];
		return;
	}
	for (int i = 0; i < 3; i++)
		r[i] /= rl;
	if (linear || dd <= 0)
		return;
	for (int i = 0; i < 3; i++)
		k += ds[i] * d[i];
	k /= dd;
	double h2k2 = 0.25 * dd * k * k;
	double sag;
	if (h2k2 >= 1)
		sag = k > 0 ? 0.5 * sqrt(dd) : -0.5 * sqrt(dd);
	else
		sag = 0.25 * dd * k / (1 + sqrt(1 - h2k2));
	for (int i = 0; i < 3; i++)
		p[i] += sag * r[i];
}

/* Cuts segment s at its middle (arc or linear). */
static void cut(struct mesh *m, const struct rfield *f, int s, int linear)
{
	const struct node *a = &m->node[m->seg[s].n[0]], *b = &m->node[m->seg[s].n[1]];
	double p[3], r[3];
	interp_node(a, b, linear, p, r);
	/* a node between two nodes on the same face is on that face */
	unsigned fl = a->flags & b->flags & (ON_WALLS | ON_SUB);
	if (fl & ON_X0) p[0] = f->lo[0];
	if (fl & ON_X1) p[0] = f->hi[0];
	if (fl & ON_Y0) p[1] = f->lo[1];
	if (fl & ON_Y1) p[1] = f->hi[1];
	if (fl & ON_TOP) p[2] = f->hi[2];
	if (fl & ON_SUB) p[2] = f->lo[2];
	mesh_split(m, s, p, r, fl);
}

/* Whether merging segment s by deleting node del would join keep to a
 * neighbour of del farther than smax: the next pass would cut that new
 * segment again, and on sliver triangles (rays converging in a
 * standing-wave minimum) cut and merge then chase each other every step
 * (the unbaked contact: 1.2 million of each in 540 steps). */
static int overstretches(const struct mesh *m, int s, int del, double smax)
{
	const struct segment *sg = &m->seg[s];
	int keep = sg->n[0] == del ? sg->n[1] : sg->n[0];
	const double *pk = m->node[keep].p;
	const struct node *nd = &m->node[del];
	for (int i = 0; i < nd->nseg; i++) {
		const struct segment *x = &m->seg[nd->seg[i]];
		int y = x->n[0] == del ? x->n[1] : x->n[0];
		if (y == keep)
			continue;
		const double *py = m->node[y].p;
		double d2 = 0;
		for (int k = 0; k < 3; k++)
			d2 += (py[k] - pk[k]) * (py[k] - pk[k]);
		if (d2 > smax * smax)
			return 1;
	}
	return 0;
}

/* The largest square whose sqrt is at most s, and the smallest whose sqrt
 * is at least s (sqrt is correctly rounded and monotone): a squared length
 * compared with these decides as its sqrt would against s. */
static double square_at_most(double s)
{
	double x = s * s;
	while (x > 0 && sqrt(x) > s)
		x = nextafter(x, 0);
	while (sqrt(nextafter(x, INFINITY)) <= s)
		x = nextafter(x, INFINITY);
	return x;
}

static double square_at_least(double s)
{
	double x = s * s;
	while (sqrt(x) < s)
		x = nextafter(x, INFINITY);
	while (x > 0 && sqrt(nextafter(x, 0)) >= s)
		x = nextafter(x, 0);
	return x;
}

void modify_mesh(struct mesh *m, const struct rfield *f, double seg,
		 const struct etch_opts *o, struct etch_stats *st)
{
	double smax = o->smax * seg, smin = o->smin * seg;
	/* most triangles need neither a cut nor a merge: their squared
	 * lengths say so without the three square roots */
	int quick = isfinite(smax) && isfinite(smin) && smax > 0 && smin > 0 && smin < smax;
	double qmax = quick ? square_at_most(smax) : 0, qmin = quick ? square_at_least(smin) : 0;
	long limit = (long)(OPS_PER_TRI * m->live_tri) + 64, ops = 0;
	for (size_t t = 0; t < m->ntri && ops < limit; t++) {
		const struct triangle *tr = &m->tri[t];
		if (!tr->alive)
			continue;
		double len[3];
		int lo = 0, hi = 0;
		/* segment s[j] joins n[j] and n[j+1]: its length from the
		 * triangle's own nodes, without the segment array's indirection
		 * (the same value as mesh_seg_length: only signs differ) */
		const double *q[3] = {m->node[tr->n[0]].p, m->node[tr->n[1]].p, m->node[tr->n[2]].p};
		double sq[3];
		int inside = quick;
		for (int j = 0; j < 3; j++) {
			const double *a = q[j], *b = q[j == 2 ? 0 : j + 1];
			double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
			sq[j] = dx * dx + dy * dy + dz * dz;
			inside &= sq[j] <= qmax && sq[j] >= qmin;      /* false for NaN */
		}
		if (inside)
			continue;
		for (int j = 0; j < 3; j++) {
			len[j] = sqrt(sq[j]);
			if (len[j] > len[hi]) hi = j;
			if (len[j] < len[lo]) lo = j;
		}
		if (len[hi] > smax && st->max_live_tri > 0 &&
		    (long)m->live_tri >= st->max_live_tri) {
			st->capped++;   /* the mesh is at its bound (etch.h) */
		} else if (len[hi] > smax) {
			cut(m, f, tr->s[hi], o->linear);
			st->cuts++;
			ops++;
			t--;            /* look at the remaining half again */
			continue;
		}
		if (len[lo] >= smin)
			continue;
		int s = tr->s[lo];
		int a = m->seg[s].n[0], b = m->seg[s].n[1];
		/* thesis 8.4.1.2: delete the node with the most segments (on a
		 * tie the later one), never one on the boundary */
		int na = m->node[a].nseg, nb = m->node[b].nseg;
		int del = na > nb ? a : nb > na ? b : (a > b ? a : b);
		int other = del == a ? b : a;
		if (mesh_can_merge(m, s, del) && !overstretches(m, s, del, smax)) {
			mesh_merge(m, s, del);
		} else if (mesh_can_merge(m, s, other) && !overstretches(m, s, other, smax)) {
			mesh_merge(m, s, other);
		} else {
			st->refused++;
			continue;
		}
		st->merges++;
		ops++;
	}
}
