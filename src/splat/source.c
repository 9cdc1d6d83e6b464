/*
 * source.c - the effective source and the source integral of the
 * transmission cross coefficients (Hopkins 1953; thesis 2.2.1).
 *
 * Every source shape is a signed sum of uniform discs (an annulus is the
 * outer disc minus the inner one, poles are separate discs), so each TCC
 * is a sum of integrals over the intersection of three discs: a source
 * disc and the two pupils shifted by the orders, centres -f' and -f''.
 * A plain grid of source points converges slowly, because the integrand
 * jumps where orders enter and leave the pupil.  Here the region is
 * integrated exactly instead:
 *   - across (y): the range is cut at every circle top and bottom and at
 *     every point where two circles cross, so that in each piece the
 *     row's ends are each one circle arc; the substitution
 *     y = mid + half sin(t) turns the square-root ends of the arcs into
 *     smooth functions, and Gauss-Legendre in t converges exponentially;
 *   - along (x): the row is the interval between the innermost arcs; with
 *     a flat pupil the integrand is 1 and the row integral is its length,
 *     otherwise Gauss-Legendre over the interval of the smooth
 *     exp(i (Phi(s + f') - Phi(s + f''))).
 * An image stack (planes in the resist) shares all of this: at each node
 * the integrand of plane k is that of the top plane turned by k times the
 * depth phase of one plane step, so the planes cost a complex rotation
 * each, not a second integration.
 */
#include "splat.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>

void source_init(struct source *s, const struct splat_input *in, double cutoff)
{
	s->coherent = 0;
	s->ndisc = 0;
	s->smax = 0;
	double R = cutoff;
#define DISC(x, y, rad, sg) do { int k_ = s->ndisc++; s->cx[k_] = (x); s->cy[k_] = (y); \
	s->r[k_] = (rad); s->sign[k_] = (sg); } while (0)
	switch (in->source) {
	case SPLAT_SRC_CIRCLE:
		if (in->sigma == 0)
			s->coherent = 1;
		else
			DISC(0, 0, in->sigma * R, 1);
		break;
	case SPLAT_SRC_ANNULAR:
		DISC(0, 0, in->s_out * R, 1);
		if (in->s_in > 0)
			DISC(0, 0, in->s_in * R, -1);
		break;
	case SPLAT_SRC_QUADRUPOLE: {
		double c = in->pole_c * R / sqrt(2.0), r = in->pole_r * R;
		DISC(c, c, r, 1);
		DISC(-c, c, r, 1);
		DISC(-c, -c, r, 1);
		DISC(c, -c, r, 1);
		break;
	}
	case SPLAT_SRC_DIPOLE: {
		double c = in->pole_c * R, r = in->pole_r * R;
		if (in->dipole_y) {
			DISC(0, c, r, 1);
			DISC(0, -c, r, 1);
		} else {
			DISC(c, 0, r, 1);
			DISC(-c, 0, r, 1);
		}
		break;
	}
	}
#undef DISC
	for (int k = 0; k < s->ndisc; k++) {
		double e = hypot(s->cx[k], s->cy[k]) + s->r[k];
		if (e > s->smax)
			s->smax = e;
	}
}

/* Gauss-Legendre by Newton on the three-term recurrence (Numerical
 * Recipes' gauleg); nodes accurate to rounding. */
void quad_gauss(int n, double *u, double *w)
{
	for (int i = 0; i < (n + 1) / 2; i++) {
		double z = cos(M_PI * (i + 0.75) / (n + 0.5)), pp = 1;
		for (int it = 0; it < 100; it++) {
			double p1 = 1, p2 = 0;
			for (int j = 1; j <= n; j++) {
				double p3 = p2;
				p2 = p1;
				p1 = ((2.0 * j - 1) * z * p2 - (j - 1.0) * p3) / j;
			}
			pp = n * (z * p1 - p2) / (z * z - 1);
			double dz = p1 / pp;
			z -= dz;
			if (fabs(dz) < 1e-15)
				break;
		}
		/* recompute the derivative at the converged node */
		double p1 = 1, p2 = 0;
		for (int j = 1; j <= n; j++) {
			double p3 = p2;
			p2 = p1;
			p1 = ((2.0 * j - 1) * z * p2 - (j - 1.0) * p3) / j;
		}
		pp = n * (z * p1 - p2) / (z * z - 1);
		u[i] = -z;
		u[n - 1 - i] = z;
		w[i] = w[n - 1 - i] = 2 / ((1 - z * z) * pp * pp);
	}
}

