/*
 * roughsurf - test tool: developed surfaces (plot3d, one set of
 * triangles) whose sections at half the resist height are known exactly,
 * for measure's roughness and LCDU metrology (tests/measure/).  Not a
 * test itself.
 *
 *   roughsurf line|space [-rows M] [-jitter SEED] [-swap]
 *             [-left SPEC] [-right SPEC] -truth FILE -o FILE
 *   roughsurf holes [-nx NX] [-ny NY] [-r R] [-dr DR] [-seed S]
 *             [-sides N] -truth FILE -o FILE
 *
 * line, space: box x, y from -1 to 1 um, z from -0.5 to 0.  A line
 *   (resist) or space along y whose left and right edges at z = -0.25
 *   follow SPEC on M + 1 rows y_k = -1 + 2k/M (default M 2048), the edge
 *   straight between rows.  The walls slope 0.05 um in x over the height
 *   (wider at the bottom for a line, narrower for a space); every face is
 *   planar, so the section at z = -0.25 passes through the edge values
 *   exactly.  -jitter moves the inner rows by up to 0.3 of their spacing
 *   at random (rows no longer even); -swap exchanges x and y (the feature
 *   along x).  SPEC:
 *     sin:X0:A1:N1:P1[:A2:N2:P2...]  X0 + sum A sin(2 pi N (y + 1)/2 + P)
 *     ar:X0:SIGMA:XI:SEED            X0 + a Gaussian AR(1) sequence of
 *       standard deviation SIGMA and lag-1 correlation exp(-1/XI) on the
 *       rows 0 .. M-1, row M repeating row 0 (the box repeats).
 *   The truth file has one line "y left right" per row (y along the
 *   feature).
 * holes: box x from 0 to NX/2, y from 0 to NY/2 um, z from -0.5 to 0;
 *   holes on a 0.5 um grid with centres on the box edges too, so that
 *   the outer ones are cut in half (quarters in the corners).  Hole (i,
 *   j) is a regular N-gon (default 64) in plan, circumradius
 *   R + DR u (u uniform in -1..1, seeded; default R 0.15, DR 0.02) at
 *   z = -0.25, sloping 0.03 um outwards to the top.  The truth file has
 *   one line "x y r cd" per hole inside the box, cd = sqrt(4 A / pi) of
 *   the polygon's area A.
 */
#include "args.h"
#include "fmt_plot.h"
#include "util.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double ZLO = -0.5, ZHI = 0;
enum { MAX_TERMS = 8 };

static uint64_t rng_state;
static double uniform(void)     /* splitmix64, in (0, 1) */
{
	uint64_t z = (rng_state += 0x9e3779b97f4a7c15ULL);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	z ^= z >> 31;
	return ((double)(z >> 11) + 0.5) / 9007199254740992.0;
}

static double gauss(void)
{
	double u = uniform(), v = uniform();
	return sqrt(-2 * log(u)) * cos(2 * M_PI * v);
}

struct tris {
	double *v;
	size_t n, cap;
	int swap;
};

static void tri(struct tris *t, const double *a, const double *b, const double *c)
{
	xgrow(&t->v, &t->cap, 9 * (t->n + 1), sizeof *t->v);
	double *p = t->v + 9 * t->n++;
	const double *q[3] = {a, b, c};
	for (int k = 0; k < 3; k++) {
		p[3 * k] = q[k][t->swap];
		p[3 * k + 1] = q[k][1 - t->swap];
		p[3 * k + 2] = q[k][2];
	}
}

static void quad(struct tris *t, const double *a, const double *b, const double *c,
		 const double *d)
{
	tri(t, a, b, c);
	tri(t, a, c, d);
}

static void write_plot(const char *path, const struct tris *t, const double *box)
{
	struct plot_writer *w = fmt_plot_open(path, 3);
	fmt_plot_begin_set(w, box, (long)t->n);
	for (size_t i = 0; i < t->n; i++) {
		double p[12];
		memcpy(p, t->v + 9 * i, 9 * sizeof *p);
		memcpy(p + 9, p, 3 * sizeof *p);
		fmt_plot_curve(w, 4, p);
	}
	fmt_plot_close(w);
}

