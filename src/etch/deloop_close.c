/*
 * deloop_close.c - closing what the joining of the cut sheets leaves open
 * (deloop.h, end of stage 3).
 *
 * deloop_zip.c joins the two sheets of an intersection where a node of
 * one chain lies next to a segment of the other, in its triangle's plane;
 * on rough fronts (standing waves) stretches of the two chains do not
 * meet that test and are left open, a pull-back apart (DELOOP_PULLBACK).
 * The open border of an oriented surface falls into closed loops, each
 * traversed one way by its triangles: a stretch left open is such a loop,
 * a long thin slit whose two sides are the two chains.  Each loop is
 * triangulated here by ear clipping in 3D: repeatedly the ear (v[i-1],
 * v[i], v[i+1]) with the shortest new segment v[i-1] v[i+1] is cut off
 * by one triangle traversing the loop the other way (so the orientation
 * stays consistent), which for a slit zips it from its narrow ends in,
 * across its width.  An ear is refused when its segment exists already,
 * is longer than CLOSE_SPAN of the loop's segments (a wide hole is not
 * lidded), when it is degenerate, or when its triangle faces against the
 * ones it borders (a fold; taken only if no other ear is left).  The new triangles must not cross the surface: after
 * the closing the crossings are searched again (dl_pierces_fresh) and every
 * loop one of whose triangles takes part in a crossing is opened again,
 * as it was; a touch on a face of the box (a lid's chord on the
 * substrate across the floor) is no crossing.  An open
 * stretch that ends on a face is chained along the face's border to the
 * next stretch that starts on it, by a chord on the face, and the chain
 * closed when it comes back to its start (a slit from the substrate or a
 * side wall back to it).
 */
#include "deloop_grid.h"

#include "util.h"
#include "vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Largest loop closed (nodes): the slits of the examples have up to a
 * few hundred; the ear search is quadratic in the loop's length. */
#define CLOSE_MAX_LOOP 4096
/* An ear whose triangle's area is below this fraction of the square of
 * its longest side is degenerate (its normal is rounding). */
#define CLOSE_DEGENERATE 1e-12
/* No new segment is longer than this many times the loop's longest
 * segment: a slit between two sheets is closed across its width, a
 * segment or less, while a wide hole (where no sheet was left to join)
 * would get a lid the surface does not have. */
#define CLOSE_SPAN 2.0
/* The orders of ears tried (ear_score): a loop whose closing crosses the
 * surface is opened again and closed the next way.  (A way without the
 * CLOSE_SPAN limit closed the hole 0.2 um wide that Kodak 820 on
 * examples/defect at 110 mJ/cm2 keeps, but with a lid 0.25 um from the
 * fast-marching wall there, and on the unbaked contact at 240 mJ/cm2,
 * tests/etch/deloop_contact, lids over 36 % more area.) */
#define CLOSE_WAYS 3

/* The node border segment s leaves first when traversed by its
 * triangle. */
static int border_from(const struct mesh *m, int s)
{
	const struct triangle *tr = &m->tri[m->seg[s].t[0]];
	int j = 0;
	while (j < 2 && tr->s[j] != s)
		j++;
	return tr->n[j];
}

static int other_end(const struct mesh *m, int s, int a)
{
	return m->seg[s].n[0] == a ? m->seg[s].n[1] : m->seg[s].n[0];
}

/* An open segment of the first ns leaving a (traversed from a by its
 * triangle) and not seen yet, or -1. */
static int leaving(const struct mesh *m, int a, const unsigned char *seen, size_t ns)
{
	for (int k = 0; k < m->node[a].nseg; k++) {
		int s = m->node[a].seg[k];
		if ((size_t)s < ns && !seen[s] && deloop_border_open(m, s) &&
		    border_from(m, s) == a)
			return s;
	}
	return -1;
}

static void tri_normal(const struct mesh *m, int a, int b, int c, double n[3])
{
	double u[3], v[3];
	vec3_sub(m->node[b].p, m->node[a].p, u);
	vec3_sub(m->node[c].p, m->node[a].p, v);
	vec3_cross(u, v, n);
}

/* The normal of the triangle on border segment s (not normalised). */
static void seg_normal(const struct mesh *m, int s, double n[3])
{
	const struct triangle *tr = &m->tri[m->seg[s].t[0]];
	tri_normal(m, tr->n[0], tr->n[1], tr->n[2], n);
}

