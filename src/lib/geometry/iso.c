/*
 * iso.c - marching tetrahedra (see iso.h).
 *
 * Closing the surface at the box: the grid is padded, virtually, by one
 * layer of points a hair (PAD_REL of a cell) outside the box faces, with
 * the value +infinity.  A crossing between a face point and the pad then
 * falls exactly on the face point (t = (level - f) / inf = 0), so the cap,
 * which adjoining faces share along the box edges, is
 * the part of the face where f < level, triangulated consistently with the
 * interior.  The pad's thickness keeps the tetrahedra non-degenerate, so
 * the orientation test below stays exact: for a linear function on a
 * tetrahedron, the centroid of the points above the level lies above the
 * centroid of those below, and the triangle normal is parallel to the
 * gradient; walls of the pad (two corners on one face point) are dropped.
 */
#include "iso.h"

#include "vec3.h"

#include <math.h>
#include <stddef.h>

struct grid {
	const double *f;
	const double *w;        /* speeds per point, or NULL: linear crossings */
	int n[3];
	const double *b;
	double level;
	int closed;
};

/* value and position of (padded) grid point i, j, k */
/* the pad's distance outside the box, as a fraction of a cell: small
 * enough that snapping moves no visible point, large enough that the
 * padded tetrahedra are far from degenerate in double precision */
#define PAD_REL 1e-6

static double at(const struct grid *g, const int idx[3], double p[3], double *w)
{
	*w = 0;
	int out = 0;
	for (int d = 0; d < 3; d++) {
		int i = idx[d];
		double h = (g->b[2 * d + 1] - g->b[2 * d]) / (g->n[d] - 1), off = 0;
		if (i < 0) { i = 0; out = 1; off = -PAD_REL * h; }
		if (i >= g->n[d]) { i = g->n[d] - 1; out = 1; off = PAD_REL * h; }
		/* the same expression as fmt_rate_x and fmt_contour_x */
		p[d] = g->b[2 * d] + (g->b[2 * d + 1] - g->b[2 * d]) * i / (g->n[d] - 1) + off;
	}
	if (out)
		return INFINITY; /* crossings towards the pad fall on the face point */
	size_t k = ((size_t)idx[2] * (size_t)g->n[1] + (size_t)idx[1]) * (size_t)g->n[0] + (size_t)idx[0];
	if (g->w)
		*w = g->w[k];
	return g->f[k];
}

/* Swaps the ends (value f, speed w) so that a has the lower value; 1 if
 * it did.  The edge model is evaluated from that end, so that the
 * tetrahedra sharing an edge, which may name its ends in either order,
 * get the same point. */
static int lower_first(double *fa, double *wa, double *fb, double *wb)
{
	if (!(*fb < *fa))
		return 0;
	double x = *fa;
	*fa = *fb;
	*fb = x;
	x = *wa;
	*wa = *wb;
	*wb = x;
	return 1;
}

/* The fraction of the way from a to b where f = level.  Without speeds
 * f is taken as linear along the edge.  With speeds (wa, wb > 0, linear
 * along the edge) f is taken as an arrival time: a locally plane front
 * crosses the edge at a fixed angle, so f grows as the integral of 1/w
 * along it, f(s) - fa = (fb - fa) ln(w(s)/wa) / ln(wb/wa), whose inverse
 * gives s = (r^phi - 1)/(r - 1), r = wb/wa, phi the linear fraction.
 * It is computed from the end below the level, so the tetrahedra
 * sharing an edge, which may name its ends in either order, agree. */
double iso_crossing(double fa, double wa, double fb, double wb, double level)
{
	if (!(wa > 0 && wb > 0 && isfinite(wa) && isfinite(wb)))
		return (level - fa) / (fb - fa);
	int flip = lower_first(&fa, &wa, &fb, &wb);
	double phi = (level - fa) / (fb - fa), lr = log(wb / wa);
	if (fabs(lr) > 1e-12)
		phi = expm1(phi * lr) / expm1(lr);
	return flip ? 1 - phi : phi;
}

/* The inverse of iso_crossing: the level whose crossing lies at fraction
 * s of the way from a to b, by the same edge model. */
