/*
 * mesh - unit tests of the mesh data structure and its operations
 * (thesis 8.2.2, 8.4), each checked with mesh_check and against counts
 * and positions worked out by hand:
 *   - the checker finds planted faults (a broken back-link, a flipped
 *     triangle, a duplicate segment): it can fail;
 *   - the flat start is clean, no segment is longer than S_ideal, and its
 *     border lies on the walls;
 *   - splitting a segment adds 1 node, 3 segments, 2 triangles;
 *   - merging: a wall node is never deleted (Figure 8.5); the base of a
 *     3-triangle pyramid is never merged (Figure 8.8) while its apex may
 *     be, removing 1 node, 3 segments, 2 triangles;
 *   - clipping a mesh pushed half out of the box leaves only nodes in
 *     the box, border nodes exactly on the face and flagged;
 *   - arc interpolation puts the new node of two nodes on a circle with
 *     radial rays on the circle (to 1e-12), linear interpolation at
 *     distance cos(theta) from the centre.
 */
#include "etch.h"

#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int bad;

#define CHECK(cond, ...) do { if (!(cond)) { printf("FAIL line %d: ", __LINE__); \
	printf(__VA_ARGS__); printf("\n"); bad = 1; } } while (0)

static void clean(const struct mesh *m, const char *what)
{
	const char *e = mesh_check(m);
	CHECK(e == NULL, "%s: %s", what, e);
}

static struct ratefile *box(void)
{
	double b[6] = {-1, 1, -1, 1, -1, 0};
	struct ratefile *r = fmt_rate_new(3, 3, 3, b);
	for (int i = 0; i < 27; i++)
		fmt_rate_values(r)[i] = 1;
	return r;
}

static void test_checker(const struct rfield *f)
{
	struct mesh *m = mesh_new();
	start_flat(m, f, 0.5);
	clean(m, "flat start");
	m->seg[3].n[0] = m->seg[3].n[0] == 0 ? 1 : 0;
	CHECK(mesh_check(m) != NULL, "broken back-link not found");
	mesh_free(m);
	m = mesh_new();
	start_flat(m, f, 0.5);
	struct triangle *t = &m->tri[0];
	int n = t->n[1], s = t->s[0];
	t->n[1] = t->n[2];
	t->n[2] = n;
	t->s[0] = t->s[2];
	t->s[2] = s;
	CHECK(mesh_check(m) != NULL, "flipped triangle not found");
	mesh_free(m);
}

static void test_flat_split(const struct rfield *f)
{
	struct mesh *m = mesh_new();
	start_flat(m, f, 0.25);
	clean(m, "flat");
	for (size_t k = 0; k < m->nseg; k++)
		CHECK(mesh_seg_length(m, (int)k) <= 0.25 * (1 + 1e-9),
		      "flat start segment %zu of length %g > S_ideal", k, mesh_seg_length(m, (int)k));
	for (size_t s = 0; s < m->nseg; s++) {
		if (m->seg[s].t[1] >= 0)
			continue;
		unsigned c = m->node[m->seg[s].n[0]].flags & m->node[m->seg[s].n[1]].flags;
		CHECK(c & ON_SIDES, "flat border segment %zu not on a wall", s);
	}
	/* an interior segment */
	size_t s = 0;
	while (m->seg[s].t[1] < 0)
		s++;
	size_t nn = m->live_node, ns = m->live_seg, nt = m->live_tri;
	double p[3], r[3];
	interp_node(&m->node[m->seg[s].n[0]], &m->node[m->seg[s].n[1]], 0, p, r);
	mesh_split(m, (int)s, p, r, 0);
	clean(m, "after split");
	CHECK(m->live_node == nn + 1 && m->live_seg == ns + 3 && m->live_tri == nt + 2,
	      "split counts %zu %zu %zu", m->live_node, m->live_seg, m->live_tri);
	/* a segment from a wall node to an interior node: the wall node
	 * may not be deleted */
	for (size_t k = 0; k < m->nseg; k++) {
		int a = m->seg[k].n[0], b = m->seg[k].n[1];
		if ((m->node[a].flags & ON_SIDES) && !(m->node[b].flags & ON_SIDES)) {
			CHECK(!mesh_can_merge(m, (int)k, a), "wall node %d may be deleted", a);
			break;
		}
	}
	mesh_free(m);
}

/* Adds triangle (a, b, c) oriented with its normal away from the origin. */
static void add_out(struct mesh *m, int a, int b, int c)
{
	const double *p = m->node[a].p, *q = m->node[b].p, *r = m->node[c].p;
	double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
	double w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
	double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
	if (n[0] * (p[0] + q[0] + r[0]) + n[1] * (p[1] + q[1] + r[1]) + n[2] * (p[2] + q[2] + r[2]) > 0)
		mesh_add_triangle(m, a, b, c);
	else
		mesh_add_triangle(m, a, c, b);
}

/* An octahedron with one face replaced by a pyramid of three triangles
 * around an apex node pushed outwards. */
