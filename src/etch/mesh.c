/*
 * mesh.c - the node/segment/triangle data structure of the 3D ray-string
 * algorithm (thesis 8.2.2, Figure 8.1), its two editing primitives
 * (segment splitting, Figure 8.2, and segment merging, Figure 8.4) and
 * its consistency checker.  See mesh.h for the representation.
 *
 * Every primitive leaves the mesh consistent; the tests run mesh_check
 * after every step of every simulation.
 */
#include "mesh.h"

#include "util.h"
#include "vec3.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct mesh *mesh_new(void)
{
	return xcalloc(1, sizeof(struct mesh));
}

void mesh_free(struct mesh *m)
{
	if (!m)
		return;
	for (size_t i = 0; i < m->nnode; i++)
		free(m->node[i].seg);
	free(m->node);
	free(m->seg);
	free(m->tri);
	free(m);
}

struct mesh *mesh_copy(const struct mesh *m)
{
	struct mesh *c = xcalloc(1, sizeof *c);
	*c = *m;
	c->node = xreallocarray(NULL, m->capnode + 1, sizeof *c->node);
	c->seg = xreallocarray(NULL, m->capseg + 1, sizeof *c->seg);
	c->tri = xreallocarray(NULL, m->captri + 1, sizeof *c->tri);
	if (m->nnode)
		memcpy(c->node, m->node, m->nnode * sizeof *c->node);
	if (m->nseg)
		memcpy(c->seg, m->seg, m->nseg * sizeof *c->seg);
	if (m->ntri)
		memcpy(c->tri, m->tri, m->ntri * sizeof *c->tri);
	for (size_t i = 0; i < m->nnode; i++) {
		/* the same capacity, and no array where there was none: the
		 * mesh code grows a node's list from (NULL, 0) */
		const struct node *n = &m->node[i];
		c->node[i].seg = NULL;
		if (n->seg && n->capseg > 0) {
			c->node[i].seg = xreallocarray(NULL, (size_t)n->capseg, sizeof *n->seg);
			if (n->nseg)
				memcpy(c->node[i].seg, n->seg, (size_t)n->nseg * sizeof *n->seg);
		}
	}
	return c;
}

int mesh_add_node(struct mesh *m, const double p[3], const double s[3], unsigned flags)
{
	if (m->nnode >= (size_t)0x7fffffff)
		die("mesh: too many nodes");
	xgrow(&m->node, &m->capnode, m->nnode + 1, sizeof *m->node);
	struct node *n = &m->node[m->nnode];
	memset(n, 0, sizeof *n);
	memcpy(n->p, p, sizeof n->p);
	memcpy(n->s, s, sizeof n->s);
	n->flags = flags;
	n->alive = 1;
	m->live_node++;
	return (int)m->nnode++;
}

static void node_attach(struct mesh *m, int n, int s)
{
	struct node *nd = &m->node[n];
	if (nd->nseg == nd->capseg) {
		size_t cap = (size_t)nd->capseg;
		xgrow(&nd->seg, &cap, (size_t)nd->nseg + 1, sizeof *nd->seg);
		nd->capseg = (int)cap;
	}
	nd->seg[nd->nseg++] = s;
}

static void node_detach(struct mesh *m, int n, int s)
{
	struct node *nd = &m->node[n];
	for (int i = 0; i < nd->nseg; i++)
		if (nd->seg[i] == s) {
			/* keep the order: output and merging order depend on it */
			memmove(nd->seg + i, nd->seg + i + 1,
				(size_t)(nd->nseg - i - 1) * sizeof *nd->seg);
			nd->nseg--;
			return;
		}
}

static int seg_other(const struct mesh *m, int s, int n)
{
	const struct segment *sg = &m->seg[s];
	return sg->n[0] == n ? sg->n[1] : sg->n[0];
}

