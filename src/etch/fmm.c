/*
 * fmm.c - fast marching solver of |grad T| R = 1 (see fmm.h).
 *
 * Design.  Nodes are FAR, TRIAL or KNOWN (Sethian 1996).  KNOWN nodes
 * start as the source (the resist top, or the nodes around seed points);
 * the TRIAL node of least T is accepted next and its neighbours are
 * updated from their KNOWN neighbours only, so T is computed in
 * increasing order and every node once: O(N log N) with a binary heap.
 * The heap (4-ary) holds (T, node, slot) entries by value, so sifting
 * touches one array, and the node's slot holds its heap position for
 * decrease-key.
 *
 * A TRIAL node is updated once for every neighbour accepted before it,
 * each time from all its KNOWN neighbours, and the slowness of a cell
 * (cell_slowness: a logarithm and the limited curvature of four rates)
 * depends on the rates alone: so each TRIAL node holds, in a slot of its
 * own (struct cells, numbered per node), the cell slownesses it has
 * computed towards its upwind neighbours, and those of the cells beyond
 * them that the second-order form reads, which the neighbour, when
 * accepted, hands over from its own slot.  Every value is computed by
 * the same function from the same rates as without the slots, so T is
 * the same to the last bit; the slots cost memory in proportion to the
 * front (the TRIAL nodes: the whole developed surface of the moment,
 * some 20-30 nodes an x-y column on the examples), not the grid (on
 * examples/contact without bake, three cell slownesses a node computed
 * instead of eleven).
 *
 * The update (Sethian & Vladimirsky's second-order upwind scheme):
 * along each axis take the KNOWN neighbour of smaller T, T1; if the next
 * node beyond it is KNOWN too with T2 <= T1, the one-sided difference
 * (3T - 4T1 + T2)/(2h) is used, else (T - T1)/h.  Writing each as
 * sqrt(a)(T - b), T solves sum a_d (T - b_d)^2 = 1/R^2 over the axes
 * whose b_d lies below T (added in increasing b_d, the causality
 * condition).  Where the second-order quadratic has no root (rare, near
 * sharp rate changes) the solution with fewer axes is kept: never below
 * the true upwind value, so the order of acceptance stays causal.
 *
 * The slowness.  A difference along an axis stands for the slowness
 * over the cells it spans, not at the node: (T - T1)/h for the mean of
 * 1/R over the cell, (3T - 4T1 + T2)/(2h) for 3/2 of it minus 1/2 of the
 * next cell's.  The axis' coefficient is scaled by (f/mean)^2, f the
 * node's slowness, so that the quadratic keeps f on its right-hand side.
 * In one dimension the solve is then exact for the rate the cells
 * integrate, whatever its contrast; the published scheme (f at the node,
 * fmm_solve_nodal) is second order only where R is smooth on the grid
 * scale, and where the rate changes several-fold within a cell (a resist
 * at the edge of the image) puts the front behind: on the baked contact
 * of examples/contact at 60 s, 0.12 of an x-y cell on average.
 *
 * The rate between nodes.  A rate file samples a smooth field, so the
 * rate along a grid line is taken as linear between two nodes plus the
 * curvature their neighbours show, R = Rlin - (D/2) u(1 - u) with D the
 * second difference (rate_between), limited (cell_curvature: none where
 * the neighbours' second differences differ in sign, as at a sharp edge
 * or a standing wave sampled too coarsely, else the smaller, and the
 * result kept in the neighbours' range).  The mean of 1/R over a cell is
 * the linear rate's, (ln Ra - ln Rb)/(Ra - Rb) exactly, plus about
 * D/(12 Ra Rb) to first order in D (cell_slowness, bow_weight).  Taken
 * as linear, the rate made the front run ahead where it is convex and
 * behind where it is concave, by an error of every cell crossed that no
 * refinement removed: 0.085 of a z cell on average on a Gaussian focus,
 * 0.016 at the bottom of an exponential attenuation
 * (tests/etch/fmm_smooth.c).  The rates at the nodes of a refined grid
 * are the same reconstruction, axis by axis (refine_rates), so that
 * refining converges to the sampled field.  fmm_solve_linear and the
 * lazy solve of deloop's classifier keep the rate linear (trilinear at a
 * refined grid's nodes, rate_at), as the ray-string engine takes it.
 */
#include "fmm.h"
#include "util.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { FAR = 0, TRIAL = 1, KNOWN = 2 };

/* Point sources: nodes within this many cells (per axis) of a seed get
 * the exact distance / rate, so the march starts where the front is
 * already smooth on the grid scale (the point singularity would
 * otherwise cost an O(h log h) error everywhere). */
enum { SEED_CELLS = 2 };