double iso_value_at(double fa, double wa, double fb, double wb, double s)
{
	if (!(wa > 0 && wb > 0 && isfinite(wa) && isfinite(wb)))
		return fa + s * (fb - fa);
	if (lower_first(&fa, &wa, &fb, &wb))
		s = 1 - s;
	double lr = log(wb / wa), phi = s;
	if (fabs(lr) > 1e-12)
		phi = log1p(s * expm1(lr)) / lr;
	return fa + phi * (fb - fa);
}

static void lerp(const double *a, double fa, double wa, const double *b, double fb, double wb,
		 double level, double *out)
{
	if (isinf(fa) || isinf(fb)) {   /* a pad point: the crossing is its partner */
		const double *c = isinf(fa) ? b : a;
		for (int d = 0; d < 3; d++)
			out[d] = c[d];
		return;
	}
	double t = iso_crossing(fa, wa, fb, wb, level);
	for (int d = 0; d < 3; d++)
		out[d] = a[d] + t * (b[d] - a[d]);
}

/* emits tri, flipped if needed so its normal points along up */
static long out(double *tri, const double *up, iso_emit emit, void *ctx, double scale,
		const double *b)
{
	if (b)  /* snap crossings in the pad onto the box faces */
		for (int q = 0; q < 3; q++)
			for (int d = 0; d < 3; d++)
				tri[3 * q + d] = fmin(fmax(tri[3 * q + d], b[2 * d]), b[2 * d + 1]);
	double u[3], v[3], c[3];
	vec3_sub(tri + 3, tri, u);
	vec3_sub(tri + 6, tri, v);
	vec3_cross(u, v, c);
	/* Dropped: a triangle two of whose corners coincide, to a billionth of
	 * a cell (the walls of the pad, whose crossings fall on the same face
	 * point, and crossings at a grid point whose value is the level), as
	 * welding would make it a line.  Not dropped for being small: where
	 * the level passes a hair from a grid point the triangles around it
	 * are legitimately tiny, and dropping them would leave a hole in the
	 * surface. */
	double w[3], e2 = 1e-9 * scale;
	vec3_sub(tri + 6, tri + 3, w);
	if (fmin(vec3_dot(u, u), fmin(vec3_dot(v, v), vec3_dot(w, w))) <= e2 * e2)
		return 0;
	if (vec3_dot(c, up) < 0)
		for (int d = 0; d < 3; d++) {
			double s = tri[3 + d];
			tri[3 + d] = tri[6 + d];
			tri[6 + d] = s;
		}
	emit(ctx, tri);
	return 1;
}

static long tet(const double p[4][3], const double v[4], const double w[4], double level,
		iso_emit emit, void *ctx, double scale, const double *box)
{
	int in[4], nin = 0;
	for (int i = 0; i < 4; i++) {
		in[i] = v[i] < level;
		nin += in[i];
	}
	if (nin == 0 || nin == 4)
		return 0;
	/* "up": from the centroid of the points below to those above */
	double cb[3] = {0, 0, 0}, ca[3] = {0, 0, 0}, up[3];
	for (int i = 0; i < 4; i++)
		for (int d = 0; d < 3; d++) {
			if (in[i])
				cb[d] += p[i][d] / nin;
			else
				ca[d] += p[i][d] / (4 - nin);
		}
	for (int d = 0; d < 3; d++)
		up[d] = ca[d] - cb[d];
	double tri[9];
	if (nin == 1 || nin == 3) {
		int lone = 0;
		for (int i = 0; i < 4; i++)
			if (in[i] == (nin == 1))
				lone = i;
		int m = 0;
		for (int i = 0; i < 4; i++)
			if (i != lone)
				lerp(p[lone], v[lone], w[lone], p[i], v[i], w[i], level,
				     tri + 3 * m++);
		return out(tri, up, emit, ctx, scale, box);
	}
	/* two in, two out: a quadrilateral a0-b0, a0-b1, a1-b1, a1-b0 */
	int a[2], b[2], na = 0, nb = 0;
	for (int i = 0; i < 4; i++) {
		if (in[i])
			a[na++] = i;
		else
			b[nb++] = i;
	}
	double q[4][3];
	lerp(p[a[0]], v[a[0]], w[a[0]], p[b[0]], v[b[0]], w[b[0]], level, q[0]);
	lerp(p[a[0]], v[a[0]], w[a[0]], p[b[1]], v[b[1]], w[b[1]], level, q[1]);
	lerp(p[a[1]], v[a[1]], w[a[1]], p[b[1]], v[b[1]], w[b[1]], level, q[2]);
	lerp(p[a[1]], v[a[1]], w[a[1]], p[b[0]], v[b[0]], w[b[0]], level, q[3]);
	long n = 0;
	for (int d = 0; d < 3; d++) {
		tri[d] = q[0][d], tri[3 + d] = q[1][d], tri[6 + d] = q[2][d];
	}
	n += out(tri, up, emit, ctx, scale, box);
	for (int d = 0; d < 3; d++) {
		tri[d] = q[0][d], tri[3 + d] = q[2][d], tri[6 + d] = q[3][d];
	}
	n += out(tri, up, emit, ctx, scale, box);
	return n;
}