static int add_segment(struct mesh *m, int a, int b)
{
	if (m->nseg >= (size_t)0x7fffffff)
		die("mesh: too many segments");
	xgrow(&m->seg, &m->capseg, m->nseg + 1, sizeof *m->seg);
	int s = (int)m->nseg++;
	m->seg[s] = (struct segment){{a, b}, {-1, -1}, 1};
	node_attach(m, a, s);
	node_attach(m, b, s);
	m->live_seg++;
	return s;
}

static void kill_node(struct mesh *m, int n)
{
	struct node *nd = &m->node[n];
	free(nd->seg);
	nd->seg = NULL;
	nd->nseg = nd->capseg = 0;
	nd->alive = 0;
	m->live_node--;
}

static void kill_segment(struct mesh *m, int s)
{
	struct segment *sg = &m->seg[s];
	node_detach(m, sg->n[0], s);
	node_detach(m, sg->n[1], s);
	sg->alive = 0;
	m->live_seg--;
}

static void seg_add_tri(struct mesh *m, int s, int t)
{
	struct segment *sg = &m->seg[s];
	if (sg->t[0] < 0)
		sg->t[0] = t;
	else if (sg->t[1] < 0)
		sg->t[1] = t;
	else
		die("mesh: segment %d has more than two triangles", s);
}

static void seg_remove_tri(struct mesh *m, int s, int t)
{
	struct segment *sg = &m->seg[s];
	if (sg->t[0] == t) {
		sg->t[0] = sg->t[1];
		sg->t[1] = -1;
	} else if (sg->t[1] == t) {
		sg->t[1] = -1;
	}
}

static void seg_replace_tri(struct mesh *m, int s, int from, int to)
{
	struct segment *sg = &m->seg[s];
	if (sg->t[0] == from)
		sg->t[0] = to;
	else if (sg->t[1] == from)
		sg->t[1] = to;
}

int mesh_find_segment(const struct mesh *m, int a, int b)
{
	const struct node *na = &m->node[a];
	for (int i = 0; i < na->nseg; i++)
		if (seg_other(m, na->seg[i], a) == b)
			return na->seg[i];
	return -1;
}

static int seg_get(struct mesh *m, int a, int b)
{
	int s = mesh_find_segment(m, a, b);
	return s >= 0 ? s : add_segment(m, a, b);
}

/* Stores triangle slot t as (a, b, c) with segments sa sb sc, no links. */
static void tri_set(struct mesh *m, int t, int a, int b, int c, int sa, int sb, int sc)
{
	struct triangle *tr = &m->tri[t];
	tr->n[0] = a; tr->n[1] = b; tr->n[2] = c;
	tr->s[0] = sa; tr->s[1] = sb; tr->s[2] = sc;
	tr->alive = 1;
}

static int tri_slot(struct mesh *m)
{
	if (m->ntri >= (size_t)0x7fffffff)
		die("mesh: too many triangles");
	xgrow(&m->tri, &m->captri, m->ntri + 1, sizeof *m->tri);
	m->live_tri++;
	return (int)m->ntri++;
}

int mesh_add_triangle(struct mesh *m, int a, int b, int c)
{
	int sa = seg_get(m, a, b), sb = seg_get(m, b, c), sc = seg_get(m, c, a);
	int t = tri_slot(m);
	tri_set(m, t, a, b, c, sa, sb, sc);
	seg_add_tri(m, sa, t);
	seg_add_tri(m, sb, t);
	seg_add_tri(m, sc, t);
	return t;
}

double mesh_dead_share(const struct mesh *m)
{
	double a = m->nnode ? 1 - (double)m->live_node / (double)m->nnode : 0;
	double b = m->nseg ? 1 - (double)m->live_seg / (double)m->nseg : 0;
	double c = m->ntri ? 1 - (double)m->live_tri / (double)m->ntri : 0;
	return fmax(a, fmax(b, c));
}

double mesh_seg_length(const struct mesh *m, int s)
{
	const double *a = m->node[m->seg[s].n[0]].p, *b = m->node[m->seg[s].n[1]].p;
	double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
	return sqrt(dx * dx + dy * dy + dz * dz);
}

