/*
 * ray_advance.c - the ray advance (thesis 8.3 step [I]): every node moves
 * along its ray, which turns as the ray equation says, with recursive
 * vector checking (7.4.2), boundary flattening (7.5.2.2) and the
 * substrate stopping the development (8.4.2).
 *
 * The ray equation d/ds (s / R) = grad(1 / R) [6.3], written in time
 * (ds = R dt), is the system
 *
 *     dP/dt = R s,     ds/dt = -(grad R - (s . grad R) s),
 *
 * of which the thesis' step [6.7] + [6.6]/[A.33] (move P by R(P1) dt
 * along s1; s2 = s1 + s1 (R2/R1 - 1) - 0.5 (R1 + R2)/R1 grad R dt) is
 * the first-order (Euler) discretisation: expanding R2 = R1 + R1 dt
 * s1 . grad R gives s2 - s1 = -(grad R - (s1 . grad R) s1) dt + O(dt^2).
 * By default the same system is integrated by the classical fourth-order
 * Runge-Kutta rule, an improvement on the thesis: the depth reached converges
 * as dt^4 instead of dt (tests/etch/040-zonly.sh measures both); -euler
 * selects the thesis' step.  Either way a step is halved recursively while
 * the ray turns by more than the recursive length, |s2 - s1| > l (7.4.2).
 */
#include "etch.h"
#include "par.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Deepest recursion of the vector check: 2^-30 of a step.  The ray turns
 * at most |grad R| per second, so the check stops long before this; the
 * cap only bounds the work on a rate array with huge gradients. */
#define MAX_DEPTH 30
/* Rays shorter than this after flattening point straight into the wall:
 * the node has no direction to slide in and waits for the next step. */
#define FLAT_TINY 1e-12
/* What one advance needs; st is the worker's own counters (summed after
 * the parallel loop, so the totals do not depend on the split). */
struct ctx {
	const struct rfield *f;
	const struct etch_opts *o;
	struct etch_stats *st;
};

/* Nodes per thread at least: a node's advance is a few microseconds, a
 * par_for some. */
#define PAR_MIN_NODES 256
/* A node on a side wall stepping out of the box by less than this
 * fraction of the box's size stays on the wall (advance_range): far
 * above the rounding of a ray along the wall (1e-7 of the box a step on
 * examples/defect), far below a step of a ray that leaves it. */
#define WALL_NOISE 1e-5

/* The ray step itself (deriv, RK4 and the thesis' Euler step) is
 * raystep_rk4 / raystep_euler in the library (src/lib/rfield.c), shared
 * with etch2d. */

/* Boundary flattening, thesis 7.5.2.2: a node on a side wall whose ray
 * points into the volume loses the ray's component normal to the wall; a
 * ray pointing out is left alone.  Returns 0 if nothing is left of it. */
static int flatten(const struct node *n, double s[3])
{
	unsigned fl = n->flags;
	if (fl & ON_X0 && s[0] > 0) s[0] = 0;
	if (fl & ON_X1 && s[0] < 0) s[0] = 0;
	if (fl & ON_Y0 && s[1] > 0) s[1] = 0;
	if (fl & ON_Y1 && s[1] < 0) s[1] = 0;
	double r = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
	if (r < FLAT_TINY)
		return 0;
	for (int d = 0; d < 3; d++)
		s[d] /= r;
	return 1;
}

/* Recursive vector checking, thesis 7.4.2 (the advance_both of its
 * pseudo-code). */
