/*
 * deloop_contact - etch -deloop on a real resist contact with loops
 * (thesis Figures 8.16 and 8.19): examples/contact without bake (Olin Hunt
 * 6512, standing waves) at dose 240 mJ/cm2, developed 30 s; the rate file
 * is built here by splat and bleach (a failure of either fails the test).
 *
 * Checks, after the ray-string run delooped at the end:
 *   - no crossing is left (the independent counter of deloop_util.h);
 *   - the mesh still covers the whole developed surface: its area and the
 *     developed volume it encloses with the resist top (divergence
 *     theorem, deloop_util.h) agree with the fast-marching surface T = 30 s
 *     (grid refined in z by fmm_auto_refine) within 5% (the tolerance
 *     asked of delooping; the thesis' pass instead deleted most of the mesh,
 *     Figure 8.19);
 *   - the mesh checker is clean after every step.
 * The run without deloop is shown for comparison (its loops add area).
 */
#include "deloop_util.h"

#define REL_TOL 0.05
/* S_ideal, um: the default (box / 30 = 0.17 um) is coarser than the
 * standing waves (0.13 um period) and loses half the developed volume
 * with or without loops; at 0.06 um the ray-string volume is within a
 * few per cent of the fast-marching one. */
#define SEG 0.06

int main(void)
{
	const char *top = getenv("SRCDIR");
	if (!top)
		top = ".";
	char cmd[4096];
	snprintf(cmd, sizeof cmd,
		 "sed 's/^dose .*/dose 240/' '%s/examples/contact/resist-nobake.in' > resist.in && "
		 "splat -q '%s/examples/contact/mask.in' && "
		 "bleach -q -o rate.bin image.cont resist.in", top, top);
	if (system(cmd) != 0) {
		printf("FAIL: splat or bleach failed or missing\n");
		return 1;
	}
	struct ratefile *r = fmt_rate_read("rate.bin");
	struct rfield f;
	fmt_rate_field(&f, r, "rate.bin");
	double et = 30;
	int refine[3] = {1, 1, fmm_auto_refine(r)};
	struct fmm *fm = fmm_solve(r, refine);
	double fa, fv;
	fmm_area_volume(fm, et, &fa, &fv);
	printf("fast marching (refined x%d in z): area %.4g um2, developed volume %.4g um3\n",
	       refine[2], fa, fv);
	int bad = 0;
	for (int deloop = 0; deloop < 2; deloop++) {
		struct etch_opts o = default_opts(et, 0, SEG);
		o.deloop = deloop;
		o.rate = r;
		struct etch_stats st = {0};
		struct mesh *m = etch_run(&f, &o, &st);
		double a, v;
		mesh_area_volume(m, f.hi[2], &a, &v);
		long left = crossings_independent(m);
		printf("%s: %zu triangles, %ld crossings; area %.4g um2 (%.4f of fast marching), "
		       "volume %.4g um3 (%.4f)", deloop ? "delooped" : "with loops", m->live_tri,
		       left, a, a / fa, v, v / fv);
		if (deloop)
			printf("; %ld loops, %ld triangles removed in %.3g s", st.loops,
			       st.looped_tris, st.deloop_s);
		printf("\n");
		if (deloop) {
			if (left != 0) {
				printf("FAIL: %ld crossings left after deloop\n", left);
				bad = 1;
			}
			if (!(fabs(a / fa - 1) <= REL_TOL) || !(fabs(v / fv - 1) <= REL_TOL)) {
				printf("FAIL: area or volume off by more than %g\n", REL_TOL);
				bad = 1;
			}
		}
		mesh_free(m);
	}
	fmm_free(fm);
	fmt_rate_free(r);
	return bad;
}