/* Segment splitting, thesis 8.4.1.1 and Figure 8.2: segment (a, b) becomes
 * (a, c) and (c, b); each triangle (u, v, o) on it becomes (u, c, o) and
 * (c, v, o) with a new segment (c, o). */
int mesh_split(struct mesh *m, int s, const double p[3], const double r[3],
	       unsigned flags)
{
	int a = m->seg[s].n[0], b = m->seg[s].n[1];
	int tris[2] = {m->seg[s].t[0], m->seg[s].t[1]};
	int c = mesh_add_node(m, p, r, flags);
	/* s keeps (a, c); s2 is (c, b) */
	node_detach(m, b, s);
	m->seg[s].n[1] = c;
	node_attach(m, c, s);
	int s2 = add_segment(m, c, b);
	m->seg[s].t[0] = m->seg[s].t[1] = -1;
	for (int k = 0; k < 2; k++) {
		int t = tris[k];
		if (t < 0)
			continue;
		struct triangle old = m->tri[t];
		int i = 0;
		while (old.s[i] != s)
			i++;
		int u = old.n[i], v = old.n[(i + 1) % 3], o = old.n[(i + 2) % 3];
		int svo = old.s[(i + 1) % 3], sou = old.s[(i + 2) % 3];
		int e = add_segment(m, c, o);
		int t2 = tri_slot(m);
		int suc = u == a ? s : s2, scv = v == b ? s2 : s;
		tri_set(m, t, u, c, o, suc, e, sou);
		tri_set(m, t2, c, v, o, scv, svo, e);
		seg_replace_tri(m, svo, t, t2);
		seg_add_tri(m, e, t);
		seg_add_tri(m, e, t2);
		seg_add_tri(m, suc, t);
		seg_add_tri(m, scv, t2);
	}
	return c;
}

static void tri_normal(const double *a, const double *b, const double *c, double nrm[3])
{
	double u[3], v[3];
	vec3_sub(b, a, u);
	vec3_sub(c, a, v);
	vec3_cross(u, v, nrm);
}

/* Marks on neighbours: 1 for neighbours of del, 2 added for those of keep. */
int mesh_can_merge(const struct mesh *m, int s, int del)
{
	const struct segment *sg = &m->seg[s];
	int keep = seg_other(m, s, del);
	const struct node *nd = &m->node[del], *nk = &m->node[keep];
	/* never delete a node on a wall (thesis 8.4.1.2, Figure 8.5); a node
	 * stopped on the substrate only merges onto another stopped node */
	if (nd->flags & ON_WALLS)
		return 0;
	if ((nd->flags & ON_SUB) && !(nk->flags & ON_SUB))
		return 0;
	if (sg->t[0] < 0 || sg->t[1] < 0)
		return 0;
	for (int i = 0; i < nd->nseg; i++) {
		const struct segment *x = &m->seg[nd->seg[i]];
		if (x->t[0] < 0 || x->t[1] < 0)
			return 0;       /* del is on a mesh border */
	}
	int apex[2];
	for (int k = 0; k < 2; k++) {
		const struct triangle *t = &m->tri[sg->t[k]];
		apex[k] = t->n[0] != del && t->n[0] != keep ? t->n[0]
			: t->n[1] != del && t->n[1] != keep ? t->n[1] : t->n[2];
		/* 3-triangle pyramid, Figure 8.8: the apex would be left with
		 * two segments, the pyramid folded flat */
		if (m->node[apex[k]].nseg <= 3)
			return 0;
	}
	if (apex[0] == apex[1])
		return 0;
	/* link condition: a common neighbour other than the two apexes
	 * would give two segments between the same nodes after merging */
	for (int i = 0; i < nd->nseg; i++) {
		int y = seg_other(m, nd->seg[i], del);
		if (y == keep || y == apex[0] || y == apex[1])
			continue;
		if (mesh_find_segment(m, keep, y) >= 0)
			return 0;
	}
	/* no triangle may turn over when del moves onto keep */
	for (int i = 0; i < nd->nseg; i++) {
		const struct segment *x = &m->seg[nd->seg[i]];
		for (int k = 0; k < 2; k++) {
			int t = x->t[k];
			if (t == sg->t[0] || t == sg->t[1])
				continue;
			const struct triangle *tr = &m->tri[t];
			const double *p[3], *q[3];
			for (int j = 0; j < 3; j++) {
				p[j] = m->node[tr->n[j]].p;
				q[j] = tr->n[j] == del ? nk->p : p[j];
			}
			double n0[3], n1[3];
			tri_normal(p[0], p[1], p[2], n0);
			tri_normal(q[0], q[1], q[2], n1);
			if (n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2] < 0)
				return 0;
		}
	}
	return 1;
}