static void test_pyramid(void)
{
	struct mesh *m = mesh_new();
	double v[7][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
			  {0.4, 0.4, 0.4}};
	int id[7];
	for (int i = 0; i < 7; i++) {
		double s[3], r = sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
		for (int d = 0; d < 3; d++)
			s[d] = v[i][d] / r;
		id[i] = mesh_add_node(m, v[i], s, 0);
	}
	/* faces of the octahedron, outward: (+x +y +z) replaced */
	int faces[7][3] = {{0, 3, 4}, {3, 1, 4}, {1, 2, 4}, {0, 2, 5}, {2, 1, 5}, {1, 3, 5}, {3, 0, 5}};
	for (int k = 0; k < 7; k++)
		add_out(m, id[faces[k][0]], id[faces[k][1]], id[faces[k][2]]);
	add_out(m, id[0], id[2], id[6]);
	add_out(m, id[2], id[4], id[6]);
	add_out(m, id[4], id[0], id[6]);
	clean(m, "pyramid");
	CHECK(m->live_tri == 10 && m->live_seg == 15 && m->live_node == 7, "pyramid counts");
	int base = mesh_find_segment(m, id[0], id[2]);
	CHECK(!mesh_can_merge(m, base, id[0]) && !mesh_can_merge(m, base, id[2]),
	      "pyramid base may be merged (Figure 8.8)");
	int side = mesh_find_segment(m, id[6], id[0]);
	CHECK(mesh_can_merge(m, side, id[6]), "pyramid apex may not be merged");
	mesh_merge(m, side, id[6]);
	clean(m, "after merge");
	mesh_compact(m);
	clean(m, "after compact");
	CHECK(m->live_tri == 8 && m->live_seg == 12 && m->live_node == 6,
	      "merge counts %zu %zu %zu", m->live_tri, m->live_seg, m->live_node);
	/* the octahedron now: every merge would leave a valence-3 apex... or
	 * not; either way the mesh must stay clean */
	for (size_t s = 0; s < m->nseg; s++)
		if (m->seg[s].alive && mesh_can_merge(m, (int)s, m->seg[s].n[0])) {
			mesh_merge(m, (int)s, m->seg[s].n[0]);
			clean(m, "octahedron merge");
		}
	mesh_free(m);
}

static void test_clip(const struct rfield *f)
{
	struct mesh *m = mesh_new();
	start_flat(m, f, 0.2);
	for (size_t i = 0; i < m->nnode; i++) {
		m->node[i].p[0] += 0.73;
		m->node[i].p[2] -= 0.1 + 0.2 * m->node[i].p[1];
		m->node[i].flags &= ~(unsigned)(ON_X0 | ON_X1);
	}
	struct etch_stats st = {0};
	clip_mesh(m, f, &st);
	mesh_compact(m);
	clean(m, "after clip");
	CHECK(m->live_tri > 0 && st.clipped_tris > 0, "clip removed nothing or all");
	int on = 0;
	for (size_t i = 0; i < m->nnode; i++) {
		const struct node *n = &m->node[i];
		CHECK(n->p[0] <= f->hi[0] && n->p[0] >= f->lo[0], "node %zu outside, x %g", i, n->p[0]);
		if (n->flags & ON_X1) {
			on++;
			CHECK(n->p[0] == f->hi[0], "flagged node off the face");
		}
	}
	CHECK(on > 5, "only %d nodes on the clipped face", on);
	/* the border near the clipped face (the x0 side was moved inwards
	 * and unflagged above, so it is a free border) */
	for (size_t s = 0; s < m->nseg; s++)
		if (m->seg[s].t[1] < 0 && m->node[m->seg[s].n[0]].p[0] > 0.5 &&
		    m->node[m->seg[s].n[1]].p[0] > 0.5) {
			unsigned c = m->node[m->seg[s].n[0]].flags & m->node[m->seg[s].n[1]].flags;
			CHECK(c & ON_WALLS, "border segment %zu not on a face after clipping", s);
		}
	mesh_free(m);
}

static void test_arc(void)
{
	struct node a = {0}, b = {0};
	double th = 0.3;
	/* two points on the unit circle about (1, 2, 3), in a tilted plane */
	double u[3] = {0.6, 0, 0.8}, w[3] = {0, 1, 0}, c[3] = {1, 2, 3};
	for (int d = 0; d < 3; d++) {
		a.s[d] = cos(th) * u[d] + sin(th) * w[d];
		b.s[d] = cos(th) * u[d] - sin(th) * w[d];
		a.p[d] = c[d] + a.s[d];
		b.p[d] = c[d] + b.s[d];
	}
	double p[3], r[3], q[3], rq[3];
	interp_node(&a, &b, 0, p, r);
	interp_node(&a, &b, 1, q, rq);
	double ra = sqrt(pow(p[0] - c[0], 2) + pow(p[1] - c[1], 2) + pow(p[2] - c[2], 2));
	double rl = sqrt(pow(q[0] - c[0], 2) + pow(q[1] - c[1], 2) + pow(q[2] - c[2], 2));
	CHECK(fabs(ra - 1) < 1e-12, "arc node at radius %.15g", ra);
	CHECK(fabs(rl - cos(th)) < 1e-12, "linear node at radius %.15g", rl);
	CHECK(fabs(r[0] - u[0]) < 1e-12 && fabs(r[1]) < 1e-12, "arc ray wrong");
	/* concave: rays converging (a front moving into its centre) */
	for (int d = 0; d < 3; d++) {
		a.s[d] = -a.s[d];
		b.s[d] = -b.s[d];
	}
	interp_node(&a, &b, 0, p, r);
	ra = sqrt(pow(p[0] - c[0], 2) + pow(p[1] - c[1], 2) + pow(p[2] - c[2], 2));
	CHECK(fabs(ra - 1) < 1e-12, "concave arc node at radius %.15g", ra);
}

int main(void)
{
	struct ratefile *r = box();
	struct rfield f;
	fmt_rate_field(&f, r, "box");
	test_checker(&f);
	test_flat_split(&f);
	test_pyramid();
	test_clip(&f);
	test_arc();
	fmt_rate_free(r);
	if (!bad)
		printf("all mesh tests passed\n");
	return bad;
}
