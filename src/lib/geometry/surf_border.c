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

double surf_open_border(const struct surf *s)
{
	size_t nref = 3 * s->ntri;
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
	double open = 0;
	for (size_t i = 0; i < nref;) {
		size_t j = i + 1;
		while (j < nref && e[j] == e[i])
			j++;
		const double *p = s->v + 3 * (size_t)(e[i] >> 32), *q = s->v + 3 * (size_t)(e[i] & 0xffffffffu);
		if (j - i == 1 && !on_face(box, p, q, eps) && (e[i] >> 32) != (e[i] & 0xffffffffu))
			open += sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
				     (p[2] - q[2]) * (p[2] - q[2]));
		i = j;
	}
	free(e);
	return open;
}