/* The triangles around node n, each once, in a new array (*out, freed by
 * the caller); returns their number.  Merging and welding collect them
 * before n's segments move. */
static int node_triangles(const struct mesh *m, int n, int **out)
{
	const struct node *nd = &m->node[n];
	int *around = xreallocarray(NULL, 2 * (size_t)nd->nseg + 1, sizeof *around);
	int na = 0;
	for (int i = 0; i < nd->nseg; i++)
		for (int k = 0; k < 2; k++) {
			int t = m->seg[nd->seg[i]].t[k], dup = 0;
			for (int j = 0; j < na; j++)
				dup |= around[j] == t;
			if (t >= 0 && !dup)
				around[na++] = t;
		}
	*out = around;
	return na;
}

/* Segment merging, thesis 8.4.1.2 and Figure 8.4. */
void mesh_merge(struct mesh *m, int s, int del)
{
	int keep = seg_other(m, s, del);
	int tris[2] = {m->seg[s].t[0], m->seg[s].t[1]};
	/* the triangles around del, to be given to keep at the end (a
	 * segment of del may be gone by then, e.g. when del is the apex of
	 * a 3-triangle fan) */
	struct node *nd = &m->node[del];
	int *around;
	int na = node_triangles(m, del, &around);
	for (int k = 0; k < 2; k++) {
		int t = tris[k];
		struct triangle *tr = &m->tri[t];
		int o = -1;
		for (int j = 0; j < 3; j++)
			if (tr->n[j] != del && tr->n[j] != keep)
				o = tr->n[j];
		int sd = mesh_find_segment(m, del, o), sk = mesh_find_segment(m, keep, o);
		seg_remove_tri(m, sd, t);
		seg_remove_tri(m, sk, t);
		tr->alive = 0;
		m->live_tri--;
		/* the triangle beyond (del, o) now borders (keep, o) */
		int beyond = m->seg[sd].t[0];
		if (beyond >= 0) {
			struct triangle *tb = &m->tri[beyond];
			for (int j = 0; j < 3; j++)
				if (tb->s[j] == sd)
					tb->s[j] = sk;
			seg_add_tri(m, sk, beyond);
		}
		m->seg[sd].t[0] = m->seg[sd].t[1] = -1;
		kill_segment(m, sd);
	}
	kill_segment(m, s);
	/* the remaining segments and triangles of del go to keep */
	for (int i = 0; i < na; i++) {
		struct triangle *tr = &m->tri[around[i]];
		if (tr->alive)
			for (int j = 0; j < 3; j++)
				if (tr->n[j] == del)
					tr->n[j] = keep;
	}
	free(around);
	nd = &m->node[del];
	for (int i = 0; i < nd->nseg; i++) {
		int x = nd->seg[i];
		struct segment *sg = &m->seg[x];
		if (sg->n[0] == del)
			sg->n[0] = keep;
		else
			sg->n[1] = keep;
		node_attach(m, keep, x);
	}
	kill_node(m, del);
}

/* Whether triangle t traverses its segment s from node n, and its node
 * opposite s (through *apex). */
