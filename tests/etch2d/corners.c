/*
 * corners - development from a grooved surface (etch2d -start; thesis
 * 6.2.3, Figures 6.5-6.6): a V groove 0.3 um deep with a 90 degree
 * bottom (a diverging corner: the front rounds it) between two 135
 * degree rims (converging corners: the front keeps them sharp), in a
 * uniform R = 1 um/s.  The exact front at time t is the offset curve at
 * distance t: flat at z = -t beyond the rims' corners (which move along
 * their bisectors by t / sin 67.5 = 1.082 t), the walls' parallels, and
 * the arc of radius t about the groove's bottom.
 *
 * The error of a profile is its two-way distance to the exact front at
 * t = 0.5 s: the largest |distance to the groove - t| of its points, and
 * the largest distance of the exact front's points to it.  Checks:
 *   - fast marching (200 x 100 nodes, 0.01 um) within one node spacing;
 *   - the ray-string at the thesis' S_ideal = 0.2 um within 0.02 um: the
 *     fan of rays at the bottom draws the arc, delooping keeps the rims
 *     sharp and in place (their corners within 0.005 um);
 *   - the plain string at S_ideal = 0.2 um shows the thesis' corner
 *     errors: the rounding at the bottom (Figure 6.5a: a tapered groove,
 *     more than 0.025 um off) and the scissoring at the rims (Figure 6.6a:
 *     the corner lags more than 0.005 um behind the exact one), and both
 *     shrink with the segment (S_ideal 0.05: within 0.02 um), as 6.2.3.1
 *     says;
 *   - the rays alone (no delooping) keep the swallowtail the crossing rays
 *     make at the rims (a point more than 0.03 um behind the front), 6.3.3;
 *   - Dill's cells and Huygens' start from the cells above the groove and
 *     stay within 2.5 and 3.5 cells.
 */
#include "e2test.h"

#define T_END 0.5
#define DEPTH 0.3
#define H_FMM 0.01      /* one node spacing */
#define H_RS 0.02       /* ray-string, S_ideal 0.2: a tenth of it */
#define RIM_TOL 0.005   /* the rims' corners, um along the bisector */
#define H_STR_MIN 0.025 /* the string's rounding at S_ideal 0.2 exceeds */
#define H_STR_FINE 0.02 /* ... and at S_ideal 0.05 stays within */
#define RAY_LOOP 0.03   /* the rays' swallowtail reaches beyond */
#define H_CELL 0.025    /* 2.5 cells of 0.01 um */
#define H_HUY 0.035     /* 3.5 cells */

static const double groove[] = {-1, 0, -DEPTH, 0, 0, -DEPTH, DEPTH, 0, 1, 0};

static double one(double x, double z) { (void)x; (void)z; return 1; }

static int fails;

static double seg_dist(const double *a, const double *b, const double p[2])
{
	double dx = b[0] - a[0], dz = b[1] - a[1], l2 = dx * dx + dz * dz;
	double u = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dz) / l2 : 0;
	u = fmin(fmax(u, 0), 1);
	return hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dz);
}

static double groove_dist(const double p[2])
{
	double best = INFINITY;
	for (int k = 0; k < 4; k++)
		best = fmin(best, seg_dist(groove + 2 * k, groove + 2 * k + 2, p));
	return best;
}

/* n points of the exact front at t (the left half, mirrored). */
static int exact_front(double t, double (*q)[2], int per)
{
	double xc = DEPTH + t * tan(M_PI / 8), r2 = t / M_SQRT2;
	double e[2] = {-r2, -DEPTH - r2};
	int n = 0;
	for (int i = 0; i <= per; i++) {
		double u = (double)i / per;
		q[n][0] = -1 + u * (1 - xc), q[n][1] = -t, n++;
		q[n][0] = -xc + u * (e[0] + xc), q[n][1] = -t + u * (e[1] + t), n++;
		double th = -0.75 * M_PI + 0.5 * M_PI * u;
		q[n][0] = t * cos(th), q[n][1] = -DEPTH + t * sin(th), n++;
	}
	for (int i = 0; i < n; i++)
		q[n + i][0] = -q[i][0], q[n + i][1] = q[i][1];
	return 2 * n;
}

