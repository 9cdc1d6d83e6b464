/*
 * deloop_zip.c - joining the two sheets of a delooped intersection along
 * their intersection curve (thesis 8.4.3 and Figure 8.11: "the triangles
 * are cut up at their intersections", so that what is left of the mesh
 * meets itself there).
 *
 * After the cuts (deloop.c) each kept sheet ends on a chain of cut nodes,
 * every one of them a point where an edge of that sheet pierces the other
 * sheet: a vertex of the exact intersection polyline of the two
 * triangulated surfaces.  Between two consecutive cut nodes a sheet's
 * border is a chord lying in one of its own (planar) triangles, so each
 * node of the other sheet's chain lies, up to rounding, in the plane of
 * the chord's triangle and next to the chord.  Joining is then pure
 * topology: each border node y of one chain is inserted into the nearest
 * border segment of the other chain (mesh_split at y's own position, in
 * the plane of the triangle split) and welded to the new node
 * (mesh_weld), or welded directly to a node of the other chain already
 * at its place.  Once both chains have the same nodes, the twin border
 * segments become single segments with one triangle of each sheet: the
 * seam is the intersection polyline itself and neither sheet has moved.
 *
 * Which chain is "the other" is told by orientation, not by a sheet
 * label (one sheet folding through itself, Figure 8.12, has only one):
 * a border chain of an oriented surface is traversed one way by its
 * triangles, and the two chains that can be joined consistently are
 * traversed in opposite directions.  Every operation is checked first
 * (mesh_can_weld: orientation, no segment with three triangles, no
 * duplicate triangle; a direct weld must turn no triangle over; a node is
 * inserted only into a segment whose triangle's plane it lies in).  Where
 * two nodes of the chains came too close to be told apart, a border loop
 * of three or four segments is left, and is closed by one or two
 * triangles (fill_holes).  What cannot be joined stays open and deloop.c
 * pulls it back.
 */
#include "deloop.h"

#include "util.h"
#include "vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A border node joins the other chain when it lies within this fraction
 * of a segment's length from it: the nodes of both chains are on the
 * intersection curve and the chords deviate from it by their sagitta,
 * L^2 k / 8 for a curve of curvature k, a few hundredths of L for the
 * curves met here, while the nearest unrelated border (a chain's own
 * segment two along, or another curve) is about L or more away. */
#define ZIP_TOL 0.25
/* Within this fraction of the segment of one of its ends a node is
 * welded to that end instead of splitting the segment: the nodes are
 * then the same point of the curve (the cuts themselves are not made
 * nearer than this to a node, deloop.c's MIN_CUT).  Welding moves a node
 * by up to this much, off the other sheet's plane: kept this small, such
 * moves cannot open crossings deeper than rounding-sized slivers. */
#define ZIP_SNAP 1e-3
/* Cosine above which two border directions count as the same way: the
 * chains to join run opposite ways (cosine near -1), a chain's own
 * segments the same way. */
#define ZIP_OPPOSITE -0.3
/* A node of one chain lies in the plane of the triangle of the other
 * chain it belongs in: it is where an edge of its own sheet pierces that
 * triangle, or a piece of it.  Rounding puts it ~1e-16 L off; any other
 * triangle is off by the surface's curvature times L^2, 1e-3 L or more
 * at a segment per tenth of a radius. */
#define ZIP_PLANE 1e-6
/* Sweeps over the border: a sweep joins every node whose partner
 * segment is in the list it starts with; the splits add segments, which
 * the next sweep sees.  Two or three suffice in the cases tested. */
#define ZIP_SWEEPS 8

static int is_open(const struct mesh *m, int s)
{
	const struct segment *sg = &m->seg[s];
	if (!sg->alive || sg->t[0] < 0 || sg->t[1] >= 0)
		return 0;
	/* a border on a face of the box is where the mesh is meant to end */
	unsigned f = m->node[sg->n[0]].flags & m->node[sg->n[1]].flags;
	return !(f & (ON_WALLS | ON_SUB));
}

