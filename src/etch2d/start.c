/*
 * start.c - development from a given profile (-start profile.plot): the
 * thesis' grooved and cornered surfaces of 6.2.3 (Figure 6.5's diverging
 * corner, Figure 6.6's converging one).  The profile is one polyline from
 * one side wall to the other, inside the box, not crossing itself; the
 * material etched at t = 0 is the region above it (between it and the
 * developer over the top).  Each method starts from it as it starts from
 * the flat top: the surface methods with a node at each vertex and every
 * S_ideal between (the string moves them along its bisectors; a ray at a
 * converging corner along the bisector, and at a diverging corner a fan
 * of rays from the one face's normal to the other's, as from a seed), the
 * cell methods with the cells whose centres lie above it etched, fast
 * marching with the nodes above it and their first neighbours below given
 * their exact times (signed distance / R).
 */
#include "e2.h"

#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* 1 if segments p1-p2 and q1-q2 cross (properly), with the crossing's
 * parameter u along p. */
int e2_crossing(const double *p1, const double *p2, const double *q1, const double *q2,
		double *u)
{
	double r0 = p2[0] - p1[0], r1 = p2[1] - p1[1];
	double s0 = q2[0] - q1[0], s1 = q2[1] - q1[1];
	double den = r0 * s1 - r1 * s0;
	if (den == 0)
		return 0;
	double w0 = q1[0] - p1[0], w1 = q1[1] - p1[1];
	double t = (w0 * s1 - w1 * s0) / den, v = (w0 * r1 - w1 * r0) / den;
	if (t > 0 && t < 1 && v > 0 && v < 1) {
		*u = t;
		return 1;
	}
	return 0;
}

/* An end this close (relative to the width or depth) to a wall is on it. */
#define WALL_TOL 1e-6
/* Most points a start profile may have (the crossing check is n^2). */
#define MAX_START 20000

void e2_start_init(struct e2 *e)
{
	const char *fn = e->o.startfile ? e->o.startfile : "-start";
	int n = e->o.nstart;
	if (n < 2)
		die("%s:1: the start profile needs at least 2 points, from one side wall to the other", fn);
	if (n > MAX_START)
		die("%s:1: the start profile has %d points, more than the %d allowed", fn, n, MAX_START);
	double *p = xreallocarray(NULL, (size_t)n, 2 * sizeof *p);
	/* left to right: the resist on the right of the walk, below */
	int rev = e->o.start[0] > e->o.start[2 * (n - 1)], m = 0;
	for (int k = 0; k < n; k++) {
		const double *q = e->o.start + 2 * (rev ? n - 1 - k : k);
		if (m > 0 && q[0] == p[2 * (m - 1)] && q[1] == p[2 * (m - 1) + 1])
			continue;       /* a repeated point */
		p[2 * m] = q[0], p[2 * m + 1] = q[1];
		m++;
	}
	e->sp = p;
	e->nsp = n = m;
	if (n < 2)
		die("%s:1: the start profile is a single point", fn);
	double tw = WALL_TOL * (e->x1 - e->x0), td = WALL_TOL * (e->z1 - e->z0);
	if (fabs(p[0] - e->x0) > tw || fabs(p[2 * (n - 1)] - e->x1) > tw)
		die("%s:1: the start profile runs from x = %g to %g, not from wall to wall (x %g..%g)",
		    fn, p[0], p[2 * (n - 1)], e->x0, e->x1);
	p[0] = e->x0, p[2 * (n - 1)] = e->x1;
	for (int k = 0; k < n; k++) {
		double *q = p + 2 * k;
		if (!(q[0] >= e->x0 - tw && q[0] <= e->x1 + tw && q[1] >= e->z0 - td && q[1] <= e->z1 + td))
			die("%s:1: start point %d (%g, %g) is outside the box x %g..%g, z %g..%g",
			    fn, k + 1, q[0], q[1], e->x0, e->x1, e->z0, e->z1);
		q[0] = fmin(fmax(q[0], e->x0), e->x1);
		q[1] = fmin(fmax(q[1], e->z0), e->z1);
	}
	for (int i = 0; i + 1 < n; i++)
		for (int j = i + 2; j + 1 < n; j++) {
			double u;
			if (e2_crossing(p + 2 * i, p + 2 * i + 2, p + 2 * j, p + 2 * j + 2, &u))
				die("%s:1: the start profile crosses itself (segments %d and %d)",
				    fn, i + 1, j + 1);
		}
}

int e2_start_etched(const struct e2 *e, double x, double z)
{
	/* even-odd test against the polygon closed over the top */
	double hi = e->z1 + 1 + (e->z1 - e->z0);
	int n = e->nsp, in = 0;
	for (int k = 0; k <= n + 1; k++) {
		double a[2], b[2];
		int ka = k, kb = (k + 1) % (n + 2);
		const double *pa = ka < n ? e->sp + 2 * ka : NULL, *pb = kb < n ? e->sp + 2 * kb : NULL;
		a[0] = pa ? pa[0] : ka == n ? e->x1 : e->x0;
		a[1] = pa ? pa[1] : hi;
		b[0] = pb ? pb[0] : kb == n ? e->x1 : e->x0;
		b[1] = pb ? pb[1] : hi;
		if ((a[1] > z) != (b[1] > z) && x < a[0] + (z - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
			in = !in;
	}
	return in;
}

double e2_start_dist(const struct e2 *e, double x, double z, double foot[2])
{
	double best = INFINITY;
	for (int k = 0; k + 1 < e->nsp; k++) {
		const double *a = e->sp + 2 * k, *b = a + 2;
		double dx = b[0] - a[0], dz = b[1] - a[1], l2 = dx * dx + dz * dz;
		double u = l2 > 0 ? ((x - a[0]) * dx + (z - a[1]) * dz) / l2 : 0;
		u = fmin(fmax(u, 0), 1);
		double f0 = a[0] + u * dx, f1 = a[1] + u * dz, d = hypot(x - f0, z - f1);
		if (d < best) {
			best = d;
			if (foot)
				foot[0] = f0, foot[1] = f1;
		}
	}
	return best;
}