/* A 4-ary heap: half the depth of a binary one, and a node's children
 * share a cache line. */
enum { ARITY = 4 };

struct heap_ent {
	double t;
	int32_t n;
	int32_t slot;           /* the node's struct cells (in the padding) */
};

/* What a TRIAL node has computed of the cells around it, per axis d:
 * near[d] the cell to its upwind neighbour, far[d] the next cell beyond
 * that neighbour (the second-order form's), for the direction the bits
 * of up say (bit d for near, 3 + d for far: towards +d), where the bits
 * of has say a value is there.  One direction per axis, as the upwind
 * neighbour of an axis seldom changes side: the slot is 56 bytes. */
struct cells {
	double near[3];
	double far[3];
	int32_t pos;            /* the node's place in the heap */
	unsigned char has, up;
};

struct solver {
	int n[3];
	ptrdiff_t stride[3];
	double a1[3];           /* 1/h^2: first-order coefficient per axis */
	double a2[3];           /* 9/(4h^2): second-order */
	double *t;
	double *slow;           /* 1/R per node, s/um; INFINITY where R ~ 0 */
	unsigned char *state;
	int nodal;              /* fmm_solve_nodal: the node's own slowness */
	int linear;             /* the rate linear between nodes (fmm_solve_linear) */
	int32_t *slot;          /* the slot of TRIAL nodes */
	struct heap_ent *heap;  /* in heap_mem, placed so that the four
				 * children of an entry share a cache line */
	struct heap_ent *heap_mem;
	size_t nheap;
	struct cells **blocks;  /* the slots, SLOT_BLOCK a block: one per
				 * TRIAL node, in memory that grows with the
				 * front without a copy */
	int32_t *free_slots;    /* slots not in use, a stack */
	size_t nslots, nfree;   /* slots made, of which free */
};

enum { SLOT_BLOCK = 1 << 14 };

static struct cells *cells_of(const struct solver *s, int32_t q)
{
	return &s->blocks[q / SLOT_BLOCK][q % SLOT_BLOCK];
}

/* An empty slot for a node becoming TRIAL. */
static int32_t slot_new(struct solver *s)
{
	int32_t q;
	if (s->nfree > 0) {
		q = s->free_slots[--s->nfree];
	} else {
		if (s->nslots % SLOT_BLOCK == 0) {
			size_t nb = s->nslots / SLOT_BLOCK + 1;
			s->blocks = xreallocarray(s->blocks, nb, sizeof *s->blocks);
			s->blocks[nb - 1] = xreallocarray(NULL, SLOT_BLOCK, sizeof **s->blocks);
			s->free_slots = xreallocarray(s->free_slots, nb * SLOT_BLOCK,
						      sizeof *s->free_slots);
		}
		q = (int32_t)s->nslots++;
	}
	cells_of(s, q)->has = 0;
	return q;
}

static void slots_free(struct solver *s)
{
	for (size_t b = 0; b * SLOT_BLOCK < s->nslots; b++)
		free(s->blocks[b]);
	free(s->blocks);
	free(s->free_slots);
}

static void slot_free(struct solver *s, int32_t q)
{
	if (q >= 0)
		s->free_slots[s->nfree++] = q;
}

static void sift_up(struct solver *s, size_t i)
{
	struct heap_ent e = s->heap[i];
	while (i > 0) {
		size_t p = (i - 1) / ARITY;
		if (s->heap[p].t <= e.t)
			break;
		s->heap[i] = s->heap[p];
		cells_of(s, s->heap[i].slot)->pos = (int32_t)i;
		i = p;
	}
	s->heap[i] = e;
	cells_of(s, e.slot)->pos = (int32_t)i;
}

/* Removing the root: the hole walks down to a leaf along the smaller
 * children, then the last entry is sifted up from there (Floyd's
 * bottom-up deletion; the last entry almost always belongs near the
 * bottom, so this saves a comparison per level). */
static void remove_root(struct solver *s)
{
	size_t n = s->nheap, i = 0;
	for (;;) {
		size_t c = ARITY * i + 1;
		if (c >= n)
			break;
		size_t best = c, end = c + ARITY < n ? c + ARITY : n;
		for (size_t q = c + 1; q < end; q++)
			if (s->heap[q].t < s->heap[best].t)
				best = q;
		s->heap[i] = s->heap[best];
		cells_of(s, s->heap[i].slot)->pos = (int32_t)i;
		i = best;
	}
	if (i != n - 1) {
		s->heap[i] = s->heap[n - 1];
		sift_up(s, i);
	}
	s->nheap = n - 1;
}

/* Makes node n TRIAL with time t and the slot q (slot_new), or lowers
 * its time to t. */
