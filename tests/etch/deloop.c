/*
 * deloop - etch -deloop on the thesis' two analytic cases (thesis 8.4.3).
 *
 * 1. The spatial index: on a looped mesh (R = 2|x| + 0.2 after 8 steps,
 *    no deloop) every crossing the independent counter of deloop_util.h
 *    finds (Moller-Trumbore, x-sorted sweep, crossing points inside by
 *    EDGE_MARGIN) is among deloop_pierces' (grid, signed volumes), and
 *    every one of those is a crossing or a touch by the same test with the
 *    triangle and segment grown by EDGE_MARGIN.
 * 2. Figure 8.13: seeds (0,0,0) and (0,1,0), 1 um/s, steps of 0.1 s,
 *    delooped at 0.8 s and at 1.0 s (print times): every node within 1%
 *    of the radius from its nearer centre, none more than 1% inside
 *    either sphere, at least one loop removed per sphere, no crossing
 *    left (independent counter), mesh checker clean after every step, and
 *    the area within 3% of the exact area of the union's outer surface,
 *    2 (4 pi R^2 - 2 pi R (R - 1/2)) (nothing of the true front deleted;
 *    3%: the chords' shortfall, 1%, plus the gaps left at the cuts).
 * 3. Three seeds at the corners of a unit triangle, 0.8 s, delooped at the
 *    end: every pair of spheres intersects and all three overlap, so
 *    triangles of three sheets cross near the triple points (where the
 *    thesis' pass failed).  Same node checks as 2; the area within 3% of
 *    the union's outer surface, computed independently by sampling each
 *    sphere at 100000 Fibonacci points and keeping those outside the
 *    other two.
 * 4. Figure 8.12: R = 2|x| + 0.2, 8 steps of 0.1 s: a loop is removed,
 *    no crossing is left, and every node lies within 2 segment lengths of
 *    the fast-marching front on a grid refined 4 times per axis (the
 *    tolerance asked of delooping); the median distance is printed.
 * 5. The hashed grid gives the pierces of a search without grid, bit for
 *    bit, with 1, 2 and 3 threads (test_grid_reference), also on a mesh
 *    of triangles of very unlike sizes whose nodes lie on cell borders
 *    (test_grid_mixed: each pair is tested in the lowest cell both boxes
 *    touch, which a triangle over many cells or a box ending on a border
 *    would get wrong first).
 */
#include "deloop_util.h"
#include "par.h"

/* The asymmetric variants' offset, um: a fifth of a rate cell, so no
 * crossing is degenerate. */
#define SHIFT 0.005

static int bad;

static void check(int ok, const char *what, double got, double want)
{
	printf("  %s: %g (%s %g)\n", what, got, ok ? "ok," : "FAIL, want", want);
	if (!ok)
		bad = 1;
}

/* R = 2|x - shift| + 0.2 (thesis [8.2]); shift 0 is the thesis' field,
 * whose mesh is its own mirror image in x = 0, so that its two sheets
 * cross exactly on each other's segments, where the independent counter
 * (strict, EDGE_MARGIN inside) sees nothing; a small shift makes the
 * crossings generic. */
static struct ratefile *triangular(double shift)
{
	double b[6] = {-0.5, 0.5, -0.25, 0.25, -1, 0};
	struct ratefile *r = fmt_rate_new(41, 11, 41, b);
	double *v = fmt_rate_values(r);
	for (int k = 0; k < r->nz; k++)
		for (int j = 0; j < r->ny; j++)
			for (int i = 0; i < r->nx; i++)
				v[fmt_rate_index(r, i, j, k)] = 2 * fabs(fmt_rate_x(r, i) - shift) + 0.2;
	return r;
}

