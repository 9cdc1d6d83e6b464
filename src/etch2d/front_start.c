/*
 * front_start.c - the first string of the surface methods (front.h): the
 * resist top with nodes at most S_ideal apart pointing down, a seed with
 * rays spread over the half circle below the top (thesis 6.3, Figure
 * 7.7), or a -start profile (start.c) with a node at each vertex and
 * every S_ideal between, along the normal into the resist, and at a
 * diverging corner a fan of rays from the one face's normal to the
 * other's (thesis 6.2.3, Figure 6.5).
 */
#include "front.h"

#include "util.h"

#include <math.h>

/* A turn smaller than this (radians) is no corner: one node, no fan. */
#define TURN_TINY 1e-9

/* Unit normal of segment k into the resist (the right of the walk), or 0
 * if the segment has no length. */
static int seg_normal(const struct e2 *e, int k, double nrm[2])
{
	const double *a = e->sp + 2 * k, *b = a + 2;
	double tx = b[0] - a[0], tz = b[1] - a[1], l = hypot(tx, tz);
	if (!(l > 0))
		return 0;
	nrm[0] = tz / l, nrm[1] = -tx / l;
	return 1;
}

static void push(struct e2 *e, struct front *fr, double x, double z, const double s[2])
{
	front_push(fr, x, z, s[0], s[1], 0);
	fr->v[fr->n - 1].flags = front_walls(e, fr->v[fr->n - 1].p);
}

void front_start_profile(struct e2 *e, struct front *fr, double seg, double fan)
{
	fr->n = 0;
	int n = e->nsp;
	double prev[2] = {0, -1};       /* the last segment's normal */
	int have = 0;
	for (int k = 0; k < n; k++) {
		const double *v = e->sp + 2 * k;
		double nin[2] = {0, 0}, nout[2] = {0, 0};
		int hin = have, hout = k + 1 < n && seg_normal(e, k, nout);
		if (hin)
			nin[0] = prev[0], nin[1] = prev[1];
		if (!hin) nin[0] = nout[0], nin[1] = nout[1];
		if (!hout) nout[0] = nin[0], nout[1] = nin[1];
		/* the turn from the incoming normal to the outgoing one; > 0: a
		 * left turn, away from the resist: a diverging corner */
		double turn = atan2(nin[0] * nout[1] - nin[1] * nout[0], nin[0] * nout[0] + nin[1] * nout[1]);
		if (fan > 0 && turn > TURN_TINY) {
			long m = (long)ceil(turn / fan);
			double th0 = atan2(nin[1], nin[0]);
			for (long q = 0; q <= m; q++) {
				double th = th0 + turn * (double)q / (double)m;
				push(e, fr, v[0], v[1], (double[2]){cos(th), sin(th)});
			}
		} else {
			double s[2] = {nin[0] + nout[0], nin[1] + nout[1]}, r = hypot(s[0], s[1]);
			if (r > 0)
				s[0] /= r, s[1] /= r;
			else
				s[0] = nout[0], s[1] = nout[1];
			push(e, fr, v[0], v[1], s);
		}
		if (!hout)
			continue;
		/* nodes at most seg apart along the segment, its normal */
		const double *w = v + 2;
		double len = hypot(w[0] - v[0], w[1] - v[1]);
		double mm = ceil(len / seg - 1e-9);
		if (!(mm < 4000000.0))
			die("-seg %g: %.3g nodes along the start profile, too many", seg, mm);
		long m = (long)mm;
		for (long q = 1; q < m; q++) {
			double u = (double)q / (double)m;
			push(e, fr, v[0] + u * (w[0] - v[0]), v[1] + u * (w[1] - v[1]), nout);
		}
		prev[0] = nout[0], prev[1] = nout[1];
		have = 1;
	}
}

void front_start(struct e2 *e, struct front *fr, double seg, long nseed)
{
	fr->n = 0;
	if (e->sp) {
		/* rays fanned as from a seed: nseed over the half circle */
		front_start_profile(e, fr, seg, nseed > 1 ? M_PI / (double)(nseed - 1) : M_PI / 8);
		return;
	}
	if (e->o.seeded) {
		for (long k = 0; k < nseed; k++) {
			double th = M_PI * (double)(nseed - 1 - k) / (double)(nseed - 1);
			double s[2] = {cos(th), -sin(th)};
			if (k == 0) s[0] = -1, s[1] = 0;
			if (k == nseed - 1) s[0] = 1, s[1] = 0;
			front_push(fr, e->o.seed[0], e->o.seed[1], s[0], s[1], 0);
			fr->v[fr->n - 1].flags = front_walls(e, fr->v[fr->n - 1].p);
		}
		return;
	}
	double mm = ceil((e->x1 - e->x0) / seg - 1e-9);
	if (!(mm < FRONT_MAX_NODES))
		die("-seg %g: %.3g nodes across the top, more than the %ld allowed", seg, mm, FRONT_MAX_NODES);
	long m = (long)mm;
	if (m < 1)
		m = 1;
	for (long k = 0; k <= m; k++) {
		double x = k == m ? e->x1 : e->x0 + (e->x1 - e->x0) * (double)k / (double)m;
		front_push(fr, x, e->z1, 0, -1, 0);
		fr->v[fr->n - 1].flags = front_walls(e, fr->v[fr->n - 1].p);
	}
}