/* The square of the distance between nodes a and b. */
static double dist2(const struct mesh *m, int a, int b)
{
	double d[3];
	vec3_sub(m->node[a].p, m->node[b].p, d);
	return vec3_dot(d, d);
}

/* Whether the ear at v[i] of the loop may be cut off: its triangle
 * (v[i+1], v[i], v[i-1]) new, not degenerate, and facing the way of the
 * triangles on the two loop segments it takes (sn[i-1], sn[i]). */
static int ear_ok(const struct mesh *m, const int *v, const double (*sn)[3], int n, int i,
		  int strict, double span2)
{
	int a = v[(i + n - 1) % n], b = v[i], c = v[(i + 1) % n];
	if (a == c || (n > 3 && mesh_find_segment(m, a, c) >= 0) || dist2(m, a, c) > span2)
		return 0;
	if (n == 3) {
		/* the last triangle must not lie back to back on another */
		int e = mesh_find_segment(m, a, b);
		for (int k = 0; e >= 0 && k < 2; k++) {
			int x = m->seg[e].t[k];
			if (x < 0)
				continue;
			const int *tn = m->tri[x].n;
			if ((tn[0] == c || tn[1] == c || tn[2] == c))
				return 0;
		}
	}
	double nt[3];
	tri_normal(m, c, b, a, nt);
	double l = fmax(dist2(m, a, b), fmax(dist2(m, b, c), dist2(m, a, c)));
	double area2 = vec3_dot(nt, nt);
	if (!(area2 > CLOSE_DEGENERATE * l * l))
		return 0;
	return !strict || (vec3_dot(nt, sn[(i + n - 1) % n]) > 0 && vec3_dot(nt, sn[i]) > 0);
}

/* The ear at v[i] in the order the loop's closing takes them, lowest
 * first: way 0 by the length of its new segment (a slit zips across its
 * width), way 1 by how far its triangle turns from the two it borders
 * (the smoothest closing), way 2 by its smallest angle, largest first. */
static double ear_score(const struct mesh *m, const int *v, const double (*sn)[3], int n,
			int i, int way)
{
	int a = v[(i + n - 1) % n], b = v[i], c = v[(i + 1) % n];
	if (way == 0)
		return dist2(m, a, c);
	if (way == 1) {
		double nt[3];
		tri_normal(m, c, b, a, nt);
		double l = sqrt(vec3_dot(nt, nt)), worst = 1;
		for (int k = 0; k < 2; k++) {
			const double *q = sn[k ? i : (i + n - 1) % n];
			double lq = sqrt(vec3_dot(q, q));
			if (l > 0 && lq > 0)
				worst = fmin(worst, vec3_dot(nt, q) / (l * lq));
		}
		return -worst;
	}
	int x[3] = {a, b, c};
	double lo = 1;
	for (int k = 0; k < 3; k++) {
		/* the sine-free measure of an angle: 1 - cos */
		double u[3], w[3];
		vec3_sub(m->node[x[(k + 1) % 3]].p, m->node[x[k]].p, u);
		vec3_sub(m->node[x[(k + 2) % 3]].p, m->node[x[k]].p, w);
		double d = sqrt(vec3_dot(u, u) * vec3_dot(w, w));
		lo = fmin(lo, d > 0 ? 1 - vec3_dot(u, w) / d : 0);
	}
	return -lo;
}

/* Triangulates the loop v[0 .. n) (traversed v[k] -> v[k+1] by the
 * triangles on its segments); the triangles made are appended to *tris.
 * Returns 0 when an ear could not be found (the loop's triangles made so
 * far are left for the caller to remove). */