static void offer(struct solver *s, size_t n, double t, int32_t q)
{
	if (s->state[n] == FAR) {
		s->state[n] = TRIAL;
		s->t[n] = t;
		s->heap[s->nheap].t = t;
		s->heap[s->nheap].n = (int32_t)n;
		s->heap[s->nheap].slot = q;
		s->slot[n] = q;
		s->nheap++;
		sift_up(s, s->nheap - 1);
	} else if (s->state[n] == TRIAL && t < s->t[n]) {
		s->t[n] = t;
		size_t i = (size_t)cells_of(s, s->slot[n])->pos;
		s->heap[i].t = t;
		sift_up(s, i);
	}
}

/* The slot of node n: its own if TRIAL, else a new one. */
static int32_t slot_of(struct solver *s, size_t n)
{
	return s->state[n] == TRIAL ? s->slot[n] : slot_new(s);
}

static size_t pop(struct solver *s, int32_t *slot)
{
	size_t n = (size_t)s->heap[0].n;
	*slot = s->heap[0].slot;
	remove_root(s);
	return n;
}

/* The mean slowness over the cell between neighbouring nodes of
 * slownesses sa and sb, where the rate is linear along the grid line:
 * (1/h) int dx/R = (ln Ra - ln Rb)/(Ra - Rb).  INFINITY if either
 * rate is zero (the resist top may be KNOWN at zero rate). */
static double path_slowness(double sa, double sb)
{
	if (!(sa < INFINITY && sb < INFINITY))
		return INFINITY;
	double ra = 1 / sa, rb = 1 / sb, lr = log(ra / rb);
	if (fabs(lr) < 1e-9)
		return 0.5 * (sa + sb);
	return lr / (ra - rb);
}

/* The curvature of the rate over the cell between nodes of rates ra and
 * rb, as the second difference h^2 R'' (um/s), from the second
 * differences da at a and db at b (NAN where a node has no neighbour
 * beyond it: the other one stands in).  Limited: minmod (0 where they
 * differ in sign, as at a sharp edge or a standing wave sampled too
 * coarsely, else the smaller), and at most the smaller end rate, so the
 * reconstruction R = Rlin - (D/2) u(1 - u) stays positive (its middle
 * moves by D/8) and the cell slowness finite. */
static double cell_curvature(double da, double db, double ra, double rb)
{
	if (isnan(da))
		da = db;
	if (isnan(db))
		db = da;
	if (!(da * db > 0))
		return 0;
	double d = fabs(da) < fabs(db) ? da : db, cap = fmax(0, fmin(ra, rb));
	return fmin(fmax(d, -cap), cap);
}

/* The limited curvature of the cell between v[1] and v[2] from the four
 * rates v[0..3] along a grid line (v[0], v[3] NAN where the line ends;
 * 0 if both do), and the range lo..hi of those present: the
 * reconstruction is clamped to it, so it never leaves the neighbours'
 * range (a smooth extremum between two nodes may rise above both). */
static double line_curvature(const double v[4], double *lo, double *hi)
{
	*lo = fmin(v[1], v[2]);
	*hi = fmax(v[1], v[2]);
	for (int q = 0; q < 4; q += 3)
		if (!isnan(v[q])) {
			*lo = fmin(*lo, v[q]);
			*hi = fmax(*hi, v[q]);
		}
	double da = isnan(v[0]) ? NAN : v[0] - 2 * v[1] + v[2];
	double db = isnan(v[3]) ? NAN : v[1] - 2 * v[2] + v[3];
	return isnan(da) && isnan(db) ? 0 : cell_curvature(da, db, v[1], v[2]);
}

/* The rate reconstructed at fraction u of the cell between v[1] and
 * v[2] (line_curvature's four rates): linear plus the limited curvature,
 * R = Rlin - (D/2) u(1 - u), clamped to the neighbours' range; the model
 * whose mean slowness cell_slowness takes. */
static double rate_between(const double v[4], double u)
{
	double lo, hi, d = line_curvature(v, &lo, &hi);
	return fmin(fmax(v[1] + (v[2] - v[1]) * u - 0.5 * d * u * (1 - u), lo), hi);
}

/* The mean slowness the bow -(D/2) u(1 - u) adds to the linear rate
 * from ra to rb, per unit D/2, to first order: the integral over the
 * cell of u(1 - u)/Rlin(u)^2, ((ra + rb) ln(rb/ra) - 2 (rb - ra)) /
 * (rb - ra)^3, given lr = ln(ra/rb); 1/(6 ra rb) where the rates nearly
 * agree (the closed form cancels there; the two differ by
 * (rb - ra)^2/ra^2 relative). */