void quad_init(struct quad *q, int nouter, int ninner)
{
	q->nouter = nouter;
	q->ninner = ninner;
	q->uo = xreallocarray(NULL, (size_t)nouter, sizeof *q->uo);
	q->wo = xreallocarray(NULL, (size_t)nouter, sizeof *q->wo);
	q->ui = xreallocarray(NULL, (size_t)ninner, sizeof *q->ui);
	q->wi = xreallocarray(NULL, (size_t)ninner, sizeof *q->wi);
	quad_gauss(nouter, q->uo, q->wo);
	quad_gauss(ninner, q->ui, q->wi);
	q->so = xreallocarray(NULL, (size_t)nouter, sizeof *q->so);
	q->co = xreallocarray(NULL, (size_t)nouter, sizeof *q->co);
	q->wco = xreallocarray(NULL, (size_t)nouter, sizeof *q->wco);
	for (int i = 0; i < nouter; i++) {
		double t = q->uo[i] * (M_PI / 2);
		q->so[i] = sin(t);
		q->co[i] = cos(t);
		q->wco[i] = q->wo[i] * (M_PI / 2);
	}
}

void quad_free(struct quad *q)
{
	free(q->uo);
	free(q->wo);
	free(q->ui);
	free(q->wi);
	free(q->so);
	free(q->co);
	free(q->wco);
}

/* Gauss-Legendre integrates exp(i phi) to rounding once it has a few
 * points more than the phase excursion in radians over a piece; the
 * difference Phi(s + f') - Phi(s + f'') spans at most 2 pi * 2 * waves.
 * The base orders were found by doubling them (tests/splat/quad.c):
 * 12 across already moves a flat-pupil image by less than 1e-9. */
enum { QUAD_BASE_OUTER = 12, QUAD_BASE_INNER = 8, QUAD_MAX = 128 };