static int tri_leaves(const struct mesh *m, int t, int s, int n, int *apex)
{
	const struct triangle *tr = &m->tri[t];
	int j = 0;
	while (j < 2 && tr->s[j] != s)
		j++;
	*apex = tr->n[(j + 2) % 3];
	return tr->n[j] == n;
}

int mesh_can_weld(const struct mesh *m, int keep, int del)
{
	if (keep == del || !m->node[keep].alive || !m->node[del].alive)
		return 0;
	if (mesh_find_segment(m, keep, del) >= 0)
		return 0;
	const struct node *nd = &m->node[del];
	for (int i = 0; i < nd->nseg; i++) {
		int sd = nd->seg[i], x = seg_other(m, sd, del);
		int sk = mesh_find_segment(m, keep, x);
		if (sk < 0)
			continue;
		const struct segment *a = &m->seg[sd], *b = &m->seg[sk];
		/* twins: one triangle each, else three would share a segment */
		if (a->t[0] < 0 || a->t[1] >= 0 || b->t[0] < 0 || b->t[1] >= 0)
			return 0;
		int apex_d, apex_k;
		int fd = tri_leaves(m, a->t[0], sd, del, &apex_d);
		int fk = tri_leaves(m, b->t[0], sk, keep, &apex_k);
		/* orientation consistent after the weld, and no two triangles
		 * on the same three nodes */
		if (fd == fk || apex_d == apex_k)
			return 0;
	}
	return 1;
}

int mesh_weld(struct mesh *m, int keep, int del)
{
	int joined = 0;
	/* del's triangles, collected before its segments move */
	int *around;
	int na = node_triangles(m, del, &around);
	while (m->node[del].nseg > 0) {
		int sd = m->node[del].seg[0], x = seg_other(m, sd, del);
		int sk = mesh_find_segment(m, keep, x);
		if (sk < 0) {
			/* a segment new to keep moves over */
			node_detach(m, del, sd);
			struct segment *sg = &m->seg[sd];
			sg->n[sg->n[0] == del ? 0 : 1] = keep;
			node_attach(m, keep, sd);
			continue;
		}
		/* twin border segments: sd's triangle now borders sk */
		int t = m->seg[sd].t[0];
		struct triangle *tr = &m->tri[t];
		for (int j = 0; j < 3; j++)
			if (tr->s[j] == sd)
				tr->s[j] = sk;
		seg_add_tri(m, sk, t);
		m->seg[sd].t[0] = m->seg[sd].t[1] = -1;
		kill_segment(m, sd);
		joined++;
	}
	for (int i = 0; i < na; i++) {
		struct triangle *tr = &m->tri[around[i]];
		for (int j = 0; j < 3; j++)
			if (tr->n[j] == del)
				tr->n[j] = keep;
	}
	free(around);
	kill_node(m, del);
	return joined;
}

void mesh_kill_triangle(struct mesh *m, int t)
{
	struct triangle *tr = &m->tri[t];
	if (!tr->alive)
		return;
	tr->alive = 0;
	m->live_tri--;
	for (int j = 0; j < 3; j++) {
		int s = tr->s[j];
		seg_remove_tri(m, s, t);
		if (m->seg[s].t[0] < 0) {
			int a = m->seg[s].n[0], b = m->seg[s].n[1];
			kill_segment(m, s);
			if (m->node[a].nseg == 0)
				kill_node(m, a);
			if (m->node[b].nseg == 0)
				kill_node(m, b);
		}
	}
}

/* x renumbered: slots below d (the first dead one) keep their number */
static inline int renum(int x, size_t d, const int *map)
{
	return (size_t)x < d ? x : map[x];
}

