/*
 * profile.c - the output: one plot set per print time, the profile as
 * polylines.  Cell methods give the staircase between etched and
 * unetched cells, fast marching the contour T = t of its arrival times;
 * both are first a soup of segments whose ends carry integer keys (a grid
 * corner, a grid edge), chained here into polylines, so that joining is
 * exact and the output deterministic.
 */
#include "e2.h"

#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void e2_begin_set(struct e2 *e)
{
	double b[4] = {e->x0, e->x1, e->z0, e->z1};
	e->set = fmt_plot_add_set(e->pf, b);
}

void e2_curve(struct e2 *e, int n, const double *xz)
{
	if (n >= 2)
		fmt_plot_add_curve(e->pf, e->set, n, xz);
}

void soup_add(struct segsoup *sp, long ka, const double a[2], long kb, const double b[2])
{
	if (ka == kb)
		return;
	xgrow(&sp->s, &sp->cap, sp->n + 1, sizeof *sp->s);
	struct seg *s = &sp->s[sp->n++];
	s->ka = ka, s->kb = kb;
	memcpy(s->a, a, sizeof s->a);
	memcpy(s->b, b, sizeof s->b);
}

void soup_free(struct segsoup *sp)
{
	free(sp->s);
	memset(sp, 0, sizeof *sp);
}

struct endp { long key; size_t seg; int end; };

static int cmp_endp(const void *a, const void *b)
{
	const struct endp *p = a, *q = b;
	if (p->key != q->key)
		return p->key < q->key ? -1 : 1;
	if (p->seg != q->seg)
		return p->seg < q->seg ? -1 : 1;
	return p->end - q->end;
}