void quad_default(const struct pupil *p, int *nouter, int *ninner)
{
	double extra = ceil(2 * M_PI * p->waves);
	if (extra > QUAD_MAX)
		extra = QUAD_MAX;
	*nouter = QUAD_BASE_OUTER + (int)extra;
	*ninner = QUAD_BASE_INNER + (int)extra;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

double complex source_disc3(const struct pupil *p, const struct quad *q,
			    double cx, double cy, double r,
			    double f1x, double f1y, double f2x, double f2y)
{
	struct pupil top = *p;
	top.nplanes = 1;
	double complex sum = 0, row;
	source_disc3_planes(&top, q, cx, cy, r, f1x, f1y, f2x, f2y, &sum, &row);
	return sum;
}

void source_disc3_planes(const struct pupil *p, const struct quad *q,
			 double cx, double cy, double r,
			 double f1x, double f1y, double f2x, double f2y,
			 double complex *sums, double complex *row)
{
	double R = p->cutoff;
	double ccx[3] = {cx, -f1x, -f2x}, ccy[3] = {cy, -f1y, -f2y}, rr[3] = {r, R, R};
	int same = f1x == f2x && f1y == f2y;
	int nc = same ? 2 : 3;
	/* quick rejection: every pair of discs must overlap */
	for (int i = 0; i < nc; i++)
		for (int j = i + 1; j < nc; j++)
			if (hypot(ccx[i] - ccx[j], ccy[i] - ccy[j]) >= rr[i] + rr[j])
				return;
	double ylo = -INFINITY, yhi = INFINITY;
	for (int i = 0; i < nc; i++) {
		if (ccy[i] - rr[i] > ylo) ylo = ccy[i] - rr[i];
		if (ccy[i] + rr[i] < yhi) yhi = ccy[i] + rr[i];
	}
	if (!(yhi > ylo))
		return;

	/* breakpoints across: range ends, circle tops and bottoms, crossings */
	double bp[2 + 6 + 6];
	int nb = 0;
	bp[nb++] = ylo;
	bp[nb++] = yhi;
	for (int i = 0; i < nc; i++) {
		double t = ccy[i] + rr[i], b = ccy[i] - rr[i];
		if (t > ylo && t < yhi) bp[nb++] = t;
		if (b > ylo && b < yhi) bp[nb++] = b;
	}
	for (int i = 0; i < nc; i++)
		for (int j = i + 1; j < nc; j++) {
			double dx = ccx[j] - ccx[i], dy = ccy[j] - ccy[i];
			double d = hypot(dx, dy);
			if (d == 0 || d >= rr[i] + rr[j] || d <= fabs(rr[i] - rr[j]))
				continue;
			double a = (rr[i] * rr[i] - rr[j] * rr[j] + d * d) / (2 * d);
			double h2 = rr[i] * rr[i] - a * a;
			double h = sqrt(h2 > 0 ? h2 : 0);
			double py = ccy[i] + a * dy / d;
			double y1 = py + h * dx / d, y2 = py - h * dx / d;
			if (y1 > ylo && y1 < yhi) bp[nb++] = y1;
			if (y2 > ylo && y2 < yhi) bp[nb++] = y2;
		}
	qsort(bp, (size_t)nb, sizeof *bp, cmp_double);

	/* the pair of an order with itself has no phase at any depth */
	int np = p->nplanes;
	int flat = (p->flat && np == 1) || same;
	for (int k = 0; k + 1 < nb; k++) {
		double y0 = bp[k], y1 = bp[k + 1];
		if (!(y1 > y0))
			continue;
		double mid = 0.5 * (y0 + y1), half = 0.5 * (y1 - y0);
		for (int io = 0; io < q->nouter; io++) {
			/* y = mid + half sin t, dy = half cos t dt (quad_init) */
			double y = mid + half * q->so[io];
			double wy = q->wco[io] * half * q->co[io];
			double a = -INFINITY, b = INFINITY;
			for (int i = 0; i < nc; i++) {
				double dy = y - ccy[i], e = rr[i] * rr[i] - dy * dy;
				double hw = sqrt(e > 0 ? e : 0);
				if (ccx[i] - hw > a) a = ccx[i] - hw;
				if (ccx[i] + hw < b) b = ccx[i] + hw;
			}
			if (!(b > a))
				continue;
			if (flat) {
				for (int l = 0; l < np; l++)
					sums[l] += wy * (b - a);
				continue;
			}
			double xm = 0.5 * (a + b), xh = 0.5 * (b - a);
			for (int l = 0; l < np; l++)
				row[l] = 0;
			/* per node: the top plane's integrand (er, ei) and the turn
			 * of one plane step (cs, ss) */
			double *er = (double *)(row + np), *ei = er + q->ninner;
			double *cs = ei + q->ninner, *ss = cs + q->ninner;
			for (int ii = 0; ii < q->ninner; ii++) {
				double x = xm + xh * q->ui[ii];
				double c = 1, sn = 0;
				if (!p->flat) {
					double ph = pupil_phase(p, x + f1x, y + f1y) -
						pupil_phase(p, x + f2x, y + f2y);
					c = cos(ph);
					sn = sin(ph);
				}
				row[0] += q->wi[ii] * (c + I * sn);
				if (np == 1)
					continue;
				double dp = p->dz * (pupil_depth(p, x + f1x, y + f1y) -
						     pupil_depth(p, x + f2x, y + f2y));
				er[ii] = q->wi[ii] * c;
				ei[ii] = q->wi[ii] * sn;
				cs[ii] = cos(dp);
				ss[ii] = sin(dp);
			}
			/* plane l adds l times the depth phase of one step: turn
			 * every node's integrand by it, plane after plane (the
			 * nodes are independent, so the loop pipelines) */
			for (int l = 1; l < np; l++) {
				double sr = 0, si = 0;
				for (int ii = 0; ii < q->ninner; ii++) {
					double re = er[ii] * cs[ii] - ei[ii] * ss[ii];
					ei[ii] = er[ii] * ss[ii] + ei[ii] * cs[ii];
					er[ii] = re;
					sr += re;
					si += ei[ii];
				}
				row[l] = sr + I * si;
			}
			for (int l = 0; l < np; l++)
				sums[l] += wy * xh * row[l];
		}
	}
}