static void test_index(void)
{
	printf("spatial index against the independent counter (R = 2|x - %g| + 0.2, "
	       "8 steps):\n", SHIFT);
	struct ratefile *r = triangular(SHIFT);
	struct rfield f;
	fmt_rate_field(&f, r, "triangular");
	struct etch_opts o = default_opts(0.8, 0.1, 0.05);
	struct etch_stats st = {0};
	struct mesh *m = etch_run(&f, &o, &st);
	struct deloop_pierce *pc;
	size_t np = deloop_pierces(m, &pc);
	long ind = crossings_independent(m);
	/* every independent crossing must be in the grid's list */
	long missed = 0;
	for (size_t s = 0; s < m->nseg; s++) {
		const struct segment *sg = &m->seg[s];
		if (!sg->alive)
			continue;
		for (size_t t = 0; t < m->ntri; t++) {
			const struct triangle *tr = &m->tri[t];
			if (!tr->alive)
				continue;
			int touch = 0;
			for (int j = 0; j < 3; j++)
				touch |= tr->n[j] == sg->n[0] || tr->n[j] == sg->n[1];
			if (touch || !mt_cross(m->node[sg->n[0]].p, m->node[sg->n[1]].p,
					       m->node[tr->n[0]].p, m->node[tr->n[1]].p,
					       m->node[tr->n[2]].p, EDGE_MARGIN))
				continue;
			int found = 0;
			for (size_t k = 0; k < np && !found; k++)
				found = pc[k].s == (int)s && pc[k].t == (int)t;
			missed += !found;
		}
	}
	printf("  %zu triangles: grid %zu pierces, independent %ld\n", m->live_tri, np, ind);
	check(ind > 0, "crossings before deloop (a loop must be there)", (double)ind, 1);
	check(missed == 0, "independent crossings missed by the grid", (double)missed, 0);
	/* and every pierce of the grid's a real crossing or touch: inside
	 * the triangle and the segment grown by EDGE_MARGIN */
	long unconfirmed = 0;
	for (size_t k = 0; k < np; k++) {
		const struct segment *sg = &m->seg[pc[k].s];
		const struct triangle *tr = &m->tri[pc[k].t];
		unconfirmed += !mt_cross(m->node[sg->n[0]].p, m->node[sg->n[1]].p,
					 m->node[tr->n[0]].p, m->node[tr->n[1]].p,
					 m->node[tr->n[2]].p, -EDGE_MARGIN);
	}
	check(unconfirmed == 0, "grid pierces not confirmed", (double)unconfirmed, 0);
	free(pc);
	mesh_free(m);
	fmt_rate_free(r);
}

/* Figure 8.13 at time et, delooped at 0.8 s and (if et > 0.8) at et; the
 * second seed at (0, 1, 0) or, to make the crossings generic (see
 * triangular), moved by SHIFT in x and z. */
static void test_spheres(double et, double shift)
{
	printf("two seeds (0,0,0) (%g,1,%g), 1 um/s, delooped at 0.8 s%s:\n", shift, shift,
	       et > 0.8 ? " and 1.0 s" : "");
	struct ratefile *r;
	struct etch_stats st;
	struct mesh *m = two_seed_run(et, shift, &r, &st);
	const double c[2][3] = {{0, 0, 0}, {shift, 1, shift}};
	double worst = 0, inside = 0;
	for (size_t i = 0; i < m->nnode; i++) {
		if (!m->node[i].alive)
			continue;
		double d[2];
		for (int k = 0; k < 2; k++) {
			double x[3];
			sub3(m->node[i].p, c[k], x);
			d[k] = sqrt(dot3(x, x));
			inside = fmax(inside, (et - d[k]) / et);
		}
		worst = fmax(worst, fabs(fmin(d[0], d[1]) - et) / et);
	}
	double area, vol;
	mesh_area_volume(m, r->zmax, &area, &vol);
	double half = 0.5 * sqrt(1 + 2 * shift * shift);   /* centre to the plane */
	double exact = 2 * (4 * M_PI * et * et - 2 * M_PI * et * (et - half));
	long left = crossings_independent(m);
	printf("  %zu triangles; deloop %ld passes, %ld loops, %.3g s\n", m->live_tri,
	       st.deloops, st.loops, st.deloop_s);
	check(worst <= 0.01, "largest | |p - nearer centre| - R | / R", worst, 0.01);
	check(inside <= 0.01, "deepest node inside a sphere / R", inside, 0.01);
	check(st.loops >= 2, "loops removed", (double)st.loops, 2);
	check(left == 0, "crossings left (independent counter)", (double)left, 0);
	check(fabs(area / exact - 1) <= 0.03, "area / exact union surface", area / exact, 1);
	mesh_free(m);
	fmt_rate_free(r);
}

