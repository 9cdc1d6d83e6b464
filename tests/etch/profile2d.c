/*
 * profile2d - rates that do not depend on y: R = exp(-4 x^2)(1.05 -
 * cos(2 pi z)) (thesis [8.1], Figure 8.7) for 2 s and R = 2|x| ([7.8],
 * Figure 7.15) for 1 s, from the flat top, in a box 2 um wide in x.
 *
 * Checks, against the symmetry of the problem (no reference solution is
 * needed: the exact surface is a cylinder along y, symmetric in x):
 *   - y-independence: every node lies on the x-z profile traced by the
 *     nodes at other y, within Y_TOL of S_ideal.  The profile near a node
 *     is the circle through its nearest other-y node A with A's ray as
 *     normal and the curvature given by the rays of A and the next node B
 *     (the arc of thesis Figure 7.6b), so interpolation between nodes does
 *     not count as error;
 *   - symmetry: the same with x mirrored (every node near the profile of
 *     the mirrored nodes), within MIRROR_TOL;
 *   - boundary flattening: nodes flagged on a side wall are exactly on it,
 *     every border segment of the mesh lies on a wall, and the border of
 *     the mesh covers both x walls down to the front (the mesh has not
 *     contracted, Figure 7.14a);
 *   - the mesh checker is clean after every step.
 * Loops (swallowtails where rays cross, thesis 7.5.4) are where the
 * profile is not a single curve; nodes whose rays turn away from A's by
 * more than 60 degrees are not held to the tolerance; they must be under
 * 1% of the nodes.
 */
#include "etch.h"

#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define Y_TOL 0.01              /* of S_ideal: the accuracy asked */
#define LOOP_COS 0.5            /* rays 60 degrees apart: a loop, not a profile */
/* S_ideal: the box width / 80, near the thesis' finest 2D runs (100
 * segments, Table 7.2).  At / 40 the worst node is 3% of S off the
 * other-y profile: nodes made by different cuts carry different arc
 * interpolation errors, which scale as S^3. */
static double SEG = 0.025;
/* Mirror symmetry is looser: which node of a short segment is deleted
 * depends on segment counts and order, not on x (thesis 8.4.1.2: merging
 * is not commutative; Figure 8.7 shows the resulting asymmetry), and the
 * nodes kept differ near the sharp corner at the top of [8.1]'s profile,
 * where rays converge and interpolation errors grow. */
#define MIRROR_TOL 0.05

struct pt { double x, z, y, sx, sz; };

static double circle_dist(const struct pt *p, const struct pt *a, const struct pt *b)
{
	double dx = b->x - a->x, dz = b->z - a->z, dd = dx * dx + dz * dz;
	double k = dd > 0 ? ((b->sx - a->sx) * dx + (b->sz - a->sz) * dz) / dd : 0;
	double ux = p->x - a->x, uz = p->z - a->z;
	if (fabs(k) < 1e-9)
		return fabs(ux * a->sx + uz * a->sz);
	double cx = a->x - a->sx / k, cz = a->z - a->sz / k;
	return fabs(hypot(p->x - cx, p->z - cz) - 1 / fabs(k));
}

/* Distance from p to the profile of the points q (those with a different
 * y if other_y); *loop set when the nearest point's ray disagrees. */
static double profile_dist(const struct pt *p, const struct pt *q, size_t n, int other_y,
			   int *loop)
{
	size_t ia = n, ib = n;
	double da = 1e300, db = 1e300;
	for (size_t i = 0; i < n; i++) {
		if (other_y && fabs(q[i].y - p->y) < 1e-9)
			continue;
		double d = hypot(q[i].x - p->x, q[i].z - p->z);
		if (d < da) {
			da = d;
			ia = i;
		}
	}
	if (ia == n)
		return 1e300;
	*loop = p->sx * q[ia].sx + p->sz * q[ia].sz < LOOP_COS;
	if (da < 1e-12)
		return 0;
	for (size_t i = 0; i < n; i++) {
		if (other_y && fabs(q[i].y - p->y) < 1e-9)
			continue;
		double dab = hypot(q[i].x - q[ia].x, q[i].z - q[ia].z);
		if (dab < 1e-9)
			continue;
		/* prefer a B on the other side of p from A */
		double side = (q[i].x - p->x) * (q[ia].x - p->x) + (q[i].z - p->z) * (q[ia].z - p->z);
		double d = hypot(q[i].x - p->x, q[i].z - p->z) + (side > 0 ? 1e3 : 0);
		if (d < db) {
			db = d;
			ib = i;
		}
	}
	if (ib == n)
		return da;
	return circle_dist(p, &q[ia], &q[ib]);
}

