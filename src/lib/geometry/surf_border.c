/*
 * surf_border.c - the open border of a triangle soup (see surf.h): the
 * edges that only one triangle has, away from the faces of the box.  A
 * surface that etch writes covers the box and ends only on its side
 * walls; an open border inside the box is a gap (delooping leaves some
 * where it cannot join two sheets), where "which side is resist" is only
 * as good as the ray test.
 *
 * Triangles are a soup, so vertices are identified by their coordinates
 * (equal bits, -0 taken as 0) through a hash table, each edge becomes a
 * pair of vertex numbers, and the pairs are radix-sorted: an edge found
 * once is open.  Time and memory grow with the number of triangles.
 *
 * For measure, the open border is also looked at one horizontal section
 * at a time (surf_border_at): the open edges crossing the plane are the
 * free ends of the section's curves, joined each to its nearest (found
 * in x order, stopping when the x distance alone is larger than the best)
 * into the chords of the gaps, and the open edges above the plane are
 * gaps the vertical-ray test looks through; each is tested against a
 * rectangle by clipping (Liang-Barsky).  The median edge length, for
 * the caller's tolerance, is found by selection, not sorting.
 */
#include "surf.h"
#include "util.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* A vertex is on a face of the box within this fraction of its diagonal. */
#define FACE_EPS 1e-9
/* Vertices are the same when their coordinates round to the same
 * multiple of this fraction of the diagonal. */
#define SNAP 1e-10

static uint64_t bits(double v)
{
	uint64_t u;
	v += 0.0; /* -0 -> +0 */
	memcpy(&u, &v, sizeof u);
	return u;
}

/* A coordinate rounded to a multiple of q (vertices that differ by
 * rounding, as two cells computing the same edge point may, meet). */
static uint64_t snapped(double v, double q)
{
	return bits(nearbyint(v / q));
}

static uint64_t mix(uint64_t h)
{
	h ^= h >> 33;
	h *= 0xff51afd7ed558ccdULL;
	h ^= h >> 33;
	h *= 0xc4ceb9fe1a85ec53ULL;
	h ^= h >> 33;
	return h;
}

static void radix_sort(uint64_t *a, size_t n)
{
	uint64_t *tmp = xreallocarray(NULL, n ? n : 1, sizeof *tmp), all = 0;
	size_t *count = xreallocarray(NULL, 65537, sizeof *count);
	for (size_t i = 0; i < n; i++)
		all |= a[i];
	for (int shift = 0; shift < 64 && (all >> shift) > 0; shift += 16) {
		memset(count, 0, 65537 * sizeof *count);
		for (size_t i = 0; i < n; i++)
			count[((a[i] >> shift) & 0xffff) + 1]++;
		for (int d = 0; d < 65536; d++)
			count[d + 1] += count[d];
		for (size_t i = 0; i < n; i++)
			tmp[count[(a[i] >> shift) & 0xffff]++] = a[i];
		memcpy(a, tmp, n * sizeof *a);
	}
	free(count);
	free(tmp);
}

static int on_face(const double *box, const double *p, const double *q, double eps)
{
	for (int k = 0; k < 3; k++)
		for (int side = 0; side < 2; side++)
			if (fabs(p[k] - box[2 * k + side]) <= eps && fabs(q[k] - box[2 * k + side]) <= eps)
				return 1;
	return 0;
}

/* The open edges as pairs of vertex references (3 t + k), in the order of
 * the sorted vertex-number pairs: a fixed order, whatever the hash. */