static double bow_weight(double ra, double rb, double lr)
{
	double dr = rb - ra;
	if (fabs(dr) < 1e-3 * fmax(ra, rb))
		return 1 / (6 * ra * rb);
	return (-(ra + rb) * lr - 2 * dr) / (dr * dr * dr);
}

static double node_rate(const struct solver *s, size_t m)
{
	return s->slow[m] < INFINITY ? 1 / s->slow[m] : 0;
}

/* The mean slowness over the cell from node a (coordinate ca) to its
 * neighbour a + o (coordinate ca + dir) on an axis of hi + 1 nodes.  The
 * rate file samples a smooth field, so the rate between the nodes is
 * reconstructed as linear plus the limited curvature D (rate_between);
 * to first order in D its mean slowness is that of the linear rate
 * (path_slowness, exact) plus (D/2) bow_weight (D/(12 Ra Rb) where Ra
 * and Rb are close), kept within the slownesses of the neighbours'
 * range.  Taking the rate as linear instead puts a front ahead where the
 * rate is convex and behind where it is concave, by an error of the cell
 * that no refinement of the same nodes removes (tests/etch/fmm_smooth.c). */
static double cell_slowness(const struct solver *s, size_t a, ptrdiff_t o, int ca, int dir,
			    int hi)
{
	size_t b = (size_t)((ptrdiff_t)a + o);
	double f = path_slowness(s->slow[a], s->slow[b]);
	if (s->nodal || s->linear || !(f < INFINITY))
		return f;
	int cp = ca - dir, cn = ca + 2 * dir;
	double v[4] = {cp >= 0 && cp <= hi ? node_rate(s, (size_t)((ptrdiff_t)a - o)) : NAN,
		       1 / s->slow[a], 1 / s->slow[b],
		       cn >= 0 && cn <= hi ? node_rate(s, (size_t)((ptrdiff_t)b + o)) : NAN};
	double rlo, rhi, d = line_curvature(v, &rlo, &rhi);
	if (d == 0)
		return f;
	/* ln(Ra/Rb) from the linear mean f = ln(Ra/Rb)/(Ra - Rb), without a
	 * second logarithm (where Ra and Rb nearly agree bow_weight does not
	 * read it) */
	f += 0.5 * d * bow_weight(v[1], v[2], f * (v[1] - v[2]));
	return rlo > 0 ? fmin(fmax(f, 1 / rhi), 1 / rlo) : fmax(f, 1 / rhi);
}

/* cell_slowness of the cell from a towards a + o, kept in *v with the
 * bit b of cl's has and up (up: o > 0). */
static double cell_slowness_memo(const struct solver *s, struct cells *cl, double *v, int b,
				 size_t a, ptrdiff_t o, int ca, int dir, int hi)
{
	unsigned char bit = (unsigned char)(1u << b), up = o > 0 ? bit : 0;
	if (!(cl->has & bit) || (cl->up & bit) != up) {
		*v = cell_slowness(s, a, o, ca, dir, hi);
		cl->has |= bit;
		cl->up = (unsigned char)((cl->up & ~bit) | up);
	}
	return *v;
}

/* The upwind update of node n at grid position c (see the note above),
 * its cell slownesses kept in cl. */
static double update(const struct solver *s, size_t n, const int c[3], struct cells *cl)
{
	double a[3], b[3];
	int m = 0;
	for (int d = 0; d < 3; d++) {
		ptrdiff_t st = s->stride[d];
		int hi = s->n[d] - 1;
		double t1 = INFINITY, t2 = INFINITY;
		ptrdiff_t o = -st;      /* towards the upwind neighbour */
		if (c[d] > 0 && s->state[n - st] == KNOWN) {
			t1 = s->t[n - st];
			if (c[d] > 1 && s->state[n - 2 * st] == KNOWN)
				t2 = s->t[n - 2 * st];
		}
		if (c[d] < hi && s->state[n + st] == KNOWN && s->t[n + st] < t1) {
			t1 = s->t[n + st];
			o = st;
			t2 = c[d] < hi - 1 && s->state[n + 2 * st] == KNOWN ? s->t[n + 2 * st]
									   : INFINITY;
		}
		if (t1 == INFINITY)
			continue;
		/* the slowness the difference stands for: the mean over the
		 * cell (first order), or the second-order combination of the
		 * two cells' means, in place of the node's own */
		int dir = o > 0 ? 1 : -1;
		double f1 = cell_slowness_memo(s, cl, &cl->near[d], d, n, o, c[d], dir, hi), f = f1;
		double aa, bb;
		if (t2 <= t1 &&
		    (f = 0.5 * (3 * f1 - cell_slowness_memo(s, cl, &cl->far[d], 3 + d, n + o, o,
							     c[d] + dir, dir, hi))) > 0) {
			aa = s->a2[d];
			bb = (4 * t1 - t2) / 3;
		} else {
			aa = s->a1[d];
			bb = t1;
			f = f1;
		}
		if (f < INFINITY && !s->nodal)
			aa *= (s->slow[n] / f) * (s->slow[n] / f);
		/* insertion by b, so axes join in causal order */
		int q = m++;
		while (q > 0 && b[q - 1] > bb) {
			a[q] = a[q - 1];
			b[q] = b[q - 1];
			q--;
		}
		a[q] = aa;
		b[q] = bb;
	}
	double f2 = s->slow[n] * s->slow[n];
	double t = b[0] + s->slow[n] / sqrt(a[0]);
	double A = a[0], B = a[0] * b[0], C = a[0] * b[0] * b[0];
	for (int q = 1; q < m && t > b[q]; q++) {
		A += a[q];
		B += a[q] * b[q];
		C += a[q] * b[q] * b[q];
		double disc = B * B - A * (C - f2);
		if (disc < 0)
			break;
		t = (B + sqrt(disc)) / A;
	}
	return t;
}