static void advance_both(struct ctx *c, struct node *n, double dt, int depth)
{
	const struct rfield *f = c->f;
	if (n->flags & ON_SUB)
		return;
	double s[3] = {n->s[0], n->s[1], n->s[2]};
	if (n->flags & ON_SIDES && !flatten(n, s))
		return;
	double p2[3], s2[3];
	if (c->o->euler)
		raystep_euler(f, n->p, s, dt, p2, s2);
	else
		raystep_rk4(f, n->p, s, dt, p2, s2);
	c->st->substeps++;
	double dx = s2[0] - s[0], dy = s2[1] - s[1], dz = s2[2] - s[2];
	if (sqrt(dx * dx + dy * dy + dz * dz) > c->o->rl && depth < MAX_DEPTH) {
		c->st->halvings++;
		memcpy(n->s, s, sizeof s);
		advance_both(c, n, 0.5 * dt, depth + 1);
		advance_both(c, n, 0.5 * dt, depth + 1);
		return;
	}
	/* a flattened node stays on its wall exactly */
	if (n->flags & ON_X0 && s[0] == 0) p2[0] = f->lo[0];
	if (n->flags & ON_X1 && s[0] == 0) p2[0] = f->hi[0];
	if (n->flags & ON_Y0 && s[1] == 0) p2[1] = f->lo[1];
	if (n->flags & ON_Y1 && s[1] == 0) p2[1] = f->hi[1];
	/* the substrate stops the development (8.4.2): the node ends where
	 * its step crosses z = zmin */
	if (p2[2] <= f->lo[2]) {
		double a = n->p[2] - f->lo[2], b = n->p[2] - p2[2];
		double t = b > 0 ? a / b : 0;
		for (int d = 0; d < 2; d++)
			p2[d] = n->p[d] + t * (p2[d] - n->p[d]);
		p2[2] = f->lo[2];
		n->flags |= ON_SUB;
		c->st->stopped++;
	}
	memcpy(n->p, p2, sizeof p2);
	memcpy(n->s, s2, sizeof s2);
}

/* The advance of nodes [lo, hi): each node moves by its own ray alone,
 * so nodes may be split among threads freely. */
struct job {
	struct mesh *m;
	const struct rfield *f;
	const struct etch_opts *o;
	double dt;
	struct etch_stats *st;          /* one per worker */
	double wall_noise;              /* WALL_NOISE times the box's size, um */
};

static void advance_range(void *arg, size_t lo, size_t hi, int worker)
{
	struct job *j = arg;
	const struct rfield *f = j->f;
	struct ctx c = {f, j->o, &j->st[worker]};
	for (size_t i = lo; i < hi; i++) {
		struct node *n = &j->m->node[i];
		if (!n->alive)
			continue;
		advance_both(&c, n, j->dt, 0);
		/* a node that has left a face is no longer on it: moving out
		 * of the box (then clipping makes a new border, 7.5.2.1) or
		 * down from the top.  But a node on a side wall that steps out
		 * by less than WALL_NOISE stays on it: its ray lies along the
		 * wall, the normal component rounding noise of either sign
		 * (the mirror walls of examples/defect).  Unflagged, such a
		 * node came back in before the clip, 1e-5 um off the wall and
		 * no longer flattened onto it, and the cuts beside it left the
		 * surface's edge there open border (0.97 um on the defect in
		 * Olin Hunt 6512 at 240 mJ/cm2) */
		for (int d = 0; d < 2; d++) {
			unsigned w0 = d ? ON_Y0 : ON_X0, w1 = d ? ON_Y1 : ON_X1;
			if (n->flags & w0 && n->p[d] != f->lo[d]) {
				if (f->lo[d] - n->p[d] < j->wall_noise)
					n->p[d] = f->lo[d];
				else
					n->flags &= ~w0;
			}
			if (n->flags & w1 && n->p[d] != f->hi[d]) {
				if (n->p[d] - f->hi[d] < j->wall_noise)
					n->p[d] = f->hi[d];
				else
					n->flags &= ~w1;
			}
		}
		if (n->flags & ON_TOP && n->p[2] != f->hi[2]) n->flags &= ~(unsigned)ON_TOP;
	}
}

void advance_mesh(struct mesh *m, const struct rfield *f, double dt,
		  const struct etch_opts *o, struct etch_stats *st)
{
	int nw = par_threads();
	struct etch_stats *ws = xcalloc((size_t)nw, sizeof *ws);
	double size = fmax(f->hi[0] - f->lo[0], fmax(f->hi[1] - f->lo[1], f->hi[2] - f->lo[2]));
	struct job j = {m, f, o, dt, ws, WALL_NOISE * size};
	par_for(m->nnode, PAR_MIN_NODES, advance_range, &j);
	for (int w = 0; w < nw; w++) {
		st->substeps += ws[w].substeps;
		st->halvings += ws[w].halvings;
		st->stopped += ws[w].stopped;
	}
	free(ws);
}