static int close_loop(struct mesh *m, int *v, int n, int way, int **tris, size_t *ntris,
		      size_t *cap)
{
	double (*sn)[3] = xreallocarray(NULL, (size_t)n, sizeof *sn), span2 = 0;
	unsigned char *virt = xcalloc((size_t)n, 1);
	int real = -1;
	for (int k = 0; k < n; k++) {
		int e = mesh_find_segment(m, v[k], v[(k + 1) % n]);
		if (e >= 0 && m->seg[e].t[0] >= 0) {
			seg_normal(m, e, sn[k]);
			real = k;
		} else {
			virt[k] = 1;    /* a chord along a face (close_all) */
		}
		span2 = fmax(span2, dist2(m, v[k], v[(k + 1) % n]));
	}
	/* a chord takes the normal of the loop segment before it */
	for (int j = 1; real >= 0 && j <= n; j++) {
		int k = (real + j) % n;
		if (virt[k])
			memcpy(sn[k], sn[(k + n - 1) % n], sizeof sn[k]);
	}
	free(virt);
	span2 *= CLOSE_SPAN * CLOSE_SPAN;
	int ok = 1;
	while (n >= 3) {
		int best = -1;
		/* an ear facing the way of its neighbours, or failing that
		 * any (a fold of the seam; the crossing check judges it) */
		for (int strict = 1; strict >= 0 && best < 0; strict--) {
			double bl = HUGE_VAL;
			for (int i = 0; i < n; i++) {
				double l = ear_score(m, v, (const double (*)[3])sn, n, i, way);
				if (l < bl && ear_ok(m, v, (const double (*)[3])sn, n, i, strict, span2)) {
					bl = l;
					best = i;
				}
			}
		}
		if (best < 0) {
			ok = 0;
			break;
		}
		int a = v[(best + n - 1) % n], b = v[best], c = v[(best + 1) % n];
		xgrow(tris, cap, *ntris + 1, sizeof **tris);
		(*tris)[(*ntris)++] = mesh_add_triangle(m, c, b, a);
		if (n == 3)
			break;
		/* the new segment a c replaces a b and b c, traversed a -> c
		 * by the remaining loop: the new triangle's normal */
		int p = (best + n - 1) % n;
		tri_normal(m, c, b, a, sn[p]);
		memmove(v + best, v + best + 1, (size_t)(n - best - 1) * sizeof *v);
		memmove(sn + best, sn + best + 1, (size_t)(n - best - 1) * sizeof *sn);
		n--;
	}
	free(sn);
	return ok;
}

/* A loop of at most four segments round one or two triangles that touch
 * nothing else (debris of the cuts, a scrap of a sheet cut off on every
 * side) cannot be closed without making a pillow (two triangles on the
 * same nodes back to back, which a later split would double a segment
 * of): the scrap is deleted instead.  Returns 1 if it was. */
static int drop_island(struct mesh *m, const int *v, int n)
{
	if (n > 4)
		return 0;
	int t[2] = {-1, -1}, nt = 0;
	for (int i = 0; i < n; i++)
		for (int j = i + 1; j < n; j++) {
			int e = mesh_find_segment(m, v[i], v[j]);
			if (e < 0)
				continue;
			for (int k = 0; k < 2; k++) {
				int x = m->seg[e].t[k];
				if (x < 0 || x == t[0] || x == t[1])
					continue;
				if (nt == 2)
					return 0;
				t[nt++] = x;
			}
		}
	/* every node of the scrap's triangles is on the loop, and each of
	 * its segments has no triangle outside the scrap */
	for (int k = 0; k < nt; k++)
		for (int j = 0; j < 3; j++) {
			int on = 0, e = m->tri[t[k]].s[j];
			for (int i = 0; i < n; i++)
				on |= m->tri[t[k]].n[j] == v[i];
			for (int c = 0; c < 2; c++) {
				int x = m->seg[e].t[c];
				on &= x < 0 || x == t[0] || x == t[1];
			}
			if (!on)
				return 0;
		}
	for (int k = 0; k < nt; k++)
		mesh_kill_triangle(m, t[k]);
	return nt > 0;
}

/* Closes the loop v[0 .. n) and records its triangles (loop[k] the
 * loop's number for tris[k]), or removes them if it cannot be closed.
 * Returns 1 if closed. */
static int take_loop(struct mesh *m, int *v, int n, int way, long nloop, int **tris, int **loop,
		     size_t *ntris, size_t *cap, size_t *capl)
{
	if (n < 3)
		return 0;
	size_t first = *ntris;
	if (drop_island(m, v, n))
		return 0;
	int ok = close_loop(m, v, n, way, tris, ntris, cap);
	if (!ok) {
		for (size_t k = first; k < *ntris; k++)
			mesh_kill_triangle(m, (*tris)[k]);
		*ntris = first;
		return 0;
	}
	xgrow(loop, capl, *ntris + 1, sizeof **loop);
	for (size_t k = first; k < *ntris; k++)
		(*loop)[k] = (int)nloop;
	return 1;
}