/* Updates the non-KNOWN, reachable neighbours of the node just accepted,
 * handing each the slowness of the cell beyond n from n's slot ns (-1:
 * none, a source node). */
static void relax(struct solver *s, size_t n, const int c[3], int32_t ns)
{
	for (int d = 0; d < 3; d++)
		for (int dir = -1; dir <= 1; dir += 2) {
			int cd = c[d] + dir;
			if (cd < 0 || cd >= s->n[d])
				continue;
			size_t m = (size_t)((ptrdiff_t)n + dir * s->stride[d]);
			if (s->state[m] == KNOWN || s->slow[m] == INFINITY)
				continue;
			int cm[3] = {c[0], c[1], c[2]};
			cm[d] = cd;
			int32_t q = slot_of(s, m);
			struct cells *cl = cells_of(s, q);
			/* from m, n lies towards -dir: the cell beyond n in
			 * that direction is n's own cell towards -dir, if n
			 * has it */
			if (ns >= 0) {
				const struct cells *cn = cells_of(s, ns);
				unsigned char bn = (unsigned char)(1u << d), up = dir < 0 ? bn : 0;
				unsigned char bf = (unsigned char)(bn << 3);
				if ((cn->has & bn) && (cn->up & bn) == up) {
					cl->far[d] = cn->near[d];
					cl->has |= bf;
					cl->up = (unsigned char)((cl->up & ~bf) | (up << 3));
				}
			}
			offer(s, m, update(s, m, cm, cl), q);
		}
}

static void coords(const struct solver *s, size_t n, int c[3])
{
	c[0] = (int)(n % (size_t)s->n[0]);
	size_t r = n / (size_t)s->n[0];
	c[1] = (int)(r % (size_t)s->n[1]);
	c[2] = (int)(r / (size_t)s->n[1]);
}

static double slowness(double rate)
{
	return rate >= FMM_RATE_FLOOR ? 1 / rate : INFINITY;
}

/* The rate at any point of the box, trilinear in the rate grid. */
static double rate_point(const struct ratefile *r, const double p[3])
{
	const double *b = &r->xmin;
	int nr[3] = {r->nx, r->ny, r->nz}, lo[3];
	double w[3];
	for (int d = 0; d < 3; d++) {
		double x = fmin(fmax(p[d], b[2 * d]), b[2 * d + 1]);
		double u = nr[d] > 1 ? (x - b[2 * d]) / (b[2 * d + 1] - b[2 * d]) * (nr[d] - 1) : 0;
		lo[d] = (int)u;
		if (lo[d] >= nr[d] - 1)
			lo[d] = nr[d] > 1 ? nr[d] - 2 : 0;
		w[d] = nr[d] > 1 ? u - lo[d] : 0;
	}
	const double *v = fmt_rate_values(r);
	double sum = 0;
	for (int q = 0; q < 8; q++) {
		double wq = 1;
		int idx[3];
		for (int d = 0; d < 3; d++) {
			int e = (q >> d) & 1;
			wq *= e ? w[d] : 1 - w[d];
			idx[d] = lo[d] + e;
		}
		if (wq > 0)
			sum += wq * v[fmt_rate_index(r, idx[0], idx[1], idx[2])];
	}
	return sum;
}

