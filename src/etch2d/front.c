/*
 * front.c - the string of nodes the surface methods move (thesis 6.2,
 * 6.3, 7.2-7.5): the ray advance of a node with recursive vector checking
 * (7.4.2) and boundary flattening (7.5.2.2), clipping at the side walls
 * (7.5.2.1) and the substrate (a wall the front slides along, as the
 * fast-marching reference's), segment cutting with arc or linear interpolation (7.5.1.1)
 * and merging (7.5.1.2), and 2D delooping (7.5.3.3).  The first string
 * is front_start.c's.
 *
 * The string is open: it runs from the left wall (or the top, from a
 * seed) to the right wall (or the top), with the resist on the right of
 * the walk.  The ray step itself is the library's (raystep_rk4 over the
 * rfield of the 2D array, y held fixed), the same as etch's in 3D.
 */
#include "front.h"

#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Deepest recursion of the vector check (as etch's ray_advance.c). */
#define MAX_DEPTH 30
/* A direction shorter than this after flattening points into the wall. */
#define FLAT_TINY 1e-12
/* Ray directions closer to parallel than this (sin of the angle) are cut
 * by linear interpolation: the arc's centre is too far to be useful. */
#define ARC_PARALLEL 1e-6

void front_push(struct front *fr, double x, double z, double sx, double sz, unsigned flags)
{
	if ((long)fr->n >= FRONT_MAX_NODES)
		die("the string has grown past %ld nodes: use a larger -seg", FRONT_MAX_NODES);
	xgrow(&fr->v, &fr->cap, fr->n + 1, sizeof *fr->v);
	fr->v[fr->n++] = (struct fnode){{x, z}, {sx, sz}, flags};
}

void front_free(struct front *fr)
{
	free(fr->v);
	memset(fr, 0, sizeof *fr);
}

double front_seg(const struct e2 *e)
{
	return e->o.seg > 0 ? e->o.seg : (e->x1 - e->x0) / 50;
}

double front_dt(const struct e2 *e)
{
	return e->o.dt > 0 ? e->o.dt : 0.1;     /* the thesis' step, Table 7.2 */
}

unsigned front_walls(const struct e2 *e, const double p[2])
{
	unsigned f = 0;
	if (p[0] <= e->x0) f |= ON_LEFT;
	if (p[0] >= e->x1) f |= ON_RIGHT;
	if (e->o.seeded && p[1] >= e->z1) f |= ON_TOP;
	return f;
}

int front_flatten(const struct e2 *e, unsigned flags, double s[2])
{
	if (flags & ON_LEFT && s[0] > 0) s[0] = 0;
	if (flags & ON_RIGHT && s[0] < 0) s[0] = 0;
	/* the top is a wall from a seed: the string's ends slide along it */
	if (flags & ON_TOP && flags & END) s[1] = 0;
	double r = hypot(s[0], s[1]);
	if (r < FLAT_TINY)
		return 0;
	s[0] /= r;
	s[1] /= r;
	return 1;
}

void front_advance_ray(struct e2 *e, struct fnode *n, double dt, int depth)
{
	double s[2] = {n->s[0], n->s[1]};
	if (!front_flatten(e, n->flags, s))
		return;
	double p3[3] = {n->p[0], e->y, n->p[1]}, s3[3] = {s[0], 0, s[1]}, p2[3], s2[3];
	raystep_rk4(e->f, p3, s3, dt, p2, s2);
	double dx = s2[0] - s[0], dz = s2[2] - s[1];
	if (hypot(dx, dz) > e->o.rl && depth < MAX_DEPTH) {
		n->s[0] = s[0], n->s[1] = s[1];
		front_advance_ray(e, n, 0.5 * dt, depth + 1);
		front_advance_ray(e, n, 0.5 * dt, depth + 1);
		return;
	}
	double q[2] = {p2[0], p2[2]};
	/* a flattened node stays on its wall exactly */
	if (n->flags & ON_LEFT && s[0] == 0) q[0] = e->x0;
	if (n->flags & ON_RIGHT && s[0] == 0) q[0] = e->x1;
	if (n->flags & ON_TOP && s[1] == 0) q[1] = e->z1;
	if (e->o.seeded && q[1] > e->z1)
		q[1] = e->z1;
	n->p[0] = q[0], n->p[1] = q[1];
	double r = hypot(s2[0], s2[2]);
	if (r > 0)
		n->s[0] = s2[0] / r, n->s[1] = s2[2] / r;
	n->flags = (n->flags & END) | front_walls(e, n->p);
}

void front_ends(struct e2 *e, struct front *fr)
{
	for (size_t i = 0; i < fr->n; i++)
		fr->v[i].flags &= ~(unsigned)END;
	if (fr->n) {
		fr->v[0].flags |= END;
		fr->v[fr->n - 1].flags |= END;
	}
	(void)e;
}

static int outside(const struct e2 *e, const double p[2])
{
	return p[0] < e->x0 || p[0] > e->x1;
}