static size_t open_pairs(const struct surf *s, uint64_t **out)
{
	size_t nref = 3 * s->ntri;
	*out = NULL;
	if (nref == 0 || nref >= UINT32_MAX)
		return 0;
	const double *box = s->box;
	double w[3] = {box[1] - box[0], box[3] - box[2], box[5] - box[4]};
	double diag = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
	double quant = SNAP * diag, eps = FACE_EPS * diag;
	/* vertex numbers: the first reference with those coordinates */
	size_t cap = 1;
	while (cap < 2 * nref)
		cap *= 2;
	uint32_t *slot = xreallocarray(NULL, cap, sizeof *slot);
	memset(slot, 0xff, cap * sizeof *slot);
	uint32_t *id = xreallocarray(NULL, nref, sizeof *id);
	for (size_t r = 0; r < nref; r++) {
		const double *p = s->v + 3 * r;
		uint64_t h = mix(snapped(p[0], quant) ^ mix(snapped(p[1], quant) ^ mix(snapped(p[2], quant))));
		size_t i = (size_t)h & (cap - 1);
		for (;; i = (i + 1) & (cap - 1)) {
			if (slot[i] == UINT32_MAX) {
				slot[i] = (uint32_t)r;
				id[r] = (uint32_t)r;
				break;
			}
			const double *q = s->v + 3 * (size_t)slot[i];
			if (snapped(p[0], quant) == snapped(q[0], quant) &&
			    snapped(p[1], quant) == snapped(q[1], quant) &&
			    snapped(p[2], quant) == snapped(q[2], quant)) {
				id[r] = slot[i];
				break;
			}
		}
	}
	free(slot);
	/* edges as (smaller, larger) vertex number */
	uint64_t *e = xreallocarray(NULL, nref, sizeof *e);
	for (size_t t = 0; t < s->ntri; t++)
		for (int k = 0; k < 3; k++) {
			uint64_t a = id[3 * t + k], b = id[3 * t + (k + 1) % 3];
			e[3 * t + k] = a < b ? a << 32 | b : b << 32 | a;
		}
	free(id);
	radix_sort(e, nref);
	size_t n = 0;
	for (size_t i = 0; i < nref;) {
		size_t j = i + 1;
		while (j < nref && e[j] == e[i])
			j++;
		uint64_t a = e[i] >> 32, b = e[i] & 0xffffffffu;
		if (j - i == 1 && a != b && !on_face(box, s->v + 3 * a, s->v + 3 * b, eps))
			e[n++] = e[i];
		i = j;
	}
	*out = e;
	return n;
}

static double dist3(const double *p, const double *q)
{
	return sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
		    (p[2] - q[2]) * (p[2] - q[2]));
}

/* The k-th smallest of a[0..n-1] (a is reordered): Hoare's selection,
 * the pivot the median of the first, middle and last. */
static double select_kth(double *a, size_t n, size_t k)
{
	size_t lo = 0, hi = n - 1;
	while (lo < hi) {
		double x = a[lo], y = a[lo + (hi - lo) / 2], z = a[hi];
		double piv = x < y ? (y < z ? y : x < z ? z : x) : (x < z ? x : y < z ? z : y);
		size_t i = lo, j = hi;
		while (i <= j) {
			while (a[i] < piv)
				i++;
			while (a[j] > piv)
				j--;
			if (i <= j) {
				double t = a[i];
				a[i] = a[j];
				a[j] = t;
				i++;
				if (j == 0)
					break;
				j--;
			}
		}
		if (k <= j)
			hi = j;
		else if (k >= i)
			lo = i;
		else
			return a[k];
	}
	return a[k];
}

void surf_border_find(const struct surf *s, struct surf_border *b)
{
	uint64_t *e;
	size_t n = open_pairs(s, &e);
	b->n = n;
	b->e = xreallocarray(NULL, n ? 6 * n : 1, sizeof *b->e);
	b->length = 0;
	for (size_t i = 0; i < n; i++) {
		memcpy(b->e + 6 * i, s->v + 3 * (size_t)(e[i] >> 32), 3 * sizeof *b->e);
		memcpy(b->e + 6 * i + 3, s->v + 3 * (size_t)(e[i] & 0xffffffffu), 3 * sizeof *b->e);
		b->length += dist3(b->e + 6 * i, b->e + 6 * i + 3);
	}
	free(e);
	/* the median length of the triangles' edges, each counted once per
	 * triangle it belongs to */
	size_t nref = 3 * s->ntri;
	double *len = xreallocarray(NULL, nref ? nref : 1, sizeof *len);
	for (size_t r = 0; r < nref; r++) {
		size_t t = r / 3, k = r % 3;
		len[r] = dist3(s->v + 9 * t + 3 * k, s->v + 9 * t + 3 * ((k + 1) % 3));
	}
	b->median_edge = nref ? select_kth(len, nref, nref / 2) : 0;
	free(len);
}

void surf_border_free(struct surf_border *b)
{
	free(b->e);
	b->e = NULL;
	b->n = 0;
}

double surf_open_border(const struct surf *s)
{
	struct surf_border b;
	surf_border_find(s, &b);
	double open = b.length;
	surf_border_free(&b);
	return open;
}

/* Whether segment a-b (2D) meets the rectangle r (xmin xmax ymin ymax):
 * the segment clipped to each slab in turn (Liang-Barsky). */
