/*
 * ray_clip.c - mesh clipping (thesis 8.4.2, Figure 8.9): for each of the six
 * faces of the box in turn, every segment with one node outside and the
 * other inside is cut where it crosses the face (a new node, flagged as
 * on that face, its ray interpolated); then every triangle with a node
 * outside goes, and with it the segments and nodes left unattached.
 * After the cuts no triangle has nodes on both sides, so what is left
 * ends exactly on the face.  Rates are not defined outside the box, so
 * nothing outside it is worth tracking (7.5.2.1).
 *
 * Nodes within CLIP_EPS of a face count as on it, so a node sliding along
 * a wall (boundary flattening) is never cut off by rounding.
 */
#include "etch.h"

#include "util.h"

#include <math.h>

/* Distance (relative to the box size) within which a node is on a face:
 * far above rounding of coordinates of order 1 um, far below any segment. */
#define CLIP_EPS 1e-9
/* A crossing nearer than this fraction of the segment to one of its
 * nodes is not cut: that node is moved onto the face instead (by less
 * than this fraction of a segment).  A node a hair inside a face, cut
 * step after step, would otherwise leave a new node beside itself each
 * clip (pinned to the face, so never merged away): near a corner of the
 * box, with rays leaning out of it, the fans of such nodes grew the mesh
 * geometrically with the number of clips, so a smaller time step stopped
 * the run (a smooth off-centre Gaussian, tests/etch/080-dt-bound.sh). */
#define CLIP_SNAP 1e-3

static const unsigned face_flag[6] = {ON_X0, ON_X1, ON_Y0, ON_Y1, ON_SUB, ON_TOP};

/* -1 inside, 0 on the face, 1 outside */
static int side(double c, double v, int upper, double eps)
{
	double out = upper ? c - v : v - c;
	return out > eps ? 1 : out < -eps ? -1 : 0;
}

void clip_mesh(struct mesh *m, const struct rfield *f, struct etch_stats *st)
{
	double size = 0;
	for (int d = 0; d < 3; d++)
		if (f->hi[d] - f->lo[d] > size)
			size = f->hi[d] - f->lo[d];
	double eps = CLIP_EPS * size;
	st->clips++;
	for (int face = 0; face < 6; face++) {
		int ax = face / 2, upper = face & 1;
		double v = upper ? f->hi[ax] : f->lo[ax];
		size_t nseg = m->nseg;
		int any = 0;
		for (size_t s = 0; s < nseg; s++) {
			if (!m->seg[s].alive)
				continue;
			const struct node *a = &m->node[m->seg[s].n[0]], *b = &m->node[m->seg[s].n[1]];
			int sa = side(a->p[ax], v, upper, eps), sb = side(b->p[ax], v, upper, eps);
			any |= sa > 0 || sb > 0;
			if (sa * sb >= 0)
				continue;
			double t = (v - a->p[ax]) / (b->p[ax] - a->p[ax]);
			if (t < CLIP_SNAP || t > 1 - CLIP_SNAP) {
				/* a node at the face: put it on it */
				struct node *nd = &m->node[m->seg[s].n[t < CLIP_SNAP ? 0 : 1]];
				nd->p[ax] = v;
				if (face != 4)
					nd->flags |= face_flag[face];
				continue;
			}
			double p[3], r[3];
			for (int d = 0; d < 3; d++) {
				p[d] = a->p[d] + t * (b->p[d] - a->p[d]);
				r[d] = a->s[d] + t * (b->s[d] - a->s[d]);
			}
			p[ax] = v;
			double rl = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
			for (int d = 0; d < 3; d++)
				r[d] = rl > 1e-12 ? r[d] / rl : a->s[d];
			unsigned fl = (a->flags & b->flags & (ON_WALLS | ON_SUB)) | face_flag[face];
			mesh_split(m, (int)s, p, r, fl);
		}
		if (!any)
			continue;
		for (size_t t = 0; t < m->ntri; t++) {
			if (!m->tri[t].alive)
				continue;
			for (int j = 0; j < 3; j++)
				if (side(m->node[m->tri[t].n[j]].p[ax], v, upper, eps) > 0) {
					mesh_kill_triangle(m, (int)t);
					st->clipped_tris++;
					break;
				}
		}
		/* nodes left on the face are on it: pin them there */
		for (size_t n = 0; n < m->nnode; n++) {
			struct node *nd = &m->node[n];
			if (nd->alive && side(nd->p[ax], v, upper, eps) == 0 &&
			    !(nd->flags & face_flag[face]) && face != 4) {
				nd->p[ax] = v;
				nd->flags |= face_flag[face];
			}
		}
	}
}