static void test_three(void)
{
	printf("three seeds, 1 um/s, 0.8 s, delooped:\n");
	double et = 0.8;
	double b[6] = {-1.5, 2.5, -1.5, 2.5, -1.5, 1.5};
	struct ratefile *r = fmt_rate_new(41, 41, 31, b);
	double *v = fmt_rate_values(r);
	for (size_t i = 0; i < (size_t)41 * 41 * 31; i++)
		v[i] = 1;
	struct rfield f;
	fmt_rate_field(&f, r, "uniform");
	struct etch_opts o = default_opts(et, 0.1, 0.1);
	o.deloop = 1;
	o.rate = r;
	o.seed = 3;
	double c[3][3] = {{0, 0, 0}, {1, 0, 0}, {0.5 + SHIFT, 0.5 * sqrt(3), SHIFT}};
	memcpy(o.seedp, c, sizeof c);
	struct etch_stats st = {0};
	struct mesh *m = etch_run(&f, &o, &st);
	double worst = 0, inside = 0;
	for (size_t i = 0; i < m->nnode; i++) {
		if (!m->node[i].alive)
			continue;
		double near = INFINITY;
		for (int k = 0; k < 3; k++) {
			double x[3];
			sub3(m->node[i].p, c[k], x);
			double d = sqrt(dot3(x, x));
			near = fmin(near, d);
			inside = fmax(inside, (et - d) / et);
		}
		worst = fmax(worst, fabs(near - et) / et);
	}
	/* the exact outer surface, by sampling (Fibonacci sphere) */
	enum { NS = 100000 };
	double exact = 0;
	for (int k = 0; k < 3; k++) {
		long out = 0;
		for (int i = 0; i < NS; i++) {
			double zz = 1 - (2 * i + 1) / (double)NS, rr = sqrt(1 - zz * zz);
			double ph = i * M_PI * (3 - sqrt(5));
			double p[3] = {c[k][0] + et * rr * cos(ph), c[k][1] + et * rr * sin(ph),
				       c[k][2] + et * zz};
			int ok = 1;
			for (int j = 0; j < 3; j++) {
				double x[3];
				sub3(p, c[j], x);
				ok &= j == k || dot3(x, x) > et * et;
			}
			out += ok;
		}
		exact += 4 * M_PI * et * et * (double)out / NS;
	}
	double area, vol;
	mesh_area_volume(m, f.hi[2], &area, &vol);
	long left = crossings_independent(m);
	printf("  %zu triangles; %ld loops removed\n", m->live_tri, st.loops);
	check(worst <= 0.01, "largest | |p - nearest centre| - R | / R", worst, 0.01);
	check(inside <= 0.01, "deepest node inside a sphere / R", inside, 0.01);
	check(st.loops >= 3, "loops removed", (double)st.loops, 3);
	check(left == 0, "crossings left (independent counter)", (double)left, 0);
	check(fabs(area / exact - 1) <= 0.03, "area / sampled union surface", area / exact, 1);
	mesh_free(m);
	fmt_rate_free(r);
}

static void test_triangular(double shift)
{
	printf("R = 2|x - %g| + 0.2, 8 steps of 0.1 s, delooped (Figure 8.12):\n", shift);
	struct ratefile *r = triangular(shift);
	struct rfield f;
	fmt_rate_field(&f, r, "triangular");
	double seg = 0.05;
	struct etch_opts o = default_opts(0.8, 0.1, seg);
	o.deloop = 1;
	o.rate = r;
	struct etch_stats st = {0};
	struct mesh *m = etch_run(&f, &o, &st);
	long left = crossings_independent(m);
	int refine[3] = {4, 4, 4};
	struct fmm *fm = fmm_solve(r, refine);
	double *p = xreallocarray(NULL, m->nnode * 3 + 1, sizeof *p);
	size_t n = 0;
	double far = 0;
	for (size_t i = 0; i < m->nnode; i++) {
		memcpy(p + 3 * n++, m->node[i].p, sizeof m->node[i].p);
		far = fmax(far, fmm_distance(fm, m->node[i].p, o.et));
	}
	double med, p95;
	fmm_distance_stats(fm, p, n, o.et, &med, &p95);
	printf("  %zu triangles; %ld loops removed; distance to the fast-marching front: "
	       "median %.3g um, 95%% %.3g um, largest %.3g um\n", m->live_tri, st.loops,
	       med, p95, far);
	check(st.loops >= 1, "loops removed", (double)st.loops, 1);
	check(left == 0, "crossings left (independent counter)", (double)left, 0);
	check(far <= 2 * seg, "largest node distance to the fast-marching front, um", far,
	      2 * seg);
	free(p);
	fmm_free(fm);
	mesh_free(m);
	fmt_rate_free(r);
}

/* 5. The hashed grid against the reference search without a
 * grid (deloop_pierces_all: every pair whose x ranges meet, the same
 * crossing test): the same pierces, bit for bit, with 1, 2 and 3
 * threads, on the looped meshes of 1 (R = 2|x| + 0.2) and of two seeds
 * grown 1 s without deloop (Figure 8.13: 2 spheres crossing).  The pass
 * depends on the mesh only through this list, so equal lists give the
 * triangles of the unhashed search before it (whose list was also exact). */
static long same_pierces(const struct mesh *m, const char *what)
{
	struct deloop_pierce *ref, *pc;
	size_t nref = deloop_pierces_all(m, &ref);
	long bad_lists = 0;
	for (int th = 1; th <= 3; th++) {
		par_set_threads(th);
		size_t np = deloop_pierces(m, &pc);
		int same = np == nref && (np == 0 || memcmp(pc, ref, np * sizeof *pc) == 0);
		printf("  %s, %d thread%s: %zu pierces, reference %zu%s\n", what, th, th > 1 ? "s" : "",
		       np, nref, same ? "" : " DIFFERENT");
		bad_lists += !same;
		free(pc);
	}
	par_set_threads(0);
	free(ref);
	check(nref > 0, "pierces in the reference (the mesh must be looped)", (double)nref, 1);
	return bad_lists;
}