/* Trilinear interpolation of the rate at refined node (i, j, k). */
static double rate_at(const struct ratefile *r, const int ref[3], const int c[3])
{
	const double *v = fmt_rate_values(r);
	int nr[3] = {r->nx, r->ny, r->nz};
	int lo[3];
	double w[3];
	for (int d = 0; d < 3; d++) {
		lo[d] = c[d] / ref[d];
		w[d] = (double)(c[d] % ref[d]) / ref[d];
		if (lo[d] >= nr[d] - 1) {   /* the far face itself */
			lo[d] = nr[d] - 1;
			w[d] = 0;
		}
	}
	double sum = 0;
	for (int q = 0; q < 8; q++) {
		int e[3] = {q & 1, (q >> 1) & 1, (q >> 2) & 1};
		double wq = 1;
		int idx[3];
		for (int d = 0; d < 3; d++) {
			wq *= e[d] ? w[d] : 1 - w[d];
			idx[d] = lo[d] + (e[d] && w[d] > 0);
		}
		if (wq > 0)
			sum += wq * v[fmt_rate_index(r, idx[0], idx[1], idx[2])];
	}
	return sum;
}

/* The rates at the nodes of a refined grid, into s->slow: the rate-grid
 * nodes' own, and between them the reconstruction of rate_between, axis
 * by axis (x along the rate grid's lines, then y through those, then z:
 * the tensor product, trilinear where no curvature is taken). */
static void refine_rates(const struct ratefile *r, const int ref[3], struct solver *s)
{
	const double *v = fmt_rate_values(r);
	int c[3];
	for (c[2] = 0; c[2] < r->nz; c[2]++)
		for (c[1] = 0; c[1] < r->ny; c[1]++)
			for (c[0] = 0; c[0] < r->nx; c[0]++)
				s->slow[(size_t)c[0] * ref[0] + (size_t)c[1] * ref[1] * s->stride[1] +
					(size_t)c[2] * ref[2] * s->stride[2]] =
					v[fmt_rate_index(r, c[0], c[1], c[2])];
	for (int d = 0; d < 3; d++) {
		if (ref[d] == 1)
			continue;
		int nc = (s->n[d] - 1) / ref[d] + 1;
		size_t n = 0;
		for (c[2] = 0; c[2] < s->n[2]; c[2]++)
			for (c[1] = 0; c[1] < s->n[1]; c[1]++)
				for (c[0] = 0; c[0] < s->n[0]; c[0]++, n++) {
					/* filled so far: every node along the axes
					 * before d, the rate grid's along the others */
					int skip = c[d] % ref[d] == 0;
					for (int e = d + 1; e < 3; e++)
						skip |= c[e] % ref[e] != 0;
					if (skip)
						continue;
					int lo = c[d] / ref[d];
					double w[4];
					for (int q = 0; q < 4; q++) {
						int k = lo - 1 + q;
						w[q] = k < 0 || k >= nc ? NAN
							: s->slow[(ptrdiff_t)n + (ptrdiff_t)(k * ref[d] - c[d]) *
										   s->stride[d]];
					}
					s->slow[n] = rate_between(w, (double)(c[d] % ref[d]) / ref[d]);
				}
	}
}

static struct fmm *setup(const struct ratefile *r, const int refine[3], int linear,
			 struct solver *s)
{
	s->linear = linear;
	struct fmm *f = xcalloc(1, sizeof *f);
	int nr[3] = {r->nx, r->ny, r->nz};
	const double *b = &r->xmin;
	size_t total = 1;
	for (int d = 0; d < 3; d++) {
		int ref = refine ? refine[d] : 1;
		if (ref < 1 || ref > FMM_MAX_REFINE)
			die("fmm: refinement factor %d out of range 1..%d", ref, FMM_MAX_REFINE);
		f->refine[d] = ref;
		long nd = (long)(nr[d] - 1) * ref + 1;
		if (nd > INT32_MAX || (total *= (size_t)nd) > INT32_MAX)
			die("fmm: refined grid too large (over %ld nodes)", (long)INT32_MAX);
		f->n[d] = s->n[d] = (int)nd;
		f->bounds[2 * d] = b[2 * d];
		f->bounds[2 * d + 1] = b[2 * d + 1];
		f->h[d] = nd > 1 ? (b[2 * d + 1] - b[2 * d]) / (double)(nd - 1) : 0;
		s->a1[d] = nd > 1 ? 1 / (f->h[d] * f->h[d]) : 0;
		s->a2[d] = 2.25 * s->a1[d];
	}
	s->stride[0] = 1;
	s->stride[1] = s->n[0];
	s->stride[2] = (ptrdiff_t)s->n[0] * s->n[1];
	f->t = xreallocarray(NULL, total, sizeof *f->t);
	s->t = f->t;
	s->slow = xreallocarray(NULL, total, sizeof *s->slow);
	s->state = xcalloc(total, 1);
	s->slot = xreallocarray(NULL, total, sizeof *s->slot);
	/* 64-byte lines: entries 4i + 1 .. 4i + 4, the children of i, fill
	 * one line when entry 1 starts a line (malloc aligns to 16) */
	s->heap_mem = xreallocarray(NULL, total + 3, sizeof *s->heap);
	s->heap = s->heap_mem + (4 - ((uintptr_t)s->heap_mem / sizeof *s->heap + 1) % 4) % 4;
	s->nheap = 0;
	s->blocks = NULL;
	s->free_slots = NULL;
	s->nslots = s->nfree = 0;
	int ref[3] = {refine ? refine[0] : 1, refine ? refine[1] : 1, refine ? refine[2] : 1};
	for (size_t n = 0; n < total; n++)
		f->t[n] = FMM_UNREACHED;
	if (ref[0] == 1 && ref[1] == 1 && ref[2] == 1) {
		/* the rate grid itself: no interpolation */
		const double *v = fmt_rate_values(r);
		for (size_t n = 0; n < total; n++)
			s->slow[n] = slowness(v[n]);
		return f;
	}
	if (linear) {
		size_t n = 0;
		int c[3];
		for (c[2] = 0; c[2] < s->n[2]; c[2]++)
			for (c[1] = 0; c[1] < s->n[1]; c[1]++)
				for (c[0] = 0; c[0] < s->n[0]; c[0]++, n++)
					s->slow[n] = slowness(rate_at(r, ref, c));
		return f;
	}
	refine_rates(r, ref, s);
	for (size_t n = 0; n < total; n++)
		s->slow[n] = slowness(s->slow[n]);
	return f;
}