/* Moves node a (outside) to where segment a-b (b inside) crosses the
 * side wall. */
static void to_wall(const struct e2 *e, struct fnode *a, const struct fnode *b)
{
	double w = a->p[0] < e->x0 ? e->x0 : e->x1;
	double u = (w - b->p[0]) / (a->p[0] - b->p[0]);
	a->p[0] = w;
	a->p[1] = b->p[1] + u * (a->p[1] - b->p[1]);
	a->flags = front_walls(e, a->p);
}

void front_clip(struct e2 *e, struct front *fr)
{
	/* ends that left through a side wall are cut back to it */
	size_t lo = 0, hi = fr->n;
	while (hi - lo >= 2 && outside(e, fr->v[lo].p) && outside(e, fr->v[lo + 1].p))
		lo++;
	if (hi - lo >= 2 && outside(e, fr->v[lo].p))
		to_wall(e, &fr->v[lo], &fr->v[lo + 1]);
	while (hi - lo >= 2 && outside(e, fr->v[hi - 1].p) && outside(e, fr->v[hi - 2].p))
		hi--;
	if (hi - lo >= 2 && outside(e, fr->v[hi - 1].p))
		to_wall(e, &fr->v[hi - 1], &fr->v[hi - 2]);
	if (lo > 0)
		memmove(fr->v, fr->v + lo, (hi - lo) * sizeof *fr->v);
	fr->n = hi - lo;
	/* a node out of the box in the middle of the string is put back on
	 * the wall it crossed */
	for (size_t i = 0; i < fr->n; i++) {
		struct fnode *n = &fr->v[i];
		if (n->p[0] < e->x0) n->p[0] = e->x0;
		if (n->p[0] > e->x1) n->p[0] = e->x1;
		if (e->o.seeded && n->p[1] > e->z1) n->p[1] = e->z1;
		n->flags = front_walls(e, n->p);
	}
}

/* The node a fraction u of the way from a to b: on the arc the two rays
 * define (their backward extensions meet at the arc's centre), or on the
 * chord. */
static struct fnode interp(const struct e2 *e, const struct fnode *a, const struct fnode *b,
			   double u, int arc)
{
	struct fnode n = {{0, 0}, {0, 0}, 0};
	double cr = a->s[0] * b->s[1] - a->s[1] * b->s[0];
	int done = 0;
	if (arc && fabs(cr) > ARC_PARALLEL) {
		/* a - la sa = b - mu sb */
		double d0 = a->p[0] - b->p[0], d1 = a->p[1] - b->p[1];
		/* la sa - mu sb = d: solve by Cramer */
		double det = -a->s[0] * b->s[1] + a->s[1] * b->s[0];
		double la = (-d0 * b->s[1] + d1 * b->s[0]) / det;
		double mu = (a->s[0] * d1 - a->s[1] * d0) / det;
		if (la > 0 && mu > 0) {
			double c[2] = {a->p[0] - la * a->s[0], a->p[1] - la * a->s[1]};
			double ta = atan2(a->s[1], a->s[0]), tb = atan2(b->s[1], b->s[0]);
			double dth = tb - ta;
			if (dth > M_PI) dth -= 2 * M_PI;
			if (dth < -M_PI) dth += 2 * M_PI;
			double th = ta + u * dth, r = la + u * (mu - la);
			n.s[0] = cos(th), n.s[1] = sin(th);
			n.p[0] = c[0] + r * n.s[0];
			n.p[1] = c[1] + r * n.s[1];
			done = 1;
		}
	}
	if (!done) {
		n.p[0] = a->p[0] + u * (b->p[0] - a->p[0]);
		n.p[1] = a->p[1] + u * (b->p[1] - a->p[1]);
		double s0 = a->s[0] + u * (b->s[0] - a->s[0]), s1 = a->s[1] + u * (b->s[1] - a->s[1]);
		double r = hypot(s0, s1);
		if (r > 0)
			n.s[0] = s0 / r, n.s[1] = s1 / r;
		else
			n.s[0] = a->s[0], n.s[1] = a->s[1];
	}
	/* a new node between two on the substrate stays on it */
	if (e->o.seeded && n.p[1] > e->z1)
		n.p[1] = e->z1;
	n.flags |= front_walls(e, n.p);
	return n;
}

