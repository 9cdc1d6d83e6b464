/*
 * deloop_zip - the two sheets of a delooped intersection are joined along
 * the intersection curve (thesis 8.4.3, Figure 8.11; src/etch/deloop_zip.c).
 *
 * 1. mesh_weld on a hand-made case: two squares of two triangles each,
 *    one above the other's right edge, sharing their border edge's
 *    positions: the weld of the two pairs of coincident nodes gives one
 *    segment with two triangles (counted), the checker passes, and a weld
 *    that would make the orientation inconsistent (the second square
 *    turned over) is refused by mesh_can_weld.
 * 2. Figure 8.13: seeds (0,0,0) and (0,1,0) (and the second moved by
 *    0.005 um in x and z, so that no crossing is degenerate), uniform
 *    1 um/s, steps of 0.1 s, delooped after 8 and 10 steps: no open border
 *    is left (every segment has two triangles: the spheres stay inside
 *    the box, so the joined union is a closed surface), the mesh checker
 *    is clean after every step (etch_run's check), no crossing is left
 *    (the independent counter of deloop_util.h), at least one seam
 *    segment was joined, and the area is within 1% of the exact area of
 *    the union's outer surface (the chords' shortfall, 0.3%, is all that
 *    separates them once nothing is cut away; tests/etch/deloop.c allows
 *    3% with the gaps).  Printed: the open border before joining (the
 *    cuts of the last deloop), after, and the seam segments joined.
 * 3. Figure 8.12: R = 2|x| + 0.2, 8 steps of 0.1 s, delooped: the one
 *    sheet folding through itself is joined to itself: no open border
 *    except on the faces of the box, no crossing left.  Figures printed
 *    as in 2.
 */
#include "deloop_util.h"

static int bad;

static void check(int ok, const char *what, double got, double want)
{
	printf("  %s: %g (%s %g)\n", what, got, ok ? "ok," : "FAIL, want", want);
	if (!ok)
		bad = 1;
}

/* Segments with one triangle not lying on a face of the box. */
static long open_segments(const struct mesh *m, double *len)
{
	long n = 0;
	*len = 0;
	for (size_t s = 0; s < m->nseg; s++) {
		const struct segment *sg = &m->seg[s];
		if (!sg->alive || sg->t[1] >= 0)
			continue;
		unsigned f = m->node[sg->n[0]].flags & m->node[sg->n[1]].flags;
		if (f & (ON_WALLS | ON_SUB))
			continue;
		n++;
		*len += mesh_seg_length(m, (int)s);
	}
	return n;
}

static void test_weld(void)
{
	printf("mesh_weld on two squares sharing an edge's place:\n");
	static const double ray[3] = {0, 0, -1};
	for (int flip = 0; flip < 2; flip++) {
		struct mesh *m = mesh_new();
		double p[8][3] = {
			{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},     /* square A */
			{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0},     /* square B */
		};
		int n[8];
		for (int i = 0; i < 8; i++)
			n[i] = mesh_add_node(m, p[i], ray, 0);
		mesh_add_triangle(m, n[0], n[1], n[2]);
		mesh_add_triangle(m, n[0], n[2], n[3]);
		if (!flip) {
			mesh_add_triangle(m, n[4], n[5], n[6]);
			mesh_add_triangle(m, n[4], n[6], n[7]);
		} else {
			mesh_add_triangle(m, n[4], n[6], n[5]);
			mesh_add_triangle(m, n[4], n[7], n[6]);
		}
		int ok1 = mesh_can_weld(m, n[1], n[4]);
		if (!flip) {
			check(ok1, "weld (1,0,0) allowed", ok1, 1);
			int j = mesh_weld(m, n[1], n[4]);
			check(j == 0, "segments joined by the first weld", j, 0);
			int ok2 = mesh_can_weld(m, n[2], n[7]);
			check(ok2, "weld (1,1,0) allowed", ok2, 1);
			j = mesh_weld(m, n[2], n[7]);
			check(j == 1, "segments joined by the second weld", j, 1);
			const char *e = mesh_check(m);
			check(e == NULL, "mesh checker clean", e != NULL, 0);
			if (e)
				printf("  %s\n", e);
			int s = mesh_find_segment(m, n[1], n[2]);
			check(s >= 0 && m->seg[s].t[1] >= 0, "shared segment has two triangles",
			      s >= 0 && m->seg[s].t[1] >= 0, 1);
		} else {
			int j = mesh_weld(m, n[1], n[4]);
			(void)j;
			int ok2 = mesh_can_weld(m, n[2], n[7]);
			check(!ok2, "weld against the orientation refused", ok2, 0);
		}
		mesh_free(m);
	}
}