/* Accepts the TRIAL node of least T and updates its neighbours: one step
 * of the march, the same whether the march runs to the end (march) or
 * only as far as a query needs (fmm_time_at_settled). */
static void accept_next(struct fmm *f, struct solver *s)
{
	int32_t q;
	size_t n = pop(s, &q);
	s->state[n] = KNOWN;
	f->accepted++;
	int c[3];
	coords(s, n, c);
	relax(s, n, c, q);
	slot_free(s, q);
}

/* The rates stay with the solution, for the surface (fmm_out.c); the
 * march's work arrays go. */
static void finish(struct fmm *f, struct solver *s)
{
	size_t total = (size_t)s->n[0] * (size_t)s->n[1] * (size_t)s->n[2];
	for (size_t n = 0; n < total; n++)
		s->slow[n] = s->slow[n] < INFINITY ? 1 / s->slow[n] : 0;
	f->rate = s->slow;
	free(s->state);
	free(s->slot);
	free(s->heap_mem);
	slots_free(s);
}

static void march(struct fmm *f, struct solver *s)
{
	while (s->nheap)
		accept_next(f, s);
	finish(f, s);
}

/* The source of a solve from the top: T = 0 on the whole plane
 * z = zmax, KNOWN, its neighbours TRIAL. */
static void start_top(struct fmm *f, struct solver *s)
{
	size_t plane = (size_t)s->n[0] * (size_t)s->n[1];
	size_t top = (size_t)(s->n[2] - 1) * plane;
	for (size_t q = 0; q < plane; q++) {
		f->t[top + q] = 0;
		s->state[top + q] = KNOWN;
	}
	f->accepted = (long)plane;
	for (size_t q = 0; q < plane; q++) {
		int c[3];
		coords(s, top + q, c);
		relax(s, top + q, c, -1);
	}
}

static struct fmm *solve_top(const struct ratefile *r, const int refine[3], int nodal,
			     int linear)
{
	struct solver s;
	struct fmm *f = setup(r, refine, linear, &s);
	s.nodal = nodal;
	start_top(f, &s);
	march(f, &s);
	return f;
}

struct fmm *fmm_solve(const struct ratefile *r, const int refine[3])
{
	return solve_top(r, refine, 0, 0);
}

struct fmm *fmm_solve_linear(const struct ratefile *r, const int refine[3])
{
	return solve_top(r, refine, 0, 1);
}

struct fmm *fmm_solve_nodal(const struct ratefile *r, const int refine[3])
{
	return solve_top(r, refine, 1, 0);
}

/* The sources of a solve from points: the nodes within SEED_CELLS of
 * each of the npts points p, TRIAL at their exact time. */