/* Whether an open segment of the first ns arrives at node a. */
static int arriving(const struct mesh *m, int a, size_t ns)
{
	for (int k = 0; k < m->node[a].nseg; k++) {
		int s = m->node[a].seg[k];
		if ((size_t)s < ns && deloop_border_open(m, s) && border_from(m, s) != a)
			return 1;
	}
	return 0;
}

/* Whether the chord from a to b (the ends of an open stretch on one face)
 * may close the stretch: no segment there yet, or a border segment on the
 * face whose one triangle traverses it from a to b, the way the stretch's
 * own triangles go round (a notch cut into the surface's edge on the wall:
 * its two open sides meet the wall at the ends of one edge segment; the
 * car-krf-lines example kept such notches open). */
static int chord_free(const struct mesh *m, int a, int b)
{
	int e = mesh_find_segment(m, a, b);
	if (e < 0)
		return 1;
	const struct segment *sg = &m->seg[e];
	return sg->t[0] >= 0 && sg->t[1] < 0 && !deloop_border_open(m, e) && border_from(m, e) == a;
}

/* Whether nodes a and b lie on a common face of the box. */
static unsigned common_face(const struct mesh *m, int a, int b)
{
	return m->node[a].flags & m->node[b].flags & (ON_WALLS | ON_SUB);
}

/* The face border segment (one triangle, not open) leaving node a the
 * way its triangle traverses it, or -1. */
static int face_leaving(const struct mesh *m, int a)
{
	for (int k = 0; k < m->node[a].nseg; k++) {
		int s = m->node[a].seg[k];
		const struct segment *sg = &m->seg[s];
		if (sg->alive && sg->t[0] >= 0 && sg->t[1] < 0 && !deloop_border_open(m, s) &&
		    border_from(m, s) == a)
			return s;
	}
	return -1;
}

/* Where the border goes on from node a, the end of an open stretch on a
 * face: along the face border (segments on the face, where the mesh
 * meets the box) to the first node from which an open stretch not
 * walked yet leaves, or back to the walk's first node v0; -1 if the face
 * border turns off a's face first, or runs longer than a loop may. */
static int next_stretch(const struct mesh *m, int a, int v0, const unsigned char *seen, size_t ns)
{
	unsigned face = common_face(m, a, a);
	int x = a;
	for (int k = 0; k < CLOSE_MAX_LOOP; k++) {
		int s = face_leaving(m, x);
		if (s < 0)
			return -1;
		x = other_end(m, s, x);
		if (!(m->node[x].flags & face))
			return -1;
		if (x == v0 || leaving(m, x, seen, ns) >= 0)
			return x;
		if (x == a)
			return -1;
	}
	return -1;
}

/* The node the walk v[0 .. nv) goes on from, its open stretch having
 * ended at v[nv - 1] on a face: the start of the next open stretch along
 * the face border (next_stretch), if the chord to it lies on one face
 * and is free (chord_free) and the node is not on the walk already; -1
 * otherwise (the walk ends, and a chord back to v[0] may close it).  A
 * slit from the substrate back to it can have two open stretches, one
 * up a wall and back and one a flap on the floor (Shipley 1470 on
 * examples/defect at 80 mJ/cm2), which only close together. */
static int chain_to(const struct mesh *m, const int *v, size_t nv, const int *pos,
		    const unsigned char *seen, size_t ns)
{
	int a = v[nv - 1];
	if (nv < 2 || !common_face(m, a, a))
		return -1;
	int x = next_stretch(m, a, v[0], seen, ns);
	if (x < 0 || x == v[0] || pos[x] || !common_face(m, a, x) || !chord_free(m, a, x))
		return -1;
	return x;
}

/* The axis a face flag of the box fixes (0 x, 1 y, 2 z), or -1 unless
 * f is one face alone. */
static int face_axis(unsigned f)
{
	switch (f) {
	case ON_X0: case ON_X1: return 0;
	case ON_Y0: case ON_Y1: return 1;
	case ON_SUB: case ON_TOP: return 2;
	default: return -1;
	}
}

