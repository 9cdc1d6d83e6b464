/*
 * deloop_util.h - helpers shared by the deloop tests (tests/etch/deloop*.c):
 * an independent self-intersection counter, areas and volumes of meshes
 * and of the fast-marching surface, and default etch options.
 *
 * The counter does not use deloop.c's grid nor its crossing test: the
 * triangles are sorted by the low x of their boxes and every segment is
 * tested, by the Moller-Trumbore ray-triangle algorithm, against the
 * triangles whose x range meets its own.  A segment counts as crossing a
 * triangle it does not touch when the crossing point lies inside the
 * triangle by more than EDGE_MARGIN in barycentric terms and inside the
 * segment by as much (touching is not intersecting).
 */
#include "deloop.h"
#include "etch.h"
#include "fmm.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EDGE_MARGIN 1e-7

/* A triangle's box: x bounds (the sweep's order), y and z bounds (a
 * segment whose box misses them cannot cross it: a rejection only). */
struct xbox { double lo, hi, ylo, yhi, zlo, zhi; int t; };

static int cmp_xbox(const void *a, const void *b)
{
	const struct xbox *p = a, *q = b;
	return (p->lo > q->lo) - (p->lo < q->lo);
}

static void sub3(const double *a, const double *b, double *c)
{
	c[0] = a[0] - b[0]; c[1] = a[1] - b[1]; c[2] = a[2] - b[2];
}