void mesh_compact(struct mesh *m)
{
	/* nothing died since the last compaction (most steps of a smooth
	 * advance): renumbering would be the identity, so skip the rewrite */
	if (m->live_node == m->nnode && m->live_seg == m->nseg && m->live_tri == m->ntri)
		return;
	/* Below the first dead slot of an array nothing moves and no number
	 * changes, so only the rest is renumbered and moved, and references
	 * into an array with no dead slot are left alone. */
	size_t dn = 0, ds = 0, dt = 0;
	while (dn < m->nnode && m->node[dn].alive)
		dn++;
	while (ds < m->nseg && m->seg[ds].alive)
		ds++;
	while (dt < m->ntri && m->tri[dt].alive)
		dt++;
	int *nmap = xreallocarray(NULL, m->nnode + 1, sizeof *nmap);
	int *smap = xreallocarray(NULL, m->nseg + 1, sizeof *smap);
	int *tmap = xreallocarray(NULL, m->ntri + 1, sizeof *tmap);
	size_t k = dn;
	for (size_t i = dn; i < m->nnode; i++)
		nmap[i] = m->node[i].alive ? (int)k++ : -1;
	k = ds;
	for (size_t i = ds; i < m->nseg; i++)
		smap[i] = m->seg[i].alive ? (int)k++ : -1;
	k = dt;
	for (size_t i = dt; i < m->ntri; i++)
		tmap[i] = m->tri[i].alive ? (int)k++ : -1;
	int segs_moved = ds < m->nseg, nodes_moved = dn < m->nnode, tris_moved = dt < m->ntri;

	k = dn;
	for (size_t i = 0; i < m->nnode; i++) {
		struct node *nd = &m->node[i];
		if (!nd->alive)
			continue;
		if (segs_moved)
			for (int j = 0; j < nd->nseg; j++)
				nd->seg[j] = renum(nd->seg[j], ds, smap);
		if (i >= dn)
			m->node[k++] = *nd;
	}
	m->nnode = k;
	k = ds;
	for (size_t i = 0; i < m->nseg; i++) {
		struct segment *sg = &m->seg[i];
		if (!sg->alive)
			continue;
		for (int j = 0; j < 2; j++) {
			if (nodes_moved)
				sg->n[j] = renum(sg->n[j], dn, nmap);
			if (tris_moved && sg->t[j] >= 0)
				sg->t[j] = renum(sg->t[j], dt, tmap);
		}
		if (i >= ds)
			m->seg[k++] = *sg;
	}
	m->nseg = k;
	k = dt;
	for (size_t i = 0; i < m->ntri; i++) {
		struct triangle *tr = &m->tri[i];
		if (!tr->alive)
			continue;
		for (int j = 0; j < 3; j++) {
			if (nodes_moved)
				tr->n[j] = renum(tr->n[j], dn, nmap);
			if (segs_moved)
				tr->s[j] = renum(tr->s[j], ds, smap);
		}
		if (i >= dt)
			m->tri[k++] = *tr;
	}
	m->ntri = k;
	free(nmap);
	free(smap);
	free(tmap);
}

static char check_msg[200];

#define FAULT(...) do { snprintf(check_msg, sizeof check_msg, __VA_ARGS__); return check_msg; } while (0)

/* Tolerance on |ray| - 1: rays are renormalised after every change, so
 * only rounding (~1e-16) separates them from unit length. */
#define RAY_UNIT_TOL 1e-9