/* first index of key in the sorted end list */
static size_t find_key(const struct endp *ep, size_t n, long key)
{
	size_t lo = 0, hi = n;
	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;
		if (ep[mid].key < key)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

void soup_emit(struct e2 *e, struct segsoup *sp)
{
	size_t n = sp->n;
	if (n == 0)
		return;
	struct endp *ep = xreallocarray(NULL, 2 * n, sizeof *ep);
	for (size_t i = 0; i < n; i++) {
		ep[2 * i] = (struct endp){sp->s[i].ka, i, 0};
		ep[2 * i + 1] = (struct endp){sp->s[i].kb, i, 1};
	}
	qsort(ep, 2 * n, sizeof *ep, cmp_endp);
	unsigned char *used = xcalloc(n, 1);
	double *pts = NULL;
	size_t cap = 0;
	/* two passes: chains from the ends of open curves (keys of odd
	 * degree) first, then what is left (closed curves) */
	for (int pass = 0; pass < 2; pass++) {
		for (size_t q = 0; q < 2 * n; q++) {
			long key = ep[q].key;
			size_t first = find_key(ep, 2 * n, key), deg = 0;
			while (first + deg < 2 * n && ep[first + deg].key == key)
				deg++;
			if (pass == 0 && deg % 2 == 0)
				continue;
			if (used[ep[q].seg])
				continue;
			size_t np = 0;
			const struct seg *s0 = &sp->s[ep[q].seg];
			xgrow(&pts, &cap, 2 * (np + 1), sizeof *pts);
			memcpy(pts, ep[q].end ? s0->b : s0->a, 2 * sizeof *pts);
			np = 1;
			long cur = key;
			for (;;) {
				size_t f = find_key(ep, 2 * n, cur), g;
				for (g = f; g < 2 * n && ep[g].key == cur; g++)
					if (!used[ep[g].seg])
						break;
				if (g >= 2 * n || ep[g].key != cur)
					break;
				const struct seg *s = &sp->s[ep[g].seg];
				used[ep[g].seg] = 1;
				const double *far = ep[g].end ? s->a : s->b;
				cur = ep[g].end ? s->ka : s->kb;
				xgrow(&pts, &cap, 2 * (np + 1), sizeof *pts);
				memcpy(pts + 2 * np, far, 2 * sizeof *pts);
				np++;
			}
			e2_curve(e, (int)np, pts);
		}
	}
	free(pts);
	free(used);
	free(ep);
}

void cells_emit(struct e2 *e, const unsigned char *etched, int nx, int nz, int open_top)
{
	struct segsoup sp = {0};
	double dx = (e->x1 - e->x0) / nx, dz = (e->z1 - e->z0) / nz;
	long w = nx + 1;
#define CORNER(i, k) ((long)(k) * w + (i))
#define PX(i) (e->x0 + (i) * dx)
#define PZ(k) ((k) == nz ? e->z1 : e->z0 + (k) * dz)
	for (int k = 0; k < nz; k++)
		for (int i = 0; i < nx; i++) {
			int me = etched[(size_t)k * nx + i];
			/* vertical edge on the left of cell (i, k) */
			if (i > 0 && me != etched[(size_t)k * nx + i - 1]) {
				double a[2] = {PX(i), PZ(k)}, b[2] = {PX(i), PZ(k + 1)};
				soup_add(&sp, CORNER(i, k), a, CORNER(i, k + 1), b);
			}
			/* horizontal edge below cell (i, k) */
			if (k > 0 && me != etched[(size_t)(k - 1) * nx + i]) {
				double a[2] = {PX(i), PZ(k)}, b[2] = {PX(i + 1), PZ(k)};
				soup_add(&sp, CORNER(i, k), a, CORNER(i + 1, k), b);
			}
			/* the substrate under an etched bottom cell: the profile runs
			 * along it, as the surface methods' stopped nodes do */
			if (k == 0 && me) {
				double a[2] = {PX(i), e->z0}, b[2] = {PX(i + 1), e->z0};
				soup_add(&sp, CORNER(i, 0), a, CORNER(i + 1, 0), b);
			}
			/* the top face of an unetched top cell under the developer */
			if (k == nz - 1 && open_top && !me) {
				double a[2] = {PX(i), e->z1}, b[2] = {PX(i + 1), e->z1};
				soup_add(&sp, CORNER(i, nz), a, CORNER(i + 1, nz), b);
			}
		}
#undef CORNER
#undef PX
#undef PZ
	soup_emit(e, &sp);
	soup_free(&sp);
}

/* The crossing of T = t on the grid edge from node a to node b. */
static void cross(const double *T, size_t a, size_t b, double t, const double pa[2],
		  const double pb[2], double out[2])
{
	double ta = T[a], tb = T[b], u;
	if (!isfinite(ta))
		u = 1;
	else if (!isfinite(tb))
		u = 0;
	else
		u = (t - ta) / (tb - ta);
	if (!(u >= 0)) u = 0;
	if (u > 1) u = 1;
	out[0] = pa[0] + u * (pb[0] - pa[0]);
	out[1] = pa[1] + u * (pb[1] - pa[1]);
}

void contour_emit(struct e2 *e, const double *T, int nx, int nz, double t)
{
	struct segsoup sp = {0};
	double hx = (e->x1 - e->x0) / (nx - 1), hz = (e->z1 - e->z0) / (nz - 1);
	/* edge keys: 2 (k nx + i) the edge to (i+1, k), + 1 the edge to (i, k+1) */
	for (int k = 0; k + 1 < nz; k++)
		for (int i = 0; i + 1 < nx; i++) {
			size_t c[4] = {(size_t)k * nx + i, (size_t)k * nx + i + 1,
				       (size_t)(k + 1) * nx + i + 1, (size_t)(k + 1) * nx + i};
			double p[4][2] = {{e->x0 + i * hx, e->z0 + k * hz},
					  {e->x0 + (i + 1) * hx, e->z0 + k * hz},
					  {e->x0 + (i + 1) * hx, e->z0 + (k + 1) * hz},
					  {e->x0 + i * hx, e->z0 + (k + 1) * hz}};
			/* edges 0: c0-c1, 1: c1-c2, 2: c3-c2, 3: c0-c3 */
			long key[4] = {2L * (long)c[0], 2L * (long)c[1] + 1, 2L * (long)c[3], 2L * (long)c[0] + 1};
			int ea[4] = {0, 1, 3, 0}, eb[4] = {1, 2, 2, 3};
			int in[4], mask = 0;
			for (int q = 0; q < 4; q++) {
				in[q] = T[c[q]] <= t;   /* etched */
				mask |= in[q] << q;
			}
			if (mask == 0 || mask == 15)
				continue;
			double x[4][2];
			int has[4] = {0};
			for (int q = 0; q < 4; q++)
				if (in[ea[q]] != in[eb[q]]) {
					cross(T, c[ea[q]], c[eb[q]], t, p[ea[q]], p[eb[q]], x[q]);
					has[q] = 1;
				}
			int list[4], m = 0;
			for (int q = 0; q < 4; q++)
				if (has[q])
					list[m++] = q;
			if (m == 2) {
				soup_add(&sp, key[list[0]], x[list[0]], key[list[1]], x[list[1]]);
			} else if (m == 4) {
				/* saddle: the cell centre's mean decides which corners join */
				double mean = 0.25 * (T[c[0]] + T[c[1]] + T[c[2]] + T[c[3]]);
				int centre_in = mean <= t;
				if (centre_in == in[0]) {
					/* corners 0 and 2 joined: cut off corners 1 and 3 */
					soup_add(&sp, key[0], x[0], key[1], x[1]);
					soup_add(&sp, key[2], x[2], key[3], x[3]);
				} else {
					soup_add(&sp, key[0], x[0], key[3], x[3]);
					soup_add(&sp, key[1], x[1], key[2], x[2]);
				}
			}
		}
	/* where the front has reached the substrate the profile runs along
	 * it (keys of nodes: negative, apart from the edges') */
	for (int i = 0; i + 1 < nx; i++) {
		int a = T[i] <= t, b = T[i + 1] <= t;
		double pa[2] = {e->x0 + i * hx, e->z0}, pb[2] = {e->x0 + (i + 1) * hx, e->z0}, x[2];
		if (a && b) {
			soup_add(&sp, -1L - i, pa, -2L - i, pb);
		} else if (a || b) {
			cross(T, (size_t)i, (size_t)i + 1, t, pa, pb, x);
			if (a)
				soup_add(&sp, -1L - i, pa, 2L * i, x);
			else
				soup_add(&sp, 2L * i, x, -2L - i, pb);
		}
	}
	soup_emit(e, &sp);
	soup_free(&sp);
}