void front_remesh(struct e2 *e, struct front *fr, double smax, double smin, int arc)
{
	if (fr->n < 2)
		return;
	/* cutting: a segment longer than smax gets m - 1 new nodes */
	struct front out = {0};
	for (size_t i = 0; i < fr->n; i++) {
		if (i > 0) {
			const struct fnode *a = &fr->v[i - 1], *b = &fr->v[i];
			double len = hypot(b->p[0] - a->p[0], b->p[1] - a->p[1]);
			if (len > smax) {
				long m = (long)ceil(len / smax);
				for (long q = 1; q < m; q++) {
					struct fnode n = interp(e, a, b, (double)q / (double)m, arc);
					front_push(&out, n.p[0], n.p[1], n.s[0], n.s[1], n.flags);
				}
			}
		}
		const struct fnode *v = &fr->v[i];
		front_push(&out, v->p[0], v->p[1], v->s[0], v->s[1], v->flags);
	}
	/* merging: a segment shorter than smin loses a node (never an end);
	 * with arc (ray-string) two interior nodes become their midpoint */
	size_t k = 1;
	for (size_t i = 1; i < out.n; i++) {
		struct fnode *a = &out.v[k - 1], *b = &out.v[i];
		double len = hypot(b->p[0] - a->p[0], b->p[1] - a->p[1]);
		int a_end = k - 1 == 0, b_end = i == out.n - 1;
		if (len > 0 && len < smin && !(a_end && b_end)) {
			if (b_end) {
				*a = *b;        /* keep the end, drop a */
			} else if (arc && !a_end) {
				struct fnode mid = interp(e, a, b, 0.5, 1);
				*a = mid;
			}
			continue;               /* b dropped */
		}
		out.v[k++] = *b;
	}
	out.n = k;
	front_free(fr);
	*fr = out;
}

long front_deloop(struct e2 *e, struct front *fr)
{
	/* The string is open, its ends on walls: where it crosses itself,
	 * the stretch between the two crossing segments is the loop (a lagging
	 * corner, or a blob cut free, Figure 7.16) and goes; the crossing
	 * becomes a node.  The widest loop at each segment goes first, so
	 * nested loops go with it. */
	long loops = 0;
	for (size_t i = 0; i + 3 < fr->n; i++) {
		const double *p1 = fr->v[i].p, *p2 = fr->v[i + 1].p;
		double bx0 = fmin(p1[0], p2[0]), bx1 = fmax(p1[0], p2[0]);
		double bz0 = fmin(p1[1], p2[1]), bz1 = fmax(p1[1], p2[1]);
		for (size_t j = fr->n - 2; j >= i + 2; j--) {
			const double *q1 = fr->v[j].p, *q2 = fr->v[j + 1].p;
			if (fmax(q1[0], q2[0]) < bx0 || fmin(q1[0], q2[0]) > bx1 ||
			    fmax(q1[1], q2[1]) < bz0 || fmin(q1[1], q2[1]) > bz1)
				continue;
			double u;
			if (!e2_crossing(p1, p2, q1, q2, &u))
				continue;
			struct fnode x = fr->v[i];
			x.p[0] = p1[0] + u * (p2[0] - p1[0]);
			x.p[1] = p1[1] + u * (p2[1] - p1[1]);
			double s0 = fr->v[i].s[0] + fr->v[j + 1].s[0], s1 = fr->v[i].s[1] + fr->v[j + 1].s[1];
			double r = hypot(s0, s1);
			if (r > 0)
				x.s[0] = s0 / r, x.s[1] = s1 / r;
			x.flags = front_walls(e, x.p);
			fr->v[i + 1] = x;
			memmove(fr->v + i + 2, fr->v + j + 1, (fr->n - j - 1) * sizeof *fr->v);
			fr->n -= j - i - 1;
			loops++;
			break;
		}
	}
	return loops;
}

void front_emit(struct e2 *e, const struct front *fr)
{
	/* The profile is the string inside the box: a run of nodes below
	 * the substrate is where the substrate is cleared, drawn along it
	 * from where the string goes under to where it comes back; nodes out
	 * through a side wall (the ray method's) break the curve. */
	double *p = xreallocarray(NULL, 2 * fr->n + 2, 2 * sizeof *p);
	int np = 0;
	for (size_t i = 0; i <= fr->n; i++) {
		const struct fnode *n = i < fr->n ? &fr->v[i] : NULL;
		if (!n || n->p[0] < e->x0 || n->p[0] > e->x1) {
			e2_curve(e, np, p);
			np = 0;
			continue;
		}
		const struct fnode *m = i > 0 ? &fr->v[i - 1] : NULL;
		int below = n->p[1] < e->z0, mbelow = m && m->p[1] < e->z0;
		if (m && below != mbelow && m->p[0] >= e->x0 && m->p[0] <= e->x1) {
			double u = (e->z0 - m->p[1]) / (n->p[1] - m->p[1]);
			p[2 * np] = m->p[0] + u * (n->p[0] - m->p[0]);
			p[2 * np + 1] = e->z0;
			np++;
		}
		if (!below) {
			p[2 * np] = n->p[0];
			p[2 * np + 1] = n->p[1];
			np++;
		} else if (!m || m->p[0] < e->x0 || m->p[0] > e->x1) {
			/* the curve starts under the substrate */
			p[2 * np] = n->p[0];
			p[2 * np + 1] = e->z0;
			np++;
		} else if (i + 1 == fr->n) {
			p[2 * np] = n->p[0];
			p[2 * np + 1] = e->z0;
			np++;
		}
	}
	free(p);
}