int deloop_border_open(const struct mesh *m, int s)
{
	return is_open(m, s);
}

double deloop_open_length(const struct mesh *m)
{
	double len = 0;
	for (size_t s = 0; s < m->nseg; s++)
		if (is_open(m, (int)s))
			len += mesh_seg_length(m, (int)s);
	return len;
}

/* The way border segment s is traversed by its triangle: the node it
 * leaves first (*from) and the unit direction. */
static void border_dir(const struct mesh *m, int s, int *from, double d[3])
{
	const struct triangle *tr = &m->tri[m->seg[s].t[0]];
	int j = 0;
	while (j < 2 && tr->s[j] != s)
		j++;
	int a = tr->n[j], b = tr->n[(j + 1) % 3];
	double l = 0;
	for (int k = 0; k < 3; k++) {
		d[k] = m->node[b].p[k] - m->node[a].p[k];
		l += d[k] * d[k];
	}
	l = sqrt(l);
	for (int k = 0; k < 3; k++)
		d[k] = l > 0 ? d[k] / l : 0;
	*from = a;
}

/* The apex of border segment s's triangle. */
static int border_apex(const struct mesh *m, int s)
{
	const struct triangle *tr = &m->tri[m->seg[s].t[0]];
	for (int j = 0; j < 3; j++)
		if (tr->n[j] != m->seg[s].n[0] && tr->n[j] != m->seg[s].n[1])
			return tr->n[j];
	return -1;
}

/* Whether node y may be welded to a node inserted into open segment e
 * (the mesh_can_weld conditions for a node not made yet): e's triangle,
 * traversing it a -> b, gives (a, z) entering z and (z, b) leaving it,
 * and an interior segment (z, apex). */
static int can_insert(const struct mesh *m, int e, int y)
{
	int from, apex = border_apex(m, e);
	double d[3];
	border_dir(m, e, &from, d);
	int a = from, b = m->seg[e].n[0] == from ? m->seg[e].n[1] : m->seg[e].n[0];
	if (y == a || y == b || y == apex || apex < 0)
		return 0;
	if (mesh_find_segment(m, y, apex) >= 0)
		return 0;
	for (int k = 0; k < 2; k++) {
		int x = k ? b : a, leaves_z = k;
		int sk = mesh_find_segment(m, y, x);
		if (sk < 0)
			continue;
		/* the twins must be one border each */
		if (m->seg[sk].t[0] < 0 || m->seg[sk].t[1] >= 0)
			return 0;
		int f2;
		double d2[3];
		border_dir(m, sk, &f2, d2);
		if ((f2 == y) == leaves_z || border_apex(m, sk) == apex)
			return 0;
	}
	return 1;
}

static void tri_normal(const double *a, const double *b, const double *c, double n[3]);

/* Distance (um) of point p from the plane of open segment e's triangle. */
static double off_plane(const struct mesh *m, int e, const double *p)
{
	const struct triangle *tr = &m->tri[m->seg[e].t[0]];
	const double *a = m->node[tr->n[0]].p;
	double n[3];
	tri_normal(a, m->node[tr->n[1]].p, m->node[tr->n[2]].p, n);
	double nl = sqrt(vec3_dot(n, n)), w[3];
	if (!(nl > 0))
		return HUGE_VAL;
	vec3_sub(p, a, w);
	return fabs(vec3_dot(n, w)) / nl;
}

static void tri_normal(const double *a, const double *b, const double *c, double n[3])
{
	double u[3], v[3];
	vec3_sub(b, a, u);
	vec3_sub(c, a, v);
	vec3_cross(u, v, n);
}

/* Whether moving node del to keep's place turns none of del's triangles
 * over. */
