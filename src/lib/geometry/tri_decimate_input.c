/*
 * tri_decimate_input.c - the decimator's checks against its input
 * (tri_decimate.h): every input vertex is tracked to the output triangle
 * that took it over and must stay within tol of the surface, and the
 * points of a collapse's new triangles on a barycentric grid must stay
 * within tol of the input triangles around them; and the collapse
 * itself, which hands the tracked vertices on.
 */
#include "surf.h"
#include "tri_decimate.h"
#include "tri_decimate_mesh.h"
#include "util.h"
#include "vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the input vertices' distance to the surface ---- */

/* distance from p to triangle a b c */
static double point_tri(const double *p, const double *a, const double *b, const double *c)
{
	return sqrt(surf_point_tri_dist2(p, a, b, c));
}

/* u's live triangles into m->star, and the input vertices they answer
 * for, u included, into m->pts */
static void gather(struct dmesh *m, int u)
{
	m->nstar = m->npts = 0;
	xgrow(&m->pts, &m->cpts, 1, sizeof *m->pts);
	xgrow(&m->phint, &m->cphint, 1, sizeof *m->phint);
	m->phint[0] = 0;
	m->pts[m->npts++] = u;
	for (long c = m->head[u]; c >= 0; c = m->next[c]) {
		long t = c / 3;
		if (m->tv[3 * t] < 0)
			continue;
		if (m->nstar + 1 > m->cstar)
			xgrow(&m->star, &m->cstar, m->nstar + 1, sizeof *m->star);
		m->star[m->nstar++] = t;
		for (int w = m->thead[t]; w >= 0; w = m->pnext[w]) {
			if (m->npts + 1 > m->cpts)
				xgrow(&m->pts, &m->cpts, m->npts + 1, sizeof *m->pts);
			if (m->npts + 1 > m->cphint)
				xgrow(&m->phint, &m->cphint, m->npts + 1, sizeof *m->phint);
			m->phint[m->npts] = m->nstar - 1;
			m->pts[m->npts++] = w;
		}
	}
}

/* the star's triangle nearest to input vertex w once u is on v (-1: none
 * within tol); with any, the first within tol, from the star's
 * triangle number hint on (the one w belonged to) */
static long nearest_new(const struct dmesh *m, int u, int v, int w, double *dist, int any,
			size_t hint)
{
	long best = -1;
	double bd = m->tol;
	const double *p = m->p + 3 * (size_t)w;
	for (size_t k0 = 0; k0 < m->nstar; k0++) {
		size_t k = (k0 + hint) % m->nstar;
		if (any && best >= 0)
			break;
		const int *tv = m->tv + 3 * m->star[k];
		if (tv[0] < 0 || tv[0] == v || tv[1] == v || tv[2] == v)
			continue;
		const double *a[3];
		for (int s2 = 0; s2 < 3; s2++)
			a[s2] = m->p + 3 * (size_t)(tv[s2] == u ? v : tv[s2]);
		double d = point_tri(p, a[0], a[1], a[2]);
		if (d <= bd) {
			bd = d;
			best = m->star[k];
		}
	}
	*dist = bd;
	return best;
}

/* whether q is within tol of input triangle t */
static int near_one(const struct dmesh *m, const double *q, size_t t)
{
	const int *o = m->otv + 3 * t;
	const float *b = m->osph + 4 * t;
	double e[3] = {q[0] - b[0], q[1] - b[1], q[2] - b[2]};
	double r = b[3] + m->tol;
	if (vec3_dot(e, e) > r * r)
		return 0;       /* its bounding sphere is too far */
	return point_tri(q, m->p + 3 * (size_t)o[0], m->p + 3 * (size_t)o[1], m->p + 3 * (size_t)o[2]) <=
	       m->tol;
}

/* the i-th vertex whose input triangles the samples are checked
 * against (after gather): the tracked input vertices, then the corners
 * of the star once u is on v */
static int set_vertex(const struct dmesh *m, int u, int v, size_t i)
{
	if (i < m->npts)
		return m->pts[i];
	i -= m->npts;
	int w = m->tv[3 * m->star[i / 3] + i % 3];
	return w == u ? v : w;
}

/* the input triangles of the set_vertex list into m->tset, each once, in
 * the order of their first appearance (the order the list was once
 * scanned in, repeats and all: the first within tol is the same one) */