const char *mesh_check(const struct mesh *m)
{
	size_t ln = 0, ls = 0, lt = 0;
	for (size_t i = 0; i < m->nnode; i++) {
		const struct node *nd = &m->node[i];
		if (!nd->alive)
			continue;
		ln++;
		for (int d = 0; d < 3; d++)
			if (!isfinite(nd->p[d]) || !isfinite(nd->s[d]))
				FAULT("node %zu: non-finite coordinate", i);
		double r = sqrt(nd->s[0] * nd->s[0] + nd->s[1] * nd->s[1] + nd->s[2] * nd->s[2]);
		if (fabs(r - 1) > RAY_UNIT_TOL)
			FAULT("node %zu: ray of length %g", i, r);
		if (nd->nseg < 2)
			FAULT("node %zu: %d segments", i, nd->nseg);
		for (int j = 0; j < nd->nseg; j++) {
			int s = nd->seg[j];
			if (s < 0 || (size_t)s >= m->nseg || !m->seg[s].alive)
				FAULT("node %zu: dangling segment %d", i, s);
			if (m->seg[s].n[0] != (int)i && m->seg[s].n[1] != (int)i)
				FAULT("node %zu: segment %d does not link back", i, s);
			for (int k = 0; k < j; k++)
				if (nd->seg[k] == s)
					FAULT("node %zu: segment %d listed twice", i, s);
		}
	}
	for (size_t i = 0; i < m->nseg; i++) {
		const struct segment *sg = &m->seg[i];
		if (!sg->alive)
			continue;
		ls++;
		for (int j = 0; j < 2; j++) {
			int n = sg->n[j];
			if (n < 0 || (size_t)n >= m->nnode || !m->node[n].alive)
				FAULT("segment %zu: dangling node %d", i, n);
			int found = 0;
			for (int k = 0; k < m->node[n].nseg; k++)
				found |= m->node[n].seg[k] == (int)i;
			if (!found)
				FAULT("segment %zu: node %d does not link back", i, n);
		}
		if (sg->n[0] == sg->n[1])
			FAULT("segment %zu: both ends node %d", i, sg->n[0]);
		if (mesh_find_segment(m, sg->n[0], sg->n[1]) != (int)i)
			FAULT("segment %zu: nodes %d %d joined twice", i, sg->n[0], sg->n[1]);
		if (sg->t[0] < 0)
			FAULT("segment %zu: no triangle", i);
		if (sg->t[1] == sg->t[0])
			FAULT("segment %zu: triangle %d twice", i, sg->t[0]);
		for (int j = 0; j < 2; j++) {
			int t = sg->t[j];
			if (t < 0)
				continue;
			if ((size_t)t >= m->ntri || !m->tri[t].alive)
				FAULT("segment %zu: dangling triangle %d", i, t);
			const struct triangle *tr = &m->tri[t];
			if (tr->s[0] != (int)i && tr->s[1] != (int)i && tr->s[2] != (int)i)
				FAULT("segment %zu: triangle %d does not link back", i, t);
		}
		if (sg->t[1] >= 0) {
			/* orientation: the two triangles traverse the segment in
			 * opposite directions */
			int dir[2];
			for (int j = 0; j < 2; j++) {
				const struct triangle *tr = &m->tri[sg->t[j]];
				int k = 0;
				while (tr->s[k] != (int)i)
					k++;
				dir[j] = tr->n[k] == sg->n[0];
			}
			if (dir[0] == dir[1])
				FAULT("segment %zu: triangles %d and %d disagree in orientation",
				      i, sg->t[0], sg->t[1]);
		}
	}
	for (size_t i = 0; i < m->ntri; i++) {
		const struct triangle *tr = &m->tri[i];
		if (!tr->alive)
			continue;
		lt++;
		for (int j = 0; j < 3; j++) {
			int s = tr->s[j];
			if (s < 0 || (size_t)s >= m->nseg || !m->seg[s].alive)
				FAULT("triangle %zu: dangling segment %d", i, s);
			int a = tr->n[j], b = tr->n[(j + 1) % 3];
			const struct segment *sg = &m->seg[s];
			if (!((sg->n[0] == a && sg->n[1] == b) || (sg->n[0] == b && sg->n[1] == a)))
				FAULT("triangle %zu: segment %d does not join nodes %d %d", i, s, a, b);
			if (sg->t[0] != (int)i && sg->t[1] != (int)i)
				FAULT("triangle %zu: segment %d does not link back", i, s);
		}
		if (tr->n[0] == tr->n[1] || tr->n[1] == tr->n[2] || tr->n[0] == tr->n[2])
			FAULT("triangle %zu: repeated node", i);
	}
	if (ln != m->live_node || ls != m->live_seg || lt != m->live_tri)
		FAULT("live counts %zu %zu %zu, recorded %zu %zu %zu",
		      ln, ls, lt, m->live_node, m->live_seg, m->live_tri);
	return NULL;
}