static int keeps_sides(const struct mesh *m, int keep, int del)
{
	const struct node *nd = &m->node[del];
	for (int i = 0; i < nd->nseg; i++)
		for (int k = 0; k < 2; k++) {
			int t = m->seg[nd->seg[i]].t[k];
			if (t < 0)
				continue;
			const double *p[3], *q[3];
			for (int j = 0; j < 3; j++) {
				int n = m->tri[t].n[j];
				p[j] = m->node[n].p;
				q[j] = n == del ? m->node[keep].p : p[j];
			}
			double n0[3], n1[3];
			tri_normal(p[0], p[1], p[2], n0);
			tri_normal(q[0], q[1], q[2], n1);
			if (!(n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2] > 0))
				return 0;
		}
	return 1;
}

/* Welds del onto keep, keep's ray the mean of the two sheets' (the seam
 * moves with both fronts); marks keep as welded. */
static long weld(struct mesh *m, int keep, int del, unsigned char *welded, size_t nwelded)
{
	double r[3], rl = 0;
	for (int k = 0; k < 3; k++) {
		r[k] = m->node[keep].s[k] + m->node[del].s[k];
		rl += r[k] * r[k];
	}
	rl = sqrt(rl);
	if (rl > 1e-6)
		for (int k = 0; k < 3; k++)
			m->node[keep].s[k] = r[k] / rl;
	m->node[keep].flags |= m->node[del].flags;
	long j = mesh_weld(m, keep, del);
	if ((size_t)keep < nwelded)
		welded[keep] = 1;
	return j;
}

struct oseg { double lo, hi; int s; };

static int cmp_oseg(const void *a, const void *b)
{
	const struct oseg *p = a, *q = b;
	if (p->lo != q->lo)
		return p->lo < q->lo ? -1 : 1;
	return (p->s > q->s) - (p->s < q->s);
}

static int cmp_int(const void *a, const void *b)
{
	int x = *(const int *)a, y = *(const int *)b;
	return (x > y) - (x < y);
}

/* Whether node i takes part: touched by this pass (or made by it). */
static int fresh_node(const unsigned char *fresh, size_t nfresh, int i)
{
	return (size_t)i >= nfresh || fresh[i];
}

/* The open segment leaving node a along the border (traversed from a by
 * its triangle), or -1 if there is not exactly one. */
static int leaving(const struct mesh *m, int a)
{
	int found = -1;
	for (int k = 0; k < m->node[a].nseg; k++) {
		int s = m->node[a].seg[k], from;
		double d[3];
		if (!is_open(m, s))
			continue;
		border_dir(m, s, &from, d);
		if (from != a)
			continue;
		if (found >= 0)
			return -1;
		found = s;
	}
	return found;
}

static int other_end(const struct mesh *m, int s, int a)
{
	return m->seg[s].n[0] == a ? m->seg[s].n[1] : m->seg[s].n[0];
}

/* Closes the small holes joining leaves where the two chains' nodes came
 * too close to be told apart (a node of one chain welded to a node next
 * to its partner): a border loop of three segments gets a triangle, one
 * of four two (across the shorter diagonal), each traversing the loop
 * the other way (consistent orientation).  Returns the border segments
 * so closed. */