static void test_grid_reference(void)
{
	printf("hashed grid against the reference search:\n");
	struct ratefile *r = triangular(SHIFT);
	struct rfield f;
	fmt_rate_field(&f, r, "triangular");
	struct etch_opts o = default_opts(0.8, 0.1, 0.05);
	struct etch_stats st = {0};
	struct mesh *m = etch_run(&f, &o, &st);
	long bad_lists = same_pierces(m, "R = 2|x| + 0.2");
	mesh_free(m);
	fmt_rate_free(r);
	double b[6] = {-1.5, 1.5, -1.5, 2.5, -1.5, 1.5};
	r = fmt_rate_new(31, 41, 31, b);
	double *v = fmt_rate_values(r);
	for (size_t i = 0; i < (size_t)31 * 41 * 31; i++)
		v[i] = 1;
	fmt_rate_field(&f, r, "uniform");
	o = default_opts(1.0, 0.1, 0.05);
	o.rate = r;
	o.seed = 2;
	double c[2][3] = {{0, 0, 0}, {SHIFT, 1, SHIFT}};
	memcpy(o.seedp, c, sizeof c);
	m = etch_run(&f, &o, &st);
	bad_lists += same_pierces(m, "two seeds, 1 s");
	mesh_free(m);
	fmt_rate_free(r);
	check(bad_lists == 0, "pierce lists unlike the reference's", (double)bad_lists, 0);
}

/* Sheet A: the square [0, 2]^2 at z = 0 in 40 x 40 squares of 0.05 um,
 * two triangles each; sheet B: the plane x = 0.5 + 0.1 z, y in [0.2,
 * 1.8], z in [-0.5, 0.5], in squares of 0.05 um (its row at z = 0 lies in
 * A); two triangles C over the whole of both, each in some thousand
 * cells, crossing A and B and each other.  Node coordinates are multiples
 * of 0.05, so many boxes end on cell borders. */
static int grid_node(struct mesh *m, double x, double y, double z)
{
	double p[3] = {x, y, z}, up[3] = {0, 0, 1};
	return mesh_add_node(m, p, up, 0);
}

static void test_grid_mixed(void)
{
	printf("hashed grid against the reference search, mixed sizes:\n");
	struct mesh *m = mesh_new();
	enum { NA = 40, NBY = 32, NBZ = 20 };
	int a[NA + 1][NA + 1], b[NBY + 1][NBZ + 1];
	for (int i = 0; i <= NA; i++)
		for (int j = 0; j <= NA; j++)
			a[i][j] = grid_node(m, 0.05 * i, 0.05 * j, 0);
	for (int i = 0; i < NA; i++)
		for (int j = 0; j < NA; j++) {
			mesh_add_triangle(m, a[i][j], a[i + 1][j], a[i + 1][j + 1]);
			mesh_add_triangle(m, a[i][j], a[i + 1][j + 1], a[i][j + 1]);
		}
	for (int i = 0; i <= NBY; i++)
		for (int k = 0; k <= NBZ; k++) {
			double z = -0.5 + 0.05 * k;
			b[i][k] = grid_node(m, 0.5 + 0.1 * z, 0.2 + 0.05 * i, z);
		}
	for (int i = 0; i < NBY; i++)
		for (int k = 0; k < NBZ; k++) {
			mesh_add_triangle(m, b[i][k], b[i + 1][k], b[i + 1][k + 1]);
			mesh_add_triangle(m, b[i][k], b[i + 1][k + 1], b[i][k + 1]);
		}
	mesh_add_triangle(m, grid_node(m, -0.1, -0.1, 0.3), grid_node(m, 2.1, -0.1, -0.3),
			  grid_node(m, 1, 2.1, 0.1));
	mesh_add_triangle(m, grid_node(m, -0.1, 1, -0.4), grid_node(m, 2.1, 0.3, 0.4),
			  grid_node(m, 2.1, 1.9, 0.2));
	long bad_lists = same_pierces(m, "sheets and two large triangles");
	check(bad_lists == 0, "pierce lists unlike the reference's (mixed sizes)", (double)bad_lists,
	      0);
	mesh_free(m);
}

int main(void)
{
	test_index();
	test_grid_reference();
	test_grid_mixed();
	test_spheres(0.8, 0);
	test_spheres(1.0, 0);
	test_spheres(1.0, SHIFT);
	test_three();
	test_triangular(0);
	test_triangular(SHIFT);
	return bad;
}
