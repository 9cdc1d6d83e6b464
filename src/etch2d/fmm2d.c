/*
 * fmm2d.c - the 2D fast-marching reference (Sethian): the arrival time
 * T(x, z) of the front solves |grad T| R = 1 on a grid of nodes, accepted
 * in order of T from a binary heap, each trial value from the upwind
 * neighbours by the second-order difference where two accepted nodes lie
 * in a row (first-order otherwise).  The profile at time t is the contour
 * T = t.  This is the independent method the others are measured
 * against (tests, make bench): it knows nothing of rays or strings.
 *
 * Start: from the resist top every node of the top row has T = 0; from a
 * seed, the nodes within START_CELLS node spacings of it get T = distance
 * / R(seed), the exact time where the rate is uniform near the seed; from
 * a -start profile (start.c) the nodes above it have T = -distance / R and
 * those next to them below T = distance / R.  The
 * box's edges are walls (no flux through them), so from a seed the front
 * slides along the top.  The grid has -cells nx nz cells (nodes one more
 * each way); nodes where R = 0 are never reached.
 */
#include "methods.h"

#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* radius of the exact start around a seed, in node spacings */
#define START_CELLS 3.0
/* A node this close (in node spacings) to a -start profile is on it. */
#define START_ON 1e-9

enum { FAR, TRIAL, DONE, NEAR };

struct heap {
	size_t n;
	int *h;         /* node indices */
	int *pos;       /* position of a node in h, or -1 */
	const double *T;
};

static int before(const struct heap *hp, int a, int b)
{
	if (hp->T[a] != hp->T[b])
		return hp->T[a] < hp->T[b];
	return a < b;   /* ties by index: deterministic */
}

static void swap(struct heap *hp, size_t i, size_t j)
{
	int a = hp->h[i], b = hp->h[j];
	hp->h[i] = b, hp->h[j] = a;
	hp->pos[b] = (int)i, hp->pos[a] = (int)j;
}

static void up(struct heap *hp, size_t i)
{
	while (i > 0 && before(hp, hp->h[i], hp->h[(i - 1) / 2])) {
		swap(hp, i, (i - 1) / 2);
		i = (i - 1) / 2;
	}
}

static void down(struct heap *hp, size_t i)
{
	for (;;) {
		size_t l = 2 * i + 1, r = l + 1, m = i;
		if (l < hp->n && before(hp, hp->h[l], hp->h[m])) m = l;
		if (r < hp->n && before(hp, hp->h[r], hp->h[m])) m = r;
		if (m == i)
			return;
		swap(hp, i, m);
		i = m;
	}
}

static void push_or_update(struct heap *hp, int c)
{
	if (hp->pos[c] < 0) {
		hp->h[hp->n] = c;
		hp->pos[c] = (int)hp->n;
		hp->n++;
	}
	up(hp, (size_t)hp->pos[c]);
}

static int pop(struct heap *hp)
{
	int c = hp->h[0];
	hp->pos[c] = -1;
	hp->n--;
	if (hp->n) {
		hp->h[0] = hp->h[hp->n];
		hp->pos[hp->h[0]] = 0;
		down(hp, 0);
	}
	return c;
}

/* The trial time of node (i, k) from its accepted neighbours. */
static double solve(const double *T, const unsigned char *st, int nx, int nz, int i, int k,
		    double hx, double hz, double R)
{
	double a[2] = {0, 0}, b[2] = {0, 0}, c[2] = {0, 0};   /* per axis: a T^2 + b T + c */
	int have[2] = {0, 0};
	double h[2] = {hx, hz};
	for (int d = 0; d < 2; d++) {
		int di = d == 0, dk = d == 1;
		double best = INFINITY, best2 = INFINITY;
		for (int sgn = -1; sgn <= 1; sgn += 2) {
			int i1 = i + sgn * di, k1 = k + sgn * dk;
			if (i1 < 0 || i1 >= nx || k1 < 0 || k1 >= nz)
				continue;
			size_t c1 = (size_t)k1 * nx + i1;
			if (st[c1] != DONE || !(T[c1] < best))
				continue;
			best = T[c1];
			best2 = INFINITY;
			int i2 = i1 + sgn * di, k2 = k1 + sgn * dk;
			if (i2 >= 0 && i2 < nx && k2 >= 0 && k2 < nz) {
				size_t c2 = (size_t)k2 * nx + i2;
				if (st[c2] == DONE && T[c2] <= T[c1])
					best2 = T[c2];
			}
		}
		if (!isfinite(best))
			continue;
		have[d] = 1;
		if (isfinite(best2)) {
			/* second order: (3T - 4T1 + T2) / (2h) */
			double tstar = (4 * best - best2) / 3, w = 9.0 / (4 * h[d] * h[d]);
			a[d] = w, b[d] = -2 * w * tstar, c[d] = w * tstar * tstar;
		} else {
			double w = 1 / (h[d] * h[d]);
			a[d] = w, b[d] = -2 * w * best, c[d] = w * best * best;
		}
	}
	double rhs = 1 / (R * R);
	double A = a[0] + a[1], B = b[0] + b[1], C = c[0] + c[1] - rhs;
	double disc = B * B - 4 * A * C;
	if (have[0] && have[1] && disc >= 0) {
		double t = (-B + sqrt(disc)) / (2 * A);
		/* upwind: the solution must not precede what it was built from */
		if (t >= -b[0] / (2 * a[0]) && t >= -b[1] / (2 * a[1]))
			return t;
	}
	/* one axis alone, first order on the smaller */
	double best = INFINITY;
	for (int d = 0; d < 2; d++) {
		if (!have[d])
			continue;
		double t1 = -b[d] / (2 * a[d]);
		/* from the axis' own upwind form a (T - T*)^2 = rhs */
		double t = t1 + sqrt(rhs / a[d]);
		if (t < best)
			best = t;
	}
	return best;
}