static long fill_holes(struct mesh *m, const unsigned char *fresh, size_t nfresh)
{
	long added = 0;
	size_t ns = m->nseg;
	for (size_t s = 0; s < ns; s++) {
		if (!is_open(m, (int)s))
			continue;
		int a = m->seg[s].n[0], b = m->seg[s].n[1];
		if (!fresh_node(fresh, nfresh, a) || !fresh_node(fresh, nfresh, b))
			continue;
		int from;
		double d[3];
		border_dir(m, (int)s, &from, d);
		int v[4] = {from, other_end(m, (int)s, from), -1, -1}, k = 2;
		/* follow the border, at most four nodes round */
		for (; k <= 4; k++) {
			int e = leaving(m, v[k - 1]);
			if (e < 0)
				break;
			int w = other_end(m, e, v[k - 1]);
			if (w == v[0])
				break;
			if (k == 4 || !fresh_node(fresh, nfresh, w)) {
				k = 5;
				break;
			}
			v[k] = w;
		}
		/* a loop round one or two triangles only (an island) is no
		 * hole: filling it would close a pillow */
		if (k == 3 || k == 4) {
			int tris[4], island = 0;
			for (int i = 0; i < k; i++) {
				int e = mesh_find_segment(m, v[i], v[(i + 1) % k]);
				tris[i] = e >= 0 ? m->seg[e].t[0] : -1;
				for (int j = 0; j < i; j++)
					island |= tris[j] == tris[i];
				island |= tris[i] < 0;
			}
			if (island)
				continue;
		}
		if (k == 3 && leaving(m, v[2]) >= 0 &&
		    other_end(m, leaving(m, v[2]), v[2]) == v[0]) {
			mesh_add_triangle(m, v[0], v[2], v[1]);
			added += 3;
		} else if (k == 4 && leaving(m, v[3]) >= 0 &&
			   other_end(m, leaving(m, v[3]), v[3]) == v[0]) {
			double d02 = 0, d13 = 0;
			for (int c = 0; c < 3; c++) {
				double x = m->node[v[0]].p[c] - m->node[v[2]].p[c];
				double y = m->node[v[1]].p[c] - m->node[v[3]].p[c];
				d02 += x * x;
				d13 += y * y;
			}
			int r = d02 <= d13 ? 0 : 1;
			int p0 = v[r], p1 = v[r + 1], p2 = v[(r + 2) % 4], p3 = v[(r + 3) % 4];
			if (mesh_find_segment(m, p0, p2) >= 0)
				continue;
			mesh_add_triangle(m, p0, p2, p1);
			mesh_add_triangle(m, p0, p3, p2);
			added += 4;
		}
	}
	return added;
}