/* An open stretch v[0 .. nv) from one face of the box to another that
 * meets it at an edge (a side wall and the substrate: the wall's profile
 * ends a little above the substrate, the floor a little short of the
 * wall, and the stretch joins the two across the corner; Kodak 820 on
 * examples/corner-defect at 88 mJ/cm2) is closed with a node on the
 * edge: its two chords to the stretch's ends lie on the two faces.  The
 * node is added, at the edge's point between the ends, and returned, if
 * it is no farther from either end than CLOSE_SPAN of the stretch's
 * longest segment; -1 otherwise. */
static int corner_node(struct mesh *m, const int *v, size_t nv)
{
	const struct node *a = &m->node[v[0]], *b = &m->node[v[nv - 1]];
	unsigned fa = a->flags & (ON_WALLS | ON_SUB), fb = b->flags & (ON_WALLS | ON_SUB);
	int xa = face_axis(fa), xb = face_axis(fb);
	if (nv < 2 || xa < 0 || xb < 0 || xa == xb)
		return -1;
	double p[3], len2 = 0;
	for (int d = 0; d < 3; d++)
		p[d] = 0.5 * (a->p[d] + b->p[d]);
	p[xa] = a->p[xa];
	p[xb] = b->p[xb];
	for (size_t k = 0; k + 1 < nv; k++)
		len2 = fmax(len2, dist2(m, v[k], v[k + 1]));
	double da[3], db[3];
	vec3_sub(p, a->p, da);
	vec3_sub(p, b->p, db);
	double lim = CLOSE_SPAN * CLOSE_SPAN * len2;
	if (!(vec3_dot(da, da) <= lim && vec3_dot(db, db) <= lim))
		return -1;
	double r[3];    /* copied: adding the node may move the array */
	memcpy(r, a->s, sizeof r);
	return mesh_add_node(m, p, r, fa | fb);
}

/* One closing: the open border walked segment by segment, each segment
 * once; a walk that comes back to a node on its path has gone round a
 * loop, which is cut off the path and closed (a border passing twice
 * through a node, pinched, so falls into simple loops).  Walks start
 * first where an open stretch begins on a face of the box (a slit that
 * reaches the substrate), then anywhere; a stretch that ends on the same
 * face it began on is closed with the chord between its ends, which lies
 * on that face (border where the mesh is meant to end).  loop[k] is the
 * loop of new triangle tris[k].  Returns the loops closed. */
static long close_all(struct mesh *m, int way, int **tris, int **loop, size_t *ntris)
{
	size_t ns = m->nseg, cap = 0, capl = 0, capv = 0, capw = 0, nv = 0;
	unsigned char *seen = xcalloc(ns + 1, 1);
	int *pos = xcalloc(m->nnode + 1, sizeof *pos);   /* place on the path + 1 */
	int *v = NULL, *w = NULL;
	long loops = 0;
	*ntris = 0;
	for (int sweep = 0; sweep < 2; sweep++)
	for (size_t s0 = 0; s0 < ns; s0++) {
		if (seen[s0] || !deloop_border_open(m, (int)s0))
			continue;
		int s = (int)s0;
		if (sweep == 0 && arriving(m, border_from(m, s), ns))
			continue;
		xgrow(&v, &capv, 1, sizeof *v);
		v[0] = border_from(m, s);
		pos[v[0]] = 1;
		nv = 1;
		while (nv < CLOSE_MAX_LOOP) {
			if (s < 0) {
				/* the stretch ends: on a face, chained to the
				 * next one by a chord on the face */
				int x = chain_to(m, v, nv, pos, seen, ns);
				if (x < 0)
					break;
				xgrow(&v, &capv, nv + 1, sizeof *v);
				v[nv++] = x;
				pos[x] = (int)nv;
				s = leaving(m, x, seen, ns);
			}
			seen[s] = 1;
			int b = other_end(m, s, v[nv - 1]);
			if (pos[b]) {
				size_t j = (size_t)pos[b] - 1, n = nv - j;
				xgrow(&w, &capw, n, sizeof *w);
				memcpy(w, v + j, n * sizeof *w);
				for (size_t k = j + 1; k < nv; k++)
					pos[v[k]] = 0;
				nv = j + 1;
				loops += take_loop(m, w, (int)n, way, loops, tris, loop, ntris, &cap,
						   &capl);
			} else {
				xgrow(&v, &capv, nv + 1, sizeof *v);
				v[nv++] = b;
				pos[b] = (int)nv;
			}
			s = leaving(m, v[nv - 1], seen, ns);
		}
		unsigned face = m->node[v[0]].flags & m->node[v[nv - 1]].flags & (ON_WALLS | ON_SUB);
		int c = s < 0 && !face ? corner_node(m, v, nv) : -1;
		if ((nv >= 3 && s < 0 && face && chord_free(m, v[nv - 1], v[0])) || c >= 0) {
			xgrow(&w, &capw, nv + 1, sizeof *w);
			memcpy(w, v, nv * sizeof *w);
			if (c >= 0)
				w[nv] = c;
			int n = (int)nv + (c >= 0);
			long l = take_loop(m, w, n, way, loops, tris, loop, ntris, &cap, &capl);
			if (!l && c >= 0 && m->node[c].alive && m->node[c].nseg == 0) {
				/* not closed, and nothing made: the corner node goes */
				m->node[c].alive = 0;
				m->live_node--;
			}
			loops += l;
		}
		for (size_t k = 0; k < nv; k++)
			pos[v[k]] = 0;
	}
	free(seen);
	free(pos);
	free(v);
	free(w);
	return loops;
}