static int run(const char *name, double (*rate)(double x, double z), double et, double zmin)
{
	int nx = 41, ny = 6, nz = 151;
	double b[6] = {-1, 1, 0, 0.25, zmin, 0};
	struct ratefile *r = fmt_rate_new(nx, ny, nz, b);
	double *v = fmt_rate_values(r);
	for (int k = 0; k < nz; k++)
		for (int j = 0; j < ny; j++)
			for (int i = 0; i < nx; i++)
				v[fmt_rate_index(r, i, j, k)] = rate(fmt_rate_x(r, i), fmt_rate_z(r, k));
	struct rfield f;
	fmt_rate_field(&f, r, name);
	struct etch_opts o = {0};
	o.et = et;
	o.seg = SEG;
	o.smax = ETCH_SMAX;
	o.smin = ETCH_SMIN;
	o.rl = ETCH_RL;
	o.clip_every = ETCH_CLIP;
	o.cut_axis = -1;
	o.check = 1;
	o.quiet = 1;
	struct etch_stats st = {0};
	struct mesh *m = etch_run(&f, &o, &st);
	int bad = 0;
	struct pt *p = xreallocarray(NULL, m->nnode + 1, sizeof *p);
	struct pt *mir = xreallocarray(NULL, m->nnode + 1, sizeof *mir);
	size_t n = 0;
	for (size_t i = 0; i < m->nnode; i++) {
		const struct node *nd = &m->node[i];
		p[n] = (struct pt){nd->p[0], nd->p[2], nd->p[1], nd->s[0], nd->s[2]};
		mir[n] = (struct pt){-nd->p[0], nd->p[2], nd->p[1], -nd->s[0], nd->s[2]};
		n++;
		unsigned fl = nd->flags;
		if ((fl & ON_X0 && nd->p[0] != f.lo[0]) || (fl & ON_X1 && nd->p[0] != f.hi[0]) ||
		    (fl & ON_Y0 && nd->p[1] != f.lo[1]) || (fl & ON_Y1 && nd->p[1] != f.hi[1])) {
			printf("FAIL %s: node %zu flagged on a wall but off it\n", name, i);
			bad = 1;
		}
	}
	double xlo_z = 1, xhi_z = 1;   /* lowest border node on each x wall */
	for (size_t s = 0; s < m->nseg; s++) {
		if (m->seg[s].t[1] >= 0)
			continue;
		unsigned common = m->node[m->seg[s].n[0]].flags & m->node[m->seg[s].n[1]].flags;
		if (!(common & (ON_SIDES | ON_TOP))) {
			printf("FAIL %s: border segment %zu not on a wall\n", name, s);
			bad = 1;
		}
		for (int j = 0; j < 2; j++) {
			const struct node *nd = &m->node[m->seg[s].n[j]];
			if (nd->flags & ON_X0 && nd->p[2] < xlo_z) xlo_z = nd->p[2];
			if (nd->flags & ON_X1 && nd->p[2] < xhi_z) xhi_z = nd->p[2];
		}
	}
	/* the deepest node at each x wall must be a border node on the wall */
	double dlo = 1, dhi = 1;
	for (size_t i = 0; i < n; i++) {
		if (p[i].x < f.lo[0] + 1e-9 && p[i].z < dlo) dlo = p[i].z;
		if (p[i].x > f.hi[0] - 1e-9 && p[i].z < dhi) dhi = p[i].z;
	}
	if (xlo_z > 0 || xhi_z > 0 || dlo != xlo_z || dhi != xhi_z) {
		printf("FAIL %s: the mesh border does not follow the x walls (%g %g %g %g)\n",
		       name, xlo_z, dlo, xhi_z, dhi);
		bad = 1;
	}
	double worst_y = 0, worst_m = 0;
	long loops = 0;
	for (size_t i = 0; i < n; i++) {
		int loop = 0, loop2 = 0;
		double dy = profile_dist(&p[i], p, n, 1, &loop);
		double dm = profile_dist(&p[i], mir, n, 0, &loop2);
		if (loop || loop2) {
			loops++;
			continue;
		}
		if (getenv("VERBOSE") && (dy > Y_TOL * SEG || dm > MIRROR_TOL * SEG))
			printf("  node x %g y %g z %g ray %g %g: %g %g S\n", p[i].x, p[i].y, p[i].z,
			       p[i].sx, p[i].sz, dy / SEG, dm / SEG);
		if (dy > worst_y) worst_y = dy;
		if (dm > worst_m) worst_m = dm;
	}
	printf("%s: %zu nodes, %zu triangles, %ld steps; worst distance to the other-y "
	       "profile %.3g S, to the mirrored profile %.3g S; %ld nodes in loops\n",
	       name, m->live_node, m->live_tri, st.steps, worst_y / SEG, worst_m / SEG, loops);
	if (loops > (long)n / 100) {
		printf("FAIL %s: %ld of %zu nodes excluded as loop nodes\n", name, loops, n);
		bad = 1;
	}
	if (!(worst_y <= Y_TOL * SEG) || !(worst_m <= MIRROR_TOL * SEG)) {
		printf("FAIL %s: profile depends on y or is not symmetric (tolerances %g S, %g S)\n",
		       name, Y_TOL, MIRROR_TOL);
		bad = 1;
	}
	free(p);
	free(mir);
	mesh_free(m);
	fmt_rate_free(r);
	return bad;
}

static double r87(double x, double z) { return exp(-4 * x * x) * (1.05 - cos(2 * M_PI * z)); }
static double rabs(double x, double z) { (void)z; return 2 * fabs(x); }

int main(void)
{
	if (getenv("SEG"))
		SEG = atof(getenv("SEG"));
	int bad = run("exp(-4x^2)(1.05-cos(2 pi z))", r87, 2, -1.5);
	bad |= run("2|x|", rabs, 1, -2.5);
	return bad;
}