long deloop_zip(struct mesh *m, const unsigned char *fresh, size_t nfresh,
		unsigned char *welded, size_t nwelded)
{
	long joined = 0;
	for (int sweep = 0; sweep < ZIP_SWEEPS; sweep++) {
		/* the open segments between fresh nodes, sorted by low x */
		struct oseg *os = NULL;
		size_t nos = 0, cap = 0;
		int *nodes = NULL;
		size_t nnodes = 0, capn = 0;
		double wmax = 0, lmax = 0;
		for (size_t s = 0; s < m->nseg; s++) {
			if (!is_open(m, (int)s))
				continue;
			int a = m->seg[s].n[0], b = m->seg[s].n[1];
			if (!fresh_node(fresh, nfresh, a) || !fresh_node(fresh, nfresh, b))
				continue;
			const double *p = m->node[a].p, *q = m->node[b].p;
			xgrow(&os, &cap, nos + 1, sizeof *os);
			os[nos++] = (struct oseg){fmin(p[0], q[0]), fmax(p[0], q[0]), (int)s};
			wmax = fmax(wmax, fabs(p[0] - q[0]));
			lmax = fmax(lmax, mesh_seg_length(m, (int)s));
			xgrow(&nodes, &capn, nnodes + 2, sizeof *nodes);
			nodes[nnodes++] = a;
			nodes[nnodes++] = b;
		}
		long before = joined;
		if (nos > 1)
			qsort(os, nos, sizeof *os, cmp_oseg);
		if (nnodes > 1)
			qsort(nodes, nnodes, sizeof *nodes, cmp_int);
		double reach = ZIP_TOL * lmax;
		for (size_t i = 0; i < nnodes; i++) {
			int y = nodes[i];
			if ((i > 0 && nodes[i - 1] == y) || !m->node[y].alive)
				continue;
			/* y's way along its chain */
			double tan[3] = {0, 0, 0};
			int nopen = 0;
			for (int k = 0; k < m->node[y].nseg; k++) {
				int s = m->node[y].seg[k], from;
				double d[3];
				if (!is_open(m, s))
					continue;
				border_dir(m, s, &from, d);
				for (int c = 0; c < 3; c++)
					tan[c] += d[c];
				nopen++;
			}
			double tl = sqrt(tan[0] * tan[0] + tan[1] * tan[1] + tan[2] * tan[2]);
			if (nopen == 0 || !(tl > 1e-6))
				continue;
			const double *py = m->node[y].p;
			/* the nearest open segment of a chain running the other way */
			size_t lo = 0, hi = nos;
			while (lo < hi) {
				size_t mid = (lo + hi) / 2;
				if (os[mid].lo < py[0] - reach - wmax)
					lo = mid + 1;
				else
					hi = mid;
			}
			int best = -1;
			double bd = HUGE_VAL, bu = 0;
			for (size_t k = lo; k < nos && os[k].lo <= py[0] + reach; k++) {
				int e = os[k].s;
				if (!is_open(m, e))
					continue;
				int a = m->seg[e].n[0], b = m->seg[e].n[1];
				if (a == y || b == y)
					continue;
				int from;
				double d[3];
				border_dir(m, e, &from, d);
				if (!((d[0] * tan[0] + d[1] * tan[1] + d[2] * tan[2]) / tl < ZIP_OPPOSITE))
					continue;
				const double *pa = m->node[a].p, *pb = m->node[b].p;
				double ab[3], ay[3], ll = 0, u = 0;
				for (int c = 0; c < 3; c++) {
					ab[c] = pb[c] - pa[c];
					ay[c] = py[c] - pa[c];
					ll += ab[c] * ab[c];
					u += ab[c] * ay[c];
				}
				u = ll > 0 ? fmin(fmax(u / ll, 0), 1) : 0;
				double dd = 0;
				for (int c = 0; c < 3; c++) {
					double x = pa[c] + u * ab[c] - py[c];
					dd += x * x;
				}
				dd = sqrt(dd);
				if (dd <= ZIP_TOL * sqrt(ll) && dd < bd &&
				    (u <= ZIP_SNAP || u >= 1 - ZIP_SNAP ||
				     off_plane(m, e, py) <= ZIP_PLANE * sqrt(ll))) {
					bd = dd;
					bu = u;
					best = e;
				}
			}
			if (best < 0)
				continue;
			int a = m->seg[best].n[0], b = m->seg[best].n[1];
			if (bu <= ZIP_SNAP || bu >= 1 - ZIP_SNAP) {
				/* a node of the other chain is already here */
				int z = bu <= ZIP_SNAP ? a : b;
				int keep = z < y ? z : y, del = z < y ? y : z;
				unsigned fk = m->node[keep].flags & (ON_WALLS | ON_SUB);
				unsigned fd = m->node[del].flags & (ON_WALLS | ON_SUB);
				/* a node on a face of the box stays there */
				if ((fd & ~fk) && !(fk & ~fd)) {
					int t = keep;
					keep = del;
					del = t;
				} else if ((fd & ~fk) && (fk & ~fd)) {
					continue;
				}
				if (!mesh_can_weld(m, keep, del) || !keeps_sides(m, keep, del))
					continue;
				joined += weld(m, keep, del, welded, nwelded);
			} else {
				if (!can_insert(m, best, y))
					continue;
				/* the new node at y's own place, on the plane of the
				 * triangle split; its flags are y's */
				const struct node *na = &m->node[a], *nb = &m->node[b];
				double r[3], rl = 0, p[3];
				for (int c = 0; c < 3; c++) {
					r[c] = na->s[c] + bu * (nb->s[c] - na->s[c]);
					rl += r[c] * r[c];
					p[c] = py[c];
				}
				rl = sqrt(rl);
				for (int c = 0; c < 3; c++)
					r[c] = rl > 1e-12 ? r[c] / rl : na->s[c];
				unsigned fl = na->flags & nb->flags & (ON_WALLS | ON_SUB);
				int z = mesh_split(m, best, p, r, fl);
				joined += weld(m, y, z, welded, nwelded);
			}
		}
		free(os);
		free(nodes);
		if (joined == before)
			break;
	}
	joined += fill_holes(m, fresh, nfresh);
	return joined;
}