/* The four neighbours of accepted node (i, k) not yet accepted and with a
 * rate: their times from the upwind update, lowered ones put in the band. */
static void update_neighbours(double *T, unsigned char *st, const double *R, int nx, int nz,
			      double hx, double hz, struct heap *hp, int i, int k)
{
	int nb[4][2] = {{i - 1, k}, {i + 1, k}, {i, k - 1}, {i, k + 1}};
	for (int q = 0; q < 4; q++) {
		int a = nb[q][0], b = nb[q][1];
		if (a < 0 || a >= nx || b < 0 || b >= nz)
			continue;
		size_t c2 = (size_t)b * nx + a;
		if (st[c2] == DONE || !(R[c2] > 0))
			continue;
		double t = solve(T, st, nx, nz, a, b, hx, hz, R[c2]);
		if (t < T[c2]) {
			T[c2] = t;
			st[c2] = TRIAL;
			push_or_update(hp, (int)c2);
		}
	}
}

void e2_run_fmm(struct e2 *e)
{
	int cx, cz;
	e2_cells(e, &cx, &cz);
	int nx = cx + 1, nz = cz + 1;
	size_t n = (size_t)nx * nz;
	double hx = (e->x1 - e->x0) / cx, hz = (e->z1 - e->z0) / cz;
	double *T = xreallocarray(NULL, n, sizeof *T);
	double *R = xreallocarray(NULL, n, sizeof *R);
	unsigned char *st = xcalloc(n, 1);
	struct heap hp = {0, xreallocarray(NULL, n, sizeof(int)), xreallocarray(NULL, n, sizeof(int)), T};
	e->st.bytes = n * (2 * sizeof(double) + 1 + 2 * sizeof(int));
	e->st.total = (long)n;
	for (size_t c = 0; c < n; c++) {
		T[c] = INFINITY;
		hp.pos[c] = -1;
		int i = (int)(c % nx), k = (int)(c / nx);
		R[c] = e2_rate(e, e->x0 + i * hx, k == nz - 1 ? e->z1 : e->z0 + k * hz, NULL);
	}
	if (e->o.seeded) {
		double r0 = e2_rate(e, e->o.seed[0], e->o.seed[1], NULL);
		double rad = START_CELLS * fmax(hx, hz);
		for (size_t c = 0; c < n; c++) {
			int i = (int)(c % nx), k = (int)(c / nx);
			double d = hypot(e->x0 + i * hx - e->o.seed[0], e->z0 + k * hz - e->o.seed[1]);
			if (d <= rad && r0 > 0) {
				T[c] = d / r0;
				st[c] = DONE;
			}
		}
	} else if (e->sp) {
		/* above the start profile: T = -distance / R; below it, the
		 * nodes next to one above (or on it): T = distance / R, R the
		 * mean of the node's and the profile's there */
		for (size_t c = 0; c < n; c++) {
			int i = (int)(c % nx), k = (int)(c / nx);
			double x = e->x0 + i * hx, z = k == nz - 1 ? e->z1 : e->z0 + k * hz, foot[2];
			double d = e2_start_dist(e, x, z, foot);
			if (e2_start_etched(e, x, z) && R[c] > 0) {
				T[c] = -d / R[c];
				st[c] = DONE;
			} else if (d <= START_ON * fmin(hx, hz)) {
				T[c] = 0;
				st[c] = DONE;
			}
		}
		for (size_t c = 0; c < n; c++) {
			int i = (int)(c % nx), k = (int)(c / nx);
			if (st[c] == DONE || !(R[c] > 0))
				continue;
			int next = (i > 0 && st[c - 1] == DONE) || (i + 1 < nx && st[c + 1] == DONE) ||
				   (k > 0 && st[c - nx] == DONE) || (k + 1 < nz && st[c + nx] == DONE);
			if (!next)
				continue;
			double x = e->x0 + i * hx, z = k == nz - 1 ? e->z1 : e->z0 + k * hz, foot[2];
			double d = e2_start_dist(e, x, z, foot);
			double rf = e2_rate(e, foot[0], foot[1], NULL);
			T[c] = 2 * d / (R[c] + (rf > 0 ? rf : R[c]));
			st[c] = NEAR;   /* accepted below, after the scan */
		}
		for (size_t c = 0; c < n; c++)
			if (st[c] == NEAR)
				st[c] = DONE;
	} else {
		for (int i = 0; i < nx; i++) {
			size_t c = (size_t)(nz - 1) * nx + i;
			T[c] = 0;
			st[c] = DONE;
		}
	}
	/* the trial band around the start */
	for (size_t c = 0; c < n; c++) {
		if (st[c] != DONE)
			continue;
		int i = (int)(c % nx), k = (int)(c / nx);
		update_neighbours(T, st, R, nx, nz, hx, hz, &hp, i, k);
	}
	/* the whole grid is marched: a contour's crossings need the final
	 * times of the nodes just beyond it too */
	while (hp.n) {
		int c = pop(&hp);
		st[c] = DONE;
		e->st.steps++;
		int i = c % nx, k = c / nx;
		update_neighbours(T, st, R, nx, nz, hx, hz, &hp, i, k);
		if ((long)hp.n > e->st.items)
			e->st.items = (long)hp.n;
	}
	for (int q = 0; q < e->ntp; q++) {
		e2_begin_set(e);
		contour_emit(e, T, nx, nz, e->tp[q]);
	}
	free(T);
	free(R);
	free(st);
	free(hp.h);
	free(hp.pos);
}