/* The edge values of SPEC on rows y[0..m]. */
static void edge_of(const char *spec, const double *y, long m, double *e)
{
	char *s = xstrdup(spec), *save = NULL;
	char *kind = strtok_r(s, ":", &save);
	double a[3 * MAX_TERMS + 1];
	int na = 0;
	for (char *t; na < 3 * MAX_TERMS + 1 && (t = strtok_r(NULL, ":", &save));)
		a[na++] = atof(t);
	if (!kind || na < 1)
		die("bad edge spec \"%s\"", spec);
	if (strcmp(kind, "sin") == 0 && na % 3 == 1) {
		for (long k = 0; k <= m; k++) {
			e[k] = a[0];
			for (int i = 1; i + 2 < na; i += 3)
				e[k] += a[i] * sin(2 * M_PI * a[i + 1] * (y[k] + 1) / 2 + a[i + 2]);
		}
	} else if (strcmp(kind, "ar") == 0 && na == 4) {
		double rho = exp(-1 / a[2]), d;
		rng_state = (uint64_t)a[3];
		d = a[1] * gauss();
		for (long k = 0; k < m; k++) {
			e[k] = a[0] + d;
			d = rho * d + sqrt(1 - rho * rho) * a[1] * gauss();
		}
		e[m] = e[0];
	} else {
		die("bad edge spec \"%s\"", spec);
	}
	free(s);
}

/* x positions along the profile of row k: box side, the four wall feet
 * and tops, box side (see the note at the head). */
static void line_surface(struct tris *t, int space, const double *y, const double *l,
			 const double *r, long m)
{
	const double w = 0.05;
	double z6[6] = {ZLO, ZLO, ZHI, ZHI, ZLO, ZLO};
	if (space)
		for (int i = 0; i < 6; i++)
			z6[i] = z6[i] == ZLO ? ZHI : ZLO;
	for (long k = 0; k < m; k++) {
		double p[2][6][3];
		for (int h = 0; h < 2; h++) {
			double x6[6] = {-1, l[k + h] - w, l[k + h] + w, r[k + h] - w, r[k + h] + w, 1};
			for (int i = 0; i < 6; i++) {
				p[h][i][0] = x6[i];
				p[h][i][1] = y[k + h];
				p[h][i][2] = z6[i];
			}
		}
		for (int i = 0; i < 5; i++)
			quad(t, p[0][i], p[0][i + 1], p[1][i + 1], p[1][i]);
	}
}

static void lines_main(int space, long m, long jitter, const char *ls, const char *rs,
		       struct tris *t, const char *truth)
{
	double *y = xreallocarray(NULL, (size_t)m + 1, sizeof *y);
	double *l = xreallocarray(NULL, (size_t)m + 1, sizeof *l);
	double *r = xreallocarray(NULL, (size_t)m + 1, sizeof *r);
	rng_state = (uint64_t)jitter;
	for (long k = 0; k <= m; k++) {
		y[k] = -1 + 2.0 * (double)k / (double)m;
		if (jitter && k > 0 && k < m)
			y[k] += (uniform() - 0.5) * 0.6 * 2.0 / (double)m;
	}
	edge_of(ls, y, m, l);
	edge_of(rs, y, m, r);
	line_surface(t, space, y, l, r, m);
	FILE *f = fopen(truth, "w");
	if (!f)
		die("%s:", truth);
	for (long k = 0; k <= m; k++)
		fprintf(f, "%.17g %.17g %.17g\n", y[k], l[k], r[k]);
	fshut(f, truth);
	free(y);
	free(l);
	free(r);
}

/* cos, sin of 2 pi m / n, exact at the quarter turns; tan of the same
 * angle for |m| <= n/8, exactly 1 at the corners of a cell. */
static double cs(long m, long n, int sine)
{
	m = ((m % n) + n) % n;
	if (4 * m % n == 0) {
		long q = 4 * m / n;
		static const double c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
		return sine ? s[q] : c[q];
	}
	return sine ? sin(2 * M_PI * (double)m / (double)n) : cos(2 * M_PI * (double)m / (double)n);
}

static double tn(long m, long n)
{
	if (8 * m == n)
		return 1;
	if (8 * m == -n)
		return -1;
	return m < 0 ? -tan(2 * M_PI * (double)-m / (double)n) : tan(2 * M_PI * (double)m / (double)n);
}

/* Where the ray of sector edge m from the hole centre (cx, cy) meets the
 * side of its cell (half side hp): computed from the side's own
 * parameter, so that two cells sharing a side compute equal bits. */
static void outer(double cx, double cy, double hp, long m, long n, double *p)
{
	m = ((m % n) + n) % n;
	if (8 * m <= n || 8 * m >= 7 * n) {
		long k = 8 * m <= n ? m : m - n;
		p[0] = cx + hp, p[1] = cy + hp * tn(k, n);
	} else if (8 * m <= 3 * n) {
		p[0] = cx + hp * tn(n / 4 - m, n), p[1] = cy + hp;
	} else if (8 * m <= 5 * n) {
		p[0] = cx - hp, p[1] = cy + hp * tn(n / 2 - m, n);
	} else {
		p[0] = cx - hp * tn(3 * n / 4 - m, n), p[1] = cy - hp;
	}
}