static size_t input_set(struct dmesh *m, int u, int v)
{
	size_t n = 0;
	m->tstamp++;
	for (size_t i = 0; i < m->npts + 3 * m->nstar; i++) {
		int w = set_vertex(m, u, v, i);
		for (size_t k = m->ostart[w]; k < m->ostart[w + 1]; k++) {
			size_t t = m->otri[k];
			if (m->tmark[t] == m->tstamp)
				continue;
			m->tmark[t] = m->tstamp;
			if (n + 1 > m->ctset)
				xgrow(&m->tset, &m->ctset, n + 1, sizeof *m->tset);
			m->tset[n++] = t;
		}
	}
	return n;
}

/* whether, once u is on v, every input vertex u's star answers for stays
 * within tol of the star, and the star's points on the barycentric grid
 * of step 1/TRI_DECIMATE_SAMPLES within tol of the input triangles
 * around them */
int dm_points_ok(struct dmesh *m, int u, int v)
{
	gather(m, u);
	for (size_t i = 0; i < m->npts; i++) {
		double d;
		if (nearest_new(m, u, v, m->pts[i], &d, 1, m->phint[i]) < 0)
			return 0;
	}
	/* the set of input triangles the samples are checked against: those
	 * of the tracked input vertices and of the new star's corners, read
	 * where they are (whether any is within tol does not depend on the
	 * order, nor on a triangle being tried twice) */
	long last = -1;
	for (size_t i = 0; i < m->npts + 3 * m->nstar && last < 0; i++) {
		int w = set_vertex(m, u, v, i);
		if (m->ostart[w] < m->ostart[w + 1])
			last = (long)m->otri[m->ostart[w]];
	}
	if (last < 0)
		return 0;
	enum { S = TRI_DECIMATE_SAMPLES };
	size_t nset = 0;
	int set_built = 0;
	for (size_t k = 0; k < m->nstar; k++) {
		const int *tv = m->tv + 3 * m->star[k];
		if (tv[0] == v || tv[1] == v || tv[2] == v)
			continue;
		const double *a[3];
		for (int s2 = 0; s2 < 3; s2++)
			a[s2] = m->p + 3 * (size_t)(tv[s2] == u ? v : tv[s2]);
		for (int i = 0; i <= S; i++)
			for (int j = 0; i + j <= S; j++) {
				if (i == S || j == S || i + j == 0)
					continue;       /* the corners are input vertices */
				double x = (double)i / S, y = (double)j / S, q[3];
				for (int d = 0; d < 3; d++)
					q[d] = (1 - x - y) * a[0][d] + x * a[1][d] + y * a[2][d];
				/* the triangle that held the last sample first (the
				 * samples are near each other), then the set from
				 * its start (the triangles around u) */
				if (near_one(m, q, (size_t)last))
					continue;
				if (!set_built) {
					nset = input_set(m, u, v);
					set_built = 1;
				}
				int near = 0;
				for (size_t k2 = 0; k2 < nset && !near; k2++)
					if (near_one(m, q, m->tset[k2])) {
						near = 1;
						last = (long)m->tset[k2];
					}
				if (!near)
					return 0;
			}
	}
	return 1;
}

void dm_collapse(struct dmesh *m, int u, int v)
{
	gather(m, u);
	/* the input vertices go to the nearest triangle of the new star */
	long *own = xreallocarray(NULL, m->npts + 1, sizeof *own);
	for (size_t i = 0; i < m->npts; i++) {
		double d;
		own[i] = nearest_new(m, u, v, m->pts[i], &d, 0, 0);
	}
	for (size_t k = 0; k < m->nstar; k++)
		m->thead[m->star[k]] = -1;
	for (size_t i = m->npts; i-- > 0;)
		if (own[i] >= 0) {
			m->pnext[m->pts[i]] = m->thead[own[i]];
			m->thead[own[i]] = m->pts[i];
		}
	free(own);
	long c = m->head[u];
	while (c >= 0) {
		long nx = m->next[c], t = c / 3;
		int *tv = m->tv + 3 * t;
		if (tv[0] >= 0) {
			if (tv[0] == v || tv[1] == v || tv[2] == v)
				tv[0] = tv[1] = tv[2] = -1;
			else {
				tv[c % 3] = v;
				m->next[c] = m->head[v];
				m->head[v] = (int)c;
			}
		}
		c = nx;
	}
	m->head[u] = -1;
	m->flag[u] |= F_DEAD;
	/* v's list without its dead corners (they would pile up on the
	 * vertices that absorb many) */
	int *pc = &m->head[v];
	while (*pc >= 0) {
		if (m->tv[3 * (*pc / 3)] < 0)
			*pc = m->next[*pc];
		else
			pc = &m->next[*pc];
	}
	for (int k = 0; k < 10; k++)
		m->q[10 * (size_t)v + k] += m->q[10 * (size_t)u + k];
}