static void report(const struct mesh *m, const struct etch_stats *st)
{
	struct deloop_pierce *pc;
	size_t np = deloop_pierces(m, &pc);
	free(pc);
	double len;
	long nopen = open_segments(m, &len);
	printf("  %zu triangles; %ld seam segments joined; open border after the last cuts "
	       "%.4g um, after joining %.4g um (%ld segments); %zu pierces\n", m->live_tri,
	       st->seam_joined, st->open_cut, st->open_left, nopen, np);
}

static void test_spheres(double shift)
{
	double et = 1.0;
	printf("two seeds (0,0,0) (%g,1,%g), 1 um/s, delooped at 0.8 s and 1.0 s:\n", shift,
	       shift);
	struct ratefile *r;
	struct etch_stats st;
	struct mesh *m = two_seed_run(et, shift, &r, &st);
	report(m, &st);
	double len;
	long nopen = open_segments(m, &len);
	double area, vol;
	mesh_area_volume(m, r->zmax, &area, &vol);
	double half = 0.5 * sqrt(1 + 2 * shift * shift);
	double exact = 2 * (4 * M_PI * et * et - 2 * M_PI * et * (et - half));
	long left = crossings_independent(m);
	check(nopen == 0, "open segments (closed union)", (double)nopen, 0);
	check(st.seam_joined > 0, "seam segments joined", (double)st.seam_joined, 1);
	check(left == 0, "crossings left (independent counter)", (double)left, 0);
	check(fabs(area / exact - 1) <= 0.01, "area / exact union surface", area / exact, 1);
	mesh_free(m);
	fmt_rate_free(r);
}

static void test_fold(double shift)
{
	printf("R = 2|x - %g| + 0.2, 8 steps of 0.1 s, delooped (Figure 8.12):\n", shift);
	double b[6] = {-0.5, 0.5, -0.25, 0.25, -1, 0};
	struct ratefile *r = fmt_rate_new(41, 11, 41, b);
	double *v = fmt_rate_values(r);
	for (int k = 0; k < r->nz; k++)
		for (int j = 0; j < r->ny; j++)
			for (int i = 0; i < r->nx; i++)
				v[fmt_rate_index(r, i, j, k)] = 2 * fabs(fmt_rate_x(r, i) - shift) + 0.2;
	struct rfield f;
	fmt_rate_field(&f, r, "triangular");
	struct etch_opts o = default_opts(0.8, 0.1, 0.05);
	o.deloop = 1;
	o.rate = r;
	struct etch_stats st = {0};
	struct mesh *m = etch_run(&f, &o, &st);
	report(m, &st);
	double len;
	long nopen = open_segments(m, &len);
	long left = crossings_independent(m);
	check(nopen == 0, "open segments off the box faces", (double)nopen, 0);
	check(st.seam_joined > 0, "seam segments joined", (double)st.seam_joined, 1);
	check(left == 0, "crossings left (independent counter)", (double)left, 0);
	mesh_free(m);
	fmt_rate_free(r);
}

int main(void)
{
	test_weld();
	test_spheres(0);
	test_spheres(0.005);
	test_fold(0);
	test_fold(0.005);
	return bad;
}