long iso_surface(const double *f, int nx, int ny, int nz, const double bounds[6],
		 double level, int closed, iso_emit emit, void *ctx)
{
	return iso_surface_speed(f, NULL, nx, ny, nz, bounds, level, closed, emit, ctx);
}

long iso_surface_speed(const double *f, const double *w, int nx, int ny, int nz,
		       const double bounds[6], double level, int closed, iso_emit emit, void *ctx)
{
	int lo = closed ? -1 : 0, n[3] = {nx, ny, nz};
	int c0[3] = {lo, lo, lo}, c1[3];
	for (int d = 0; d < 3; d++)
		c1[d] = n[d] - 1 - lo;
	return iso_surface_window(f, w, nx, ny, nz, bounds, level, closed, c0, c1, emit, ctx);
}

long iso_surface_window(const double *f, const double *w, int nx, int ny, int nz,
			const double bounds[6], double level, int closed, const int c0[3],
			const int c1[3], iso_emit emit, void *ctx)
{
	struct grid g = {f, w, {nx, ny, nz}, bounds, level, closed};
	/* the six tetrahedra of the Kuhn split: 0, e_a, e_a+e_b, 1 for each
	 * order (a, b, c) of the axes; corners numbered x + 2y + 4z */
	static const int kuhn[6][4] = {
		{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
		{0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7},
	};
	double scale = 0;
	for (int d = 0; d < 3; d++)
		scale = fmax(scale, (bounds[2 * d + 1] - bounds[2 * d]) / (g.n[d] - 1));
	/* the cells asked for, within those the grid (and its pad) has */
	int lo = closed ? -1 : 0, b0[3], b1[3];
	for (int d = 0; d < 3; d++) {
		b0[d] = c0[d] < lo ? lo : c0[d];
		b1[d] = c1[d] > g.n[d] - 1 - lo ? g.n[d] - 1 - lo : c1[d];
	}
	long count = 0;
	for (int k = b0[2]; k < b1[2]; k++)
		for (int j = b0[1]; j < b1[1]; j++)
			for (int i = b0[0]; i < b1[0]; i++) {
				double cp[8][3], cv[8], cw[8];
				int below = 0;
				for (int c = 0; c < 8; c++) {
					int idx[3] = {i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)};
					cv[c] = at(&g, idx, cp[c], &cw[c]);
					below += cv[c] < level;
				}
				if (below == 0 || below == 8)
					continue;       /* no tetrahedron of the cell is cut */
				for (int t = 0; t < 6; t++) {
					double p[4][3], v[4], sw[4];
					for (int q = 0; q < 4; q++) {
						for (int d = 0; d < 3; d++)
							p[q][d] = cp[kuhn[t][q]][d];
						v[q] = cv[kuhn[t][q]];
						sw[q] = cw[kuhn[t][q]];
					}
					count += tet((const double (*)[3])p, v, sw, level, emit, ctx, scale,
						     closed ? bounds : NULL);
				}
			}
	return count;
}