/* Whether pierce p only touches on a face of the box: its segment lies
 * on a face (both nodes on it), or its triangle does.  Nothing of the
 * mesh lies beyond a face, so a triangle meets a segment or triangle in
 * the face's plane only where it touches that plane: along its own edge
 * on the face, which rounding puts just inside or just outside.  A lid
 * closing a slit that reaches the substrate has its chord there, across
 * the floor's segments (Shipley 1470 on examples/defect at 96 mJ/cm2:
 * every way of three such slits reopened for these touches). */
static int face_touch(const struct mesh *m, const struct deloop_pierce *p)
{
	const struct segment *sg = &m->seg[p->s];
	const int *tn = m->tri[p->t].n;
	unsigned fs = m->node[sg->n[0]].flags & m->node[sg->n[1]].flags;
	unsigned ft = m->node[tn[0]].flags & m->node[tn[1]].flags & m->node[tn[2]].flags;
	return ((fs | ft) & (ON_WALLS | ON_SUB)) != 0;
}

static long close_way(struct mesh *m, int way)
{
	size_t ntri0 = m->ntri, nt = 0;
	int *tris = NULL, *loop = NULL;
	long nl = close_all(m, way, &tris, &loop, &nt);
	if (nl > 0) {
		/* the loops whose triangles cross the surface open again
		 * (removing triangles makes no crossing, so once is enough);
		 * only crossings with a new triangle or a segment of one
		 * count, and only those are searched (deloop_fresh.c) */
		struct deloop_pierce *pc;
		size_t np = dl_pierces_fresh_checked(m, ntri0, &pc);
		unsigned char *bad = xcalloc((size_t)nl, 1);
		int *of = xreallocarray(NULL, m->ntri - ntri0 + 1, sizeof *of);
		for (size_t k = 0; k < m->ntri - ntri0; k++)
			of[k] = -1;
		for (size_t k = 0; k < nt; k++)
			of[(size_t)tris[k] - ntri0] = loop[k];
		long nbad = 0;
		for (size_t i = 0; i < np; i++) {
			if (face_touch(m, &pc[i]))
				continue;
			int ts[3] = {pc[i].t, m->seg[pc[i].s].t[0], m->seg[pc[i].s].t[1]};
			for (int j = 0; j < 3; j++) {
				if (ts[j] < 0 || (size_t)ts[j] < ntri0)
					continue;
				int l = of[ts[j] - ntri0];
				if (l >= 0 && !bad[l]) {
					bad[l] = 1;
					nbad++;
				}
			}
		}
		free(pc);
		for (size_t k = 0; k < nt; k++)
			if (bad[loop[k]])
				mesh_kill_triangle(m, tris[k]);
		nl -= nbad;
		free(of);
		free(bad);
	}
	free(tris);
	free(loop);
	return nl;
}

long deloop_close(struct mesh *m, int force)
{
	if (force) {
		size_t nt = 0;
		int *tris = NULL, *loop = NULL;
		long nl = close_all(m, 0, &tris, &loop, &nt);
		free(tris);
		free(loop);
		return nl;
	}
	long closed = 0;
	for (int way = 0; way < CLOSE_WAYS; way++)
		closed += close_way(m, way);
	return closed;
}