static void cross3(const double *a, const double *b, double *c)
{
	c[0] = a[1] * b[2] - a[2] * b[1];
	c[1] = a[2] * b[0] - a[0] * b[2];
	c[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot3(const double *a, const double *b)
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Moller-Trumbore: segment p + s (q - p), s in (m, 1 - m), against the
 * triangle's interior shrunk by m in barycentric coordinates. */
static int mt_cross(const double *p, const double *q, const double *a, const double *b,
		    const double *c, double mg)
{
	double d[3], e1[3], e2[3], h[3], sv[3], qv[3];
	sub3(q, p, d);
	sub3(b, a, e1);
	sub3(c, a, e2);
	cross3(d, e2, h);
	double det = dot3(e1, h);
	/* a segment in the triangle's plane (det, the sine of the angle
	 * between them times the lengths, at rounding level) only touches
	 * it, as deloop.c counts it; u and v would be rounding noise */
	if (fabs(det) <= 1e-12 * sqrt(dot3(d, d) * dot3(e1, e1) * dot3(e2, e2)))
		return 0;
	double inv = 1 / det;
	sub3(p, a, sv);
	double u = dot3(sv, h) * inv;
	if (u < mg || u > 1 - mg)
		return 0;
	cross3(sv, e1, qv);
	double v = dot3(d, qv) * inv;
	if (v < mg || u + v > 1 - mg)
		return 0;
	double s = dot3(e2, qv) * inv;
	return s > mg && s < 1 - mg;
}

/* Segment/triangle crossings of m, touching pairs excluded. */
static inline long crossings_independent(const struct mesh *m)
{
	struct xbox *bx = xreallocarray(NULL, m->ntri + 1, sizeof *bx);
	size_t n = 0;
	double wmax = 0;
	for (size_t t = 0; t < m->ntri; t++) {
		if (!m->tri[t].alive)
			continue;
		double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
		for (int j = 0; j < 3; j++)
			for (int d = 0; d < 3; d++) {
				lo[d] = fmin(lo[d], m->node[m->tri[t].n[j]].p[d]);
				hi[d] = fmax(hi[d], m->node[m->tri[t].n[j]].p[d]);
			}
		bx[n++] = (struct xbox){lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], (int)t};
		wmax = fmax(wmax, hi[0] - lo[0]);
	}
	qsort(bx, n, sizeof *bx, cmp_xbox);
	long count = 0;
	for (size_t s = 0; s < m->nseg; s++) {
		const struct segment *sg = &m->seg[s];
		if (!sg->alive)
			continue;
		const double *p = m->node[sg->n[0]].p, *q = m->node[sg->n[1]].p;
		double lo = fmin(p[0], q[0]), hi = fmax(p[0], q[0]);
		/* first box with low x >= lo - wmax */
		size_t a = 0, b = n;
		while (a < b) {
			size_t mid = (a + b) / 2;
			if (bx[mid].lo < lo - wmax)
				a = mid + 1;
			else
				b = mid;
		}
		for (size_t k = a; k < n && bx[k].lo <= hi; k++) {
			if (bx[k].hi < lo || bx[k].yhi < fmin(p[1], q[1]) || bx[k].ylo > fmax(p[1], q[1]) ||
			    bx[k].zhi < fmin(p[2], q[2]) || bx[k].zlo > fmax(p[2], q[2]))
				continue;
			const struct triangle *tr = &m->tri[bx[k].t];
			int touch = 0;
			for (int j = 0; j < 3; j++)
				touch |= tr->n[j] == sg->n[0] || tr->n[j] == sg->n[1];
			if (!touch && mt_cross(p, q, m->node[tr->n[0]].p, m->node[tr->n[1]].p,
					       m->node[tr->n[2]].p, EDGE_MARGIN))
				count++;
		}
	}
	free(bx);
	return count;
}

/* Area (um^2) of a triangle and its contribution to the developed volume
 * (um^3): by the divergence theorem with F = (0, 0, z - zmax), which
 * vanishes on the resist top and is parallel to the side walls, the
 * volume between the top and a surface oriented towards undeveloped
 * resist is the sum of (mean z - zmax) times the z component of the
 * triangle's area vector (exact: z is linear on a triangle). */
static void tri_area_volume(const double *a, const double *b, const double *c, double zmax,
			    double *area, double *vol)
{
	double u[3], v[3], n[3];
	sub3(b, a, u);
	sub3(c, a, v);
	cross3(u, v, n);
	*area += 0.5 * sqrt(dot3(n, n));
	*vol += ((a[2] + b[2] + c[2]) / 3 - zmax) * 0.5 * n[2];
}

static inline void mesh_area_volume(const struct mesh *m, double zmax, double *area, double *vol)
{
	*area = *vol = 0;
	for (size_t t = 0; t < m->ntri; t++)
		if (m->tri[t].alive)
			tri_area_volume(m->node[m->tri[t].n[0]].p, m->node[m->tri[t].n[1]].p,
					m->node[m->tri[t].n[2]].p, zmax, area, vol);
}

struct av { double zmax, area, vol; };

static void av_emit(void *ctx, const double tri[9])
{
	struct av *s = ctx;
	tri_area_volume(tri, tri + 3, tri + 6, s->zmax, &s->area, &s->vol);
}

/* The same for the fast-marching surface T = t (normals towards
 * undeveloped resist, as the mesh's). */
static inline void fmm_area_volume(const struct fmm *fm, double t, double *area, double *vol)
{
	struct av s = {fm->bounds[5], 0, 0};
	fmm_surface(fm, t, av_emit, &s);
	*area = s.area;
	*vol = s.vol;
}

static inline struct etch_opts default_opts(double et, double dt, double seg)
{
	struct etch_opts o;
	memset(&o, 0, sizeof o);
	o.et = et;
	o.dt = dt;
	o.seg = seg;
	o.smax = ETCH_SMAX;
	o.smin = ETCH_SMIN;
	o.rl = ETCH_RL;
	o.clip_every = ETCH_CLIP;
	o.cut_axis = -1;
	o.check = 1;
	o.quiet = 1;
	return o;
}

/* Thesis Figure 8.13's two seeds, (0, 0, 0) and (shift, 1, shift), grown
 * at 1 um/s with steps of 0.1 s for et seconds in a box around both,
 * delooped at 0.8 s (and at et): the mesh, with *r (free it after the
 * mesh) and the run's statistics. */
static inline struct mesh *two_seed_run(double et, double shift, struct ratefile **r,
					struct etch_stats *st)
{
	double b[6] = {-1.5, 1.5, -1.5, 2.5, -1.5, 1.5};
	*r = fmt_rate_new(31, 41, 31, b);
	double *v = fmt_rate_values(*r);
	for (size_t i = 0; i < (size_t)31 * 41 * 31; i++)
		v[i] = 1;
	struct rfield f;
	fmt_rate_field(&f, *r, "uniform");
	struct etch_opts o = default_opts(et, 0.1, 0.1);
	o.pt = 0.8;
	o.deloop = 1;
	o.rate = *r;
	o.seed = 2;
	double c[2][3] = {{0, 0, 0}, {shift, 1, shift}};
	memcpy(o.seedp, c, sizeof c);
	memset(st, 0, sizeof *st);
	return etch_run(&f, &o, st);
}