/* Distance along the right rim's bisector (from (DEPTH, 0) into the
 * resist) to the nearest crossing of the profile; the exact one is
 * t / sin 67.5. */
static double rim_corner(const struct plot_set *set)
{
	double b[2] = {1 - M_SQRT1_2, -M_SQRT1_2}, r = hypot(b[0], b[1]), best = INFINITY;
	b[0] /= r, b[1] /= r;
	for (int c = 0; c < set->ncurves; c++) {
		const double *p = set->curves[c].p;
		for (int k = 0; k + 1 < set->curves[c].npts; k++) {
			double ax = p[2 * k] - DEPTH, az = p[2 * k + 1];
			double ex = p[2 * k + 2] - p[2 * k], ez = p[2 * k + 3] - p[2 * k + 1];
			double den = -b[0] * ez + b[1] * ex;
			if (den == 0)
				continue;
			double s = (-ax * ez + az * ex) / den, u = (b[0] * az - b[1] * ax) / den;
			if (u >= 0 && u <= 1 && s > 0 && s < best)
				best = s;
		}
	}
	return best;
}

struct result { double out, in, rim; };

static struct result run(int method, double seg, double dt)
{
	double b[4] = {-1, 1, -1, 0};
	struct ratefile *r = t_rate(3, 3, b, one);
	struct e2opts o;
	t_opts(&o, method, T_END, 0);
	o.start = groove;
	o.nstart = 5;
	o.seg = seg;
	o.dt = dt;
	struct rfield f;
	struct e2 e;
	t_run(&e, r, &f, &o);
	const struct plot_set *set = &e.pf->sets[e.pf->nsets - 1];
	struct result res = {0, 0, 0};
	for (int c = 0; c < set->ncurves; c++)
		for (int k = 0; k < set->curves[c].npts; k++)
			res.out = fmax(res.out, fabs(groove_dist(set->curves[c].p + 2 * k) - T_END));
	static double q[12 * 64][2];
	int nq = exact_front(T_END, q, 60);
	for (int i = 0; i < nq; i++)
		res.in = fmax(res.in, t_dist(set, q[i]));
	res.rim = rim_corner(set) - T_END / sin(3 * M_PI / 8);
	e2_free(&e);
	fmt_rate_free(r);
	return res;
}

static void expect(const char *what, int ok, struct result r)
{
	printf("%-38s profile off by %.4f, front missed by %.4f, rim corner %+.4f um%s\n",
	       what, r.out, r.in, r.rim, ok ? "" : "  FAIL");
	if (!ok)
		fails++;
}

int main(void)
{
	util_setprog("corners");
	struct result r;
	r = run(M_FMM, 0, 0);
	expect("fmm 200 x 100", r.out < H_FMM && r.in < H_FMM, r);
	r = run(M_RAYSTRING, 0.2, 0.1);
	expect("raystring S_ideal 0.2", r.out < H_RS && r.in < H_RS && fabs(r.rim) < RIM_TOL, r);
	r = run(M_STRING, 0.2, 0.1);
	expect("string S_ideal 0.2 (rounds, scissors)", fmax(r.out, r.in) > H_STR_MIN && r.rim < -RIM_TOL, r);
	r = run(M_STRING, 0.05, 0.1);
	expect("string S_ideal 0.05", r.out < H_STR_FINE && r.in < H_STR_FINE, r);
	r = run(M_RAY, 0.2, 0.1);
	expect("ray S_ideal 0.2 (swallowtail kept)", r.out > RAY_LOOP && r.in < H_RS, r);
	r = run(M_CELL, 0, 0);
	expect("cell 200 x 100", r.out < H_CELL && r.in < H_CELL, r);
	r = run(M_HUYGENS, 0, 0);
	expect("huygens 200 x 100", r.out < H_HUY && r.in < H_HUY, r);
	return fails ? 1 : 0;
}