static void start_points(const struct ratefile *r, struct fmm *f, struct solver *s,
			 const double *p, int npts)
{
	for (int q = 0; q < npts; q++) {
		double x[3];
		int lo[3], hi[3];
		for (int d = 0; d < 3; d++) {
			x[d] = fmin(fmax(p[3 * q + d], f->bounds[2 * d]), f->bounds[2 * d + 1]);
			int near = f->h[d] > 0 ? (int)lround((x[d] - f->bounds[2 * d]) / f->h[d]) : 0;
			lo[d] = near - SEED_CELLS < 0 ? 0 : near - SEED_CELLS;
			hi[d] = near + SEED_CELLS > s->n[d] - 1 ? s->n[d] - 1 : near + SEED_CELLS;
		}
		double sp = slowness(rate_point(r, x));
		int c[3];
		for (c[2] = lo[2]; c[2] <= hi[2]; c[2]++)
			for (c[1] = lo[1]; c[1] <= hi[1]; c[1]++)
				for (c[0] = lo[0]; c[0] <= hi[0]; c[0]++) {
					size_t n = (size_t)c[0] + (size_t)c[1] * (size_t)s->stride[1] +
						   (size_t)c[2] * (size_t)s->stride[2];
					double dist = 0;
					for (int d = 0; d < 3; d++) {
						double e = f->bounds[2 * d] + c[d] * f->h[d] - x[d];
						dist += e * e;
					}
					/* mean of the slownesses at the ends: exact for a
					 * uniform rate, second order for a smooth one */
					double t = sqrt(dist) * 0.5 * (sp + s->slow[n]);
					if (s->slow[n] < INFINITY && t < INFINITY)
						offer(s, n, t, slot_of(s, n));
				}
	}
}

struct fmm *fmm_solve_points(const struct ratefile *r, const int refine[3],
			     const double *p, int npts)
{
	struct solver s;
	struct fmm *f = setup(r, refine, 0, &s);
	s.nodal = 0;
	start_points(r, f, &s, p, npts);
	march(f, &s);
	return f;
}

/* The march of a lazy solve, kept between queries. */
struct fmm_march {
	struct solver s;
};

struct fmm *fmm_solve_lazy(const struct ratefile *r, const int refine[3],
			   const double *p, int npts)
{
	struct fmm_march *mr = xcalloc(1, sizeof *mr);
	struct fmm *f = setup(r, refine, 1, &mr->s);
	mr->s.nodal = 0;
	if (npts > 0)
		start_points(r, f, &mr->s, p, npts);
	else
		start_top(f, &mr->s);
	f->march = mr;
	return f;
}

/* Whether node n of a lazy solve has its final T: KNOWN, or never to be
 * reached (FAR at zero rate: relax and the seeds skip such nodes), or
 * the march is over. */
static int settled(const struct solver *s, size_t n)
{
	return s->state[n] == KNOWN || (s->state[n] == FAR && s->slow[n] == INFINITY) ||
	       s->nheap == 0;
}

double fmm_time_at_settled(struct fmm *f, const double p[3])
{
	struct fmm_march *mr = f->march;
	if (mr) {
		/* the corners fmm_time_at interpolates between (all eight,
		 * whatever their weights) */
		int lo[3], hi[3];
		double w[3];
		fmm_cell(f, p, lo, w);
		for (int d = 0; d < 3; d++)
			hi[d] = f->n[d] < 2 ? lo[d] : lo[d] + 1;
		struct solver *s = &mr->s;
		clock_t c0 = 0;
		int marched = 0;
		for (int k = lo[2]; k <= hi[2]; k++)
			for (int j = lo[1]; j <= hi[1]; j++)
				for (int i = lo[0]; i <= hi[0]; i++) {
					size_t n = (size_t)i + (size_t)j * (size_t)s->stride[1] +
						   (size_t)k * (size_t)s->stride[2];
					if (!settled(s, n) && !marched) {
						c0 = clock();
						marched = 1;
					}
					while (!settled(s, n))
						accept_next(f, s);
				}
		if (marched)
			f->march_s += (double)(clock() - c0) / CLOCKS_PER_SEC;
	}
	return fmm_time_at(f, p);
}

int fmm_auto_refine(const struct ratefile *r)
{
	const double *v = fmt_rate_values(r);
	size_t plane = (size_t)r->nx * (size_t)r->ny;
	double worst = 0;
	for (int k = 0; k + 1 < r->nz; k++)
		for (size_t q = 0; q < plane; q++) {
			double a = v[(size_t)k * plane + q], b = v[(size_t)(k + 1) * plane + q];
			/* zero rates are never reached: no accuracy to win there */
			if (a >= FMM_RATE_FLOOR && b >= FMM_RATE_FLOOR)
				worst = fmax(worst, fabs(log(a / b)));
		}
	double n = ceil(worst / FMM_AUTO_LNSTEP - 1e-9);
	return n < 1 ? 1 : n > FMM_AUTO_MAX ? FMM_AUTO_MAX : (int)n;
}

void fmm_free(struct fmm *f)
{
	if (!f)
		return;
	if (f->march) {
		free(f->march->s.slow);
		free(f->march->s.state);
		free(f->march->s.slot);
		free(f->march->s.heap_mem);
		slots_free(&f->march->s);
		free(f->march);
	}
	free(f->t);
	free(f->rate);
	free(f);
}