static int seg_meets_rect(const double *a, const double *b, const double *r)
{
	double t0 = 0, t1 = 1;
	for (int k = 0; k < 2; k++) {
		double d = b[k] - a[k], lo = r[2 * k], hi = r[2 * k + 1];
		if (d == 0) {
			if (a[k] < lo || a[k] > hi)
				return 0;
			continue;
		}
		double ta = (lo - a[k]) / d, tb = (hi - a[k]) / d;
		if (ta > tb) {
			double t = ta;
			ta = tb;
			tb = t;
		}
		t0 = fmax(t0, ta);
		t1 = fmin(t1, tb);
		if (t0 > t1)
			return 0;
	}
	return 1;
}

struct end {
	double x, y;
	size_t i;           /* its place in border order: ties broken by it */
};

static int by_x(const void *p, const void *q)
{
	const struct end *a = p, *b = q;
	if (a->x != b->x)
		return (a->x > b->x) - (a->x < b->x);
	return (a->i > b->i) - (a->i < b->i);
}

/* The free ends of the section at z: where open edges cross the plane
 * (one end at or above z, the other below, as surf_section takes a
 * vertex on the plane), sorted by x. */
static size_t free_ends(const struct surf_border *b, double z, struct end **out)
{
	struct end *e = NULL;
	size_t n = 0, cap = 0;
	for (size_t i = 0; i < b->n; i++) {
		const double *p = b->e + 6 * i, *q = p + 3;
		if ((p[2] >= z) == (q[2] >= z))
			continue;
		if (p[2] > q[2]) {
			const double *r = p;
			p = q;
			q = r;
		}
		double f = (z - p[2]) / (q[2] - p[2]);
		xgrow(&e, &cap, n + 1, sizeof *e);
		e[n] = (struct end){p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1]), n};
		n++;
	}
	if (n)
		qsort(e, n, sizeof *e, by_x);
	*out = e;
	return n;
}

/* The nearest other free end to e[i] (ties: the first in border order),
 * scanning outwards in x until the x distance alone exceeds the best;
 * i itself if it is alone. */
static size_t nearest_end(const struct end *e, size_t n, size_t i)
{
	size_t best = i;
	double bd = INFINITY;
	for (int dir = -1; dir <= 1; dir += 2)
		for (size_t j = i; dir < 0 ? j-- > 0 : ++j < n;) {
			double dx = e[j].x - e[i].x, dy = e[j].y - e[i].y;
			if (dx * dx > bd)
				break;
			double d = dx * dx + dy * dy;
			if (d < bd || (d == bd && e[j].i < e[best].i)) {
				bd = d;
				best = j;
			}
		}
	return best;
}

/* Counts gap a-c if it meets rect, keeping the one whose middle is
 * nearest (px, py). */
static void consider(struct surf_gap *g, const double *a, const double *c, const double *rect,
		     double px, double py, double *best)
{
	if (!seg_meets_rect(a, c, rect))
		return;
	g->n++;
	double mx = 0.5 * (a[0] + c[0]) - px, my = 0.5 * (a[1] + c[1]) - py;
	if (mx * mx + my * my < *best) {
		*best = mx * mx + my * my;
		memcpy(g->a, a, 2 * sizeof *a);
		memcpy(g->b, c, 2 * sizeof *c);
	}
}

size_t surf_border_at(const struct surf_border *b, double z, const double *rect,
		      double px, double py, struct surf_gap *g)
{
	struct end *e;
	size_t n = free_ends(b, z, &e);
	double best = INFINITY;
	g->n = 0;
	g->a[0] = g->a[1] = g->b[0] = g->b[1] = 0;
	for (size_t i = 0; i < n; i++) {
		size_t j = nearest_end(e, n, i);
		/* a pair that are each other's nearest is one gap, taken once */
		if (j < i && nearest_end(e, n, j) == i)
			continue;
		double a[2] = {e[i].x, e[i].y}, c[2] = {e[j].x, e[j].y};
		consider(g, a, c, rect, px, py, &best);
	}
	free(e);
	/* open edges above the plane: the ray test looks up through them */
	for (size_t i = 0; i < b->n; i++) {
		const double *p = b->e + 6 * i, *q = p + 3;
		if (p[2] < z && q[2] < z)
			continue;
		if (p[2] < q[2]) {
			const double *r = p;
			p = q;
			q = r;
		}
		/* p is above: the part from p down to the plane */
		double f = q[2] >= z ? 1 : (p[2] - z) / (p[2] - q[2]);
		double a[2] = {p[0], p[1]};
		double c[2] = {p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1])};
		consider(g, a, c, rect, px, py, &best);
	}
	return g->n;
}