/* Hole (i, j) of the grid: the sectors that point into the box. */
static void hole_cell(struct tris *t, long i, long j, long nx, long ny, double rad, long n)
{
	const double pitch = 0.5, hp = 0.25, w = 0.03;
	double cx = pitch * (double)i, cy = pitch * (double)j;
	double ctr[3] = {cx, cy, ZLO};
	for (long m = 0; m < n; m++) {
		double cm = cs(2 * m + 1, 2 * n, 0), sm = cs(2 * m + 1, 2 * n, 1);
		if ((i == 0 && cm < 0) || (i == nx && cm > 0) || (j == 0 && sm < 0) ||
		    (j == ny && sm > 0))
			continue;
		double b[2][3], u[2][3], o[2][3];
		for (int h = 0; h < 2; h++) {
			double c = cs(m + h, n, 0), s = cs(m + h, n, 1);
			b[h][0] = cx + (rad - w) * c, b[h][1] = cy + (rad - w) * s, b[h][2] = ZLO;
			u[h][0] = cx + (rad + w) * c, u[h][1] = cy + (rad + w) * s, u[h][2] = ZHI;
			outer(cx, cy, hp, m + h, n, o[h]);
			o[h][2] = ZHI;
		}
		tri(t, ctr, b[0], b[1]);
		quad(t, b[0], u[0], u[1], b[1]);
		quad(t, u[0], o[0], o[1], u[1]);
	}
}

static void holes_main(long nx, long ny, double r0, double dr, long seed, long n,
		       struct tris *t, const char *truth)
{
	FILE *f = fopen(truth, "w");
	if (!f)
		die("%s:", truth);
	rng_state = (uint64_t)seed;
	for (long j = 0; j <= ny; j++)
		for (long i = 0; i <= nx; i++) {
			double rad = r0 + dr * (2 * uniform() - 1);
			hole_cell(t, i, j, nx, ny, rad, n);
			double a = 0.5 * (double)n * rad * rad * sin(2 * M_PI / (double)n);
			if (i > 0 && i < nx && j > 0 && j < ny)
				fprintf(f, "%.17g %.17g %.17g %.17g\n", 0.5 * (double)i,
					0.5 * (double)j, rad, sqrt(4 * a / M_PI));
		}
	fshut(f, truth);
}

int main(int argc, char **argv)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, "usage: roughsurf line|space|holes [options] -truth FILE -o FILE\n",
		   NULL, NULL);
	if (argc < 2)
		die_status(EXIT_USAGE, "give line, space or holes");
	const char *what = argv[1], *truth = NULL, *out = NULL;
	const char *ls = "sin:-0.2:0.01:8:0", *rs = "sin:0.2:0.01:5:1";
	long m = 2048, jitter = 0, swap = 0, nx = 8, ny = 8, seed = 1, n = 64;
	double r0 = 0.15, dr = 0.02;
	a.i = 2;
	while (a.i < argc) {
		if (args_int(&a, "-rows", 2, 1000000, &m) || args_int(&a, "-jitter", 1, 1000000, &jitter) ||
		    args_str(&a, "-left", &ls) || args_str(&a, "-right", &rs) ||
		    args_str(&a, "-truth", &truth) || args_str(&a, "-o", &out) ||
		    args_int(&a, "-nx", 2, 100, &nx) || args_int(&a, "-ny", 2, 100, &ny) ||
		    args_num(&a, "-r", 0.01, 0.2, &r0) || args_num(&a, "-dr", 0, 0.05, &dr) ||
		    args_int(&a, "-seed", 0, 1000000, &seed) || args_int(&a, "-sides", 8, 4096, &n))
			continue;
		if (args_flag(&a, "-swap")) {
			swap = 1;
			continue;
		}
		args_unknown(&a);
	}
	if (!truth || !out)
		args_error(&a, "give -truth FILE and -o FILE");
	args_done(&a, NULL);
	struct tris t = {NULL, 0, 0, (int)swap};
	if (strcmp(what, "holes") == 0) {
		if (n % 8)
			die_status(EXIT_USAGE, "-sides must be a multiple of 8");
		holes_main(nx, ny, r0, dr, seed, n, &t, truth);
		double box[6] = {0, 0.5 * (double)nx, 0, 0.5 * (double)ny, ZLO, ZHI};
		write_plot(out, &t, box);
	} else if (strcmp(what, "line") == 0 || strcmp(what, "space") == 0) {
		lines_main(what[0] == 's', m, jitter, ls, rs, &t, truth);
		double box[6] = {-1, 1, -1, 1, ZLO, ZHI};
		write_plot(out, &t, box);
	} else {
		die_status(EXIT_USAGE, "give line, space or holes, not \"%s\"", what);
	}
	free(t.v);
	return 0;
}
