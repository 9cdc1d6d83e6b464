/*
 * window.c - the process window of a focus-exposure matrix: the
 * exposure-latitude / depth-of-focus (EL/DOF) curve.
 *
 * A point (f, d) is in spec when |cd(f, d) - CD| <= tol CD and the opening
 * cleared.  Between the sampled foci F_i and doses D_j, cd is the bilinear
 * interpolant of its four corners, and a cell is usable only when all four
 * corners were measured and cleared.  For an exposure latitude e (percent)
 * a rectangle [f1, f2] x [d1, d2] has d1 = dc (1 - e/200), d2 = dc (1 +
 * e/200) about its centre dose dc; its DOF is f2 - f1.  The curve is
 * DOF(e) = the largest f2 - f1 over every dc of a rectangle wholly in spec.
 *
 * For a fixed (e, dc) this is exact: at a fixed focus cd is piecewise
 * linear in dose with kinks only at the sampled doses, so the vertical
 * segment {f} x [d1, d2] is in spec iff cd is in spec at d1, d2 and the
 * sampled doses between them; at each of those doses cd is linear in f
 * inside a focus cell, so each cell contributes one exact interval of f,
 * and touching intervals join.  Only dc is searched: a uniform scan of
 * SCAN_N centre doses, then REFINE_ROUNDS finer scans about the best.
 *
 * The maximum EL is found from the other side: at a fixed focus the
 * in-spec doses are exact intervals [a, b] (EL 200 (b - a) / (a + b)),
 * taken at MAXEL_SAMPLES focus samples per cell.
 */
#include "femwin.h"
#include "fmt_plot.h"
#include "fmt_template.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* centre-dose search: 1000 samples over the feasible range, then three
 * rounds of 200 over +-1 sample about the best: the centre dose is found to
 * about 1e-9 of the dose range, far below any interpolation error. */
enum { SCAN_N = 1000, REFINE_N = 200, REFINE_ROUNDS = 3 };
/* focus samples per cell for the maximum EL: its value at a kink of the
 * in-spec boundary between samples is missed by at most the slope of EL
 * times half a sample, below 0.01 % for any matrix of sane spacing */
enum { MAXEL_SAMPLES = 400 };
/* EL/DOF rows: exposure latitude in steps of 1 % */
#define EL_STEP 1.0

struct grid {
	int nf, nd;
	double *F, *D;          /* ascending */
	double *cd;             /* nf * nd, [i * nd + j] */
	unsigned char *ok;      /* measured and cleared */
	double lo, hi;          /* in spec: lo <= cd <= hi */
};

static int cmp_double(const void *pa, const void *pb)
{
	double a = *(const double *)pa, b = *(const double *)pb;
	return a < b ? -1 : a > b;
}

static int find(const double *v, int n, double x)
{
	int lo = 0, hi = n - 1;
	while (lo <= hi) {
		int m = (lo + hi) / 2;
		if (v[m] == x)
			return m;
		if (v[m] < x)
			lo = m + 1;
		else
			hi = m - 1;
	}
	return -1;
}

static void grid_build(struct grid *g, const struct fem_table *t, double lo, double hi)
{
	g->F = xreallocarray(NULL, (size_t)t->n, sizeof *g->F);
	g->D = xreallocarray(NULL, (size_t)t->n, sizeof *g->D);
	for (int i = 0; i < t->n; i++) {
		g->F[i] = t->p[i].focus;
		g->D[i] = t->p[i].dose;
	}
	qsort(g->F, (size_t)t->n, sizeof *g->F, cmp_double);
	qsort(g->D, (size_t)t->n, sizeof *g->D, cmp_double);
	g->nf = g->nd = 0;
	for (int i = 0; i < t->n; i++) {
		if (g->nf == 0 || g->F[i] != g->F[g->nf - 1])
			g->F[g->nf++] = g->F[i];
		if (g->nd == 0 || g->D[i] != g->D[g->nd - 1])
			g->D[g->nd++] = g->D[i];
	}
	g->cd = xcalloc((size_t)g->nf * (size_t)g->nd, sizeof *g->cd);
	g->ok = xcalloc((size_t)g->nf * (size_t)g->nd, 1);
	for (int k = 0; k < t->n; k++) {
		int i = find(g->F, g->nf, t->p[k].focus), j = find(g->D, g->nd, t->p[k].dose);
		g->cd[i * g->nd + j] = t->p[k].cd;
		g->ok[i * g->nd + j] = (unsigned char)(t->p[k].cleared != 0);
	}
	g->lo = lo;
	g->hi = hi;
}

static void grid_free(struct grid *g)
{
	free(g->F);
	free(g->D);
	free(g->cd);
	free(g->ok);
}

static int good(const struct grid *g, int i, int j)
{
	const unsigned char *o = g->ok;
	int nd = g->nd;
	return o[i * nd + j] && o[(i + 1) * nd + j] && o[i * nd + j + 1] && o[(i + 1) * nd + j + 1];
}

/* cd on the focus line i at dose x inside the dose band j */
static double cd_line(const struct grid *g, int i, int j, double x)
{
	double c0 = g->cd[i * g->nd + j], c1 = g->cd[i * g->nd + j + 1];
	if (x == g->D[j])
		return c0;
	if (x == g->D[j + 1])
		return c1;
	return c0 + (c1 - c0) * (x - g->D[j]) / (g->D[j + 1] - g->D[j]);
}

/* Intersects [*ta, *tb] with {t in [0, 1]: lo <= v0 + (v1 - v0) t <= hi}. */
static void clip_band(double v0, double v1, double lo, double hi, double *ta, double *tb)
{
	int in0 = v0 >= lo && v0 <= hi, in1 = v1 >= lo && v1 <= hi;
	double a, b;
	if (in0 && in1) {
		a = 0;
		b = 1;
	} else if (v0 == v1) {
		a = 1;
		b = 0;
	} else {
		double s = v1 - v0, t1 = (lo - v0) / s, t2 = (hi - v0) / s;
		a = fmax(0, fmin(t1, t2));
		b = fmin(1, fmax(t1, t2));
		if (in0)
			a = 0;
		if (in1)
			b = 1;
	}
	if (a > *ta)
		*ta = a;
	if (b < *tb)
		*tb = b;
}

/* The longest focus interval over which the dose segment [d1, d2] lies in
 * spec: returns 1 and its length and centre, or 0 if there is none. */
static int segment_run(const struct grid *g, double d1, double d2, double *len, double *centre)
{
	const double *D = g->D, *F = g->F;
	int nd = g->nd;
	if (d1 < D[0] || d2 > D[nd - 1])
		return 0;
	/* the dose bands the segment crosses: ja..jb; a point segment on a
	 * sampled dose may use either band beside it */
	int ja, jb, point = !(d2 > d1);
	ja = 0;
	while (ja < nd - 2 && D[ja + 1] <= d1)
		ja++;
	jb = ja;
	while (jb < nd - 2 && D[jb + 1] < d2)
		jb++;
	int alt = -1;   /* point segment on D[ja] with ja > 0: band ja - 1 too */
	if (point && d1 == D[ja] && ja > 0)
		alt = ja - 1;
	int found = 0;
	double run_a = 0, run_b = 0, best = -1, best_c = 0;
	int open = 0;
	for (int i = 0; i < g->nf - 1; i++) {
		double ta = 0, tb = 1;
		int use = -1;   /* the band set: ja..jb, or alt for a point */
		int valid = 1;
		for (int j = ja; j <= jb; j++)
			valid = valid && good(g, i, j);
		if (!valid && alt >= 0 && good(g, i, alt))
			valid = 1, use = alt;
		if (valid) {
			if (use >= 0) {
				clip_band(cd_line(g, i, use, d1), cd_line(g, i + 1, use, d1),
					  g->lo, g->hi, &ta, &tb);
			} else {
				clip_band(cd_line(g, i, ja, d1), cd_line(g, i + 1, ja, d1),
					  g->lo, g->hi, &ta, &tb);
				clip_band(cd_line(g, i, jb, d2), cd_line(g, i + 1, jb, d2),
					  g->lo, g->hi, &ta, &tb);
				for (int j = ja + 1; j <= jb; j++)
					clip_band(g->cd[i * nd + j], g->cd[(i + 1) * nd + j],
						  g->lo, g->hi, &ta, &tb);
			}
		}
		if (!valid || ta > tb) {
			open = 0;
			continue;
		}
		double a = ta == 0 ? F[i] : F[i] + ta * (F[i + 1] - F[i]);
		double b = tb == 1 ? F[i + 1] : F[i] + tb * (F[i + 1] - F[i]);
		if (open && run_b == F[i] && a == F[i])
			run_b = b;
		else
			run_a = a, run_b = b;
		open = b == F[i + 1];
		found = 1;
		if (run_b - run_a > best) {
			best = run_b - run_a;
			best_c = 0.5 * (run_a + run_b);
		}
	}
	if (found) {
		*len = best;
		*centre = best_c;
	}
	return found;
}

/* The best rectangle at exposure latitude el (percent). */
static int best_rect(const struct grid *g, double el, struct fem_window_row *r)
{
	double h = el / 200;
	if (h >= 1)
		return 0;
	double c0 = g->D[0] / (1 - h), c1 = g->D[g->nd - 1] / (1 + h);
	if (c0 > c1)
		return 0;
	int found = 0;
	double best = -1, best_f = 0, best_dc = 0;
	double lo = c0, hi = c1;
	for (int round = 0; round <= REFINE_ROUNDS; round++) {
		int n = round == 0 ? SCAN_N : REFINE_N;
		double step = (hi - lo) / n;
		double centre_dc = best_dc;
		for (int k = 0; k <= n; k++) {
			double dc = k == n ? hi : lo + k * step;
			double d1 = fmax(dc * (1 - h), g->D[0]), d2 = fmin(dc * (1 + h), g->D[g->nd - 1]);
			double len, fc;
			if (segment_run(g, d1, d2, &len, &fc) && len > best) {
				best = len;
				best_f = fc;
				best_dc = dc;
				found = 1;
			}
		}
		if (!found)
			return 0;
		(void)centre_dc;
		lo = fmax(c0, best_dc - step);
		hi = fmin(c1, best_dc + step);
		if (!(hi > lo))
			break;
	}
	r->el = el;
	r->dof = best;
	r->focus = best_f;
	r->dose = best_dc;
	return 1;
}

/* The in-spec dose intervals at the focus F[i] + t (F[i+1] - F[i]), t in
 * [0, 1): cd is linear in dose inside each usable cell, so they are exact;
 * touching intervals join.  Writes up to cap (a, b) pairs to iv and
 * returns their number. */
static int dose_intervals(const struct grid *g, int i, double t, double *iv, int cap)
{
	int n = 0, open = 0, nd = g->nd;
	for (int j = 0; j < nd - 1; j++) {
		if (!good(g, i, j)) {
			open = 0;
			continue;
		}
		double v0 = g->cd[i * nd + j] + t * (g->cd[(i + 1) * nd + j] - g->cd[i * nd + j]);
		double v1 = g->cd[i * nd + j + 1] +
			    t * (g->cd[(i + 1) * nd + j + 1] - g->cd[i * nd + j + 1]);
		double sa = 0, sb = 1;
		clip_band(v0, v1, g->lo, g->hi, &sa, &sb);
		if (sa > sb) {
			open = 0;
			continue;
		}
		double da = sa == 0 ? g->D[j] : g->D[j] + sa * (g->D[j + 1] - g->D[j]);
		double db = sb == 1 ? g->D[j + 1] : g->D[j] + sb * (g->D[j + 1] - g->D[j]);
		if (open && iv[2 * n - 1] == g->D[j] && da == g->D[j]) {
			iv[2 * n - 1] = db;
		} else if (n < cap) {
			iv[2 * n] = da;
			iv[2 * n + 1] = db;
			n++;
		}
		open = db == g->D[j + 1];
	}
	return n;
}

/* The largest exposure latitude (percent) of the in-spec doses at any
 * focus; -1 if nothing is in spec. */
static double max_el(const struct grid *g)
{
	double best = -1;
	double *iv = xreallocarray(NULL, (size_t)g->nd * 2, sizeof *iv);
	for (int i = 0; i < g->nf - 1; i++)
		for (int s = 0; s < MAXEL_SAMPLES; s++) {
			int n = dose_intervals(g, i, (s + 0.5) / MAXEL_SAMPLES, iv, g->nd);
			for (int k = 0; k < n; k++) {
				double e = 200 * (iv[2 * k + 1] - iv[2 * k]) / (iv[2 * k] + iv[2 * k + 1]);
				if (e > best)
					best = e;
			}
		}
	free(iv);
	return best;
}

/* The in-spec region in (focus, dose) for drawplot: the rectangles of 5 %
 * and 10 % EL (empty curves when there are none), then the outline of the
 * region, one closed curve per run of focus samples that have in-spec
 * doses (at each sample its longest in-spec dose interval), and a template
 * that labels the first three. */
enum { REGION_SAMPLES = 40 };

static void write_region(const struct grid *g, const struct fem_window_row *r5, int have5,
			 const struct fem_window_row *r10, int have10, const char *plot_path,
			 const char *template_path)
{
	double b[4] = {g->F[0], g->F[g->nf - 1], g->D[0], g->D[g->nd - 1]};
	struct plot_file *pf = fmt_plot_new(2);
	fmt_labels_set(&pf->labels, "In-spec region", "focus (um)", "dose (mJ/cm2)", NULL);
	struct plot_set *set = fmt_plot_add_set(pf, b);
	const struct fem_window_row *rr[2] = {r5, r10};
	int have[2] = {have5, have10};
	for (int k = 0; k < 2; k++) {
		const struct fem_window_row *r = rr[k];
		double h = r->el / 200, f1 = r->focus - r->dof / 2, f2 = r->focus + r->dof / 2;
		double d1 = r->dose * (1 - h), d2 = r->dose * (1 + h);
		double p[10] = {f1, d1, f2, d1, f2, d2, f1, d2, f1, d1};
		fmt_plot_add_curve(pf, set, have[k] ? 5 : 0, p);
	}
	int ns = (g->nf - 1) * REGION_SAMPLES + 1;
	double *lo = xreallocarray(NULL, (size_t)ns * 3, sizeof *lo), *hi = lo + ns, *fs = hi + ns;
	unsigned char *in = xcalloc((size_t)ns, 1);
	double *iv = xreallocarray(NULL, (size_t)g->nd * 2, sizeof *iv);
	for (int k = 0; k < ns; k++) {
		int i = k / REGION_SAMPLES;
		double t = (double)(k % REGION_SAMPLES) / REGION_SAMPLES;
		if (i == g->nf - 1) {   /* the last focus: t = 1 of the last cell */
			i--;
			t = 1;
		}
		fs[k] = g->F[i] + t * (g->F[i + 1] - g->F[i]);
		int n = dose_intervals(g, i, t, iv, g->nd);
		double best = -1;
		for (int m = 0; m < n; m++)
			if (iv[2 * m + 1] - iv[2 * m] > best) {
				best = iv[2 * m + 1] - iv[2 * m];
				lo[k] = iv[2 * m];
				hi[k] = iv[2 * m + 1];
				in[k] = 1;
			}
	}
	double *p = xreallocarray(NULL, (size_t)ns * 4 + 2, sizeof *p);
	int pieces = 0;
	for (int k = 0; k < ns;) {
		if (!in[k]) {
			k++;
			continue;
		}
		int e = k;
		while (e + 1 < ns && in[e + 1])
			e++;
		int m = 0;
		for (int q = k; q <= e; q++) {
			p[2 * m] = fs[q];
			p[2 * m++ + 1] = lo[q];
		}
		for (int q = e; q >= k; q--) {
			p[2 * m] = fs[q];
			p[2 * m++ + 1] = hi[q];
		}
		p[2 * m] = fs[k];
		p[2 * m++ + 1] = lo[k];
		fmt_plot_add_curve(pf, set, m, p);
		pieces++;
		k = e + 1;
	}
	fmt_plot_write(plot_path, pf);
	fmt_plot_free(pf);
	if (template_path) {
		/* one entry per curve, so that only the first outline is labelled */
		static char l5[] = "5 % EL", l10[] = "10 % EL", lin[] = "in spec";
		struct template t = {2 + pieces, xcalloc((size_t)(2 + pieces), sizeof *t.e)};
		t.e[0] = (struct template_entry){1, 0, l5, 0};
		t.e[1] = (struct template_entry){2, 0, l10, 0};
		for (int k = 0; k < pieces; k++)
			t.e[2 + k] = (struct template_entry){3, 0, k == 0 ? lin : NULL, 0};
		fmt_template_write(template_path, &t);
		free(t.e);
	}
	free(p);
	free(iv);
	free(in);
	free(lo);
}

/* v rounded to a multiple of 1e-9 of its axis' range q, then to 9
 * significant digits, so that window.dat carries neither the search's
 * last-digit noise nor a focus of 2.8e-17 for 0 */
static double tidy(double v, double q)
{
	char buf[40];
	q *= 1e-9;
	if (q > 0)
		v = round(v / q) * q;
	snprintf(buf, sizeof buf, "%.9g", v);
	return strtod(buf, NULL) + 0.0;
}

static void report(const struct grid *g, const char *what, const struct fem_window_row *r,
		   int have)
{
	/* a rectangle that reaches the first or last focus may be cut by the
	 * sweep's range: its DOF is a lower bound */
	double eps = 1e-9 * (g->F[g->nf - 1] - g->F[0]);
	int edge = r->focus - r->dof / 2 <= g->F[0] + eps ||
		   r->focus + r->dof / 2 >= g->F[g->nf - 1] - eps;
	if (have)
		printf("DOF at %s EL: %.4g um (focus %.4g um, dose %.4g mJ/cm2)%s\n", what,
		       r->dof, fabs(r->focus) < eps ? 0 : r->focus, r->dose,
		       edge ? "; at the edge of the focus range: sweep wider" : "");
	else
		printf("DOF at %s EL: 0 um (no window)\n", what);
}

void femwin_window(const struct fem_table *t, const struct femwin_spec *s,
		   const char *name, const char *window_path, const char *plot_path,
		   const char *region_path, const char *region_template)
{
	struct grid g;
	double tol = s->tol / 100 * s->target;
	grid_build(&g, t, s->target - tol, s->target + tol);
	if (g.nf < 2 || g.nd < 2) {
		grid_free(&g);
		die("%s: a process window needs at least 2 foci and 2 doses (%d and %d here)",
		    name, g.nf, g.nd);
	}
	double emax = max_el(&g);
	int n = 0, cap = 0;
	struct fem_window_row *rows = NULL;
	struct fem_window_row r5 = {0}, r10 = {0};
	int have5 = 0, have10 = 0;
	for (int k = 0; emax >= 0 && k * EL_STEP <= emax; k++) {
		struct fem_window_row r;
		if (!best_rect(&g, k * EL_STEP, &r))
			continue;
		double fq = g.F[g.nf - 1] - g.F[0], dq = g.D[g.nd - 1] - g.D[0];
		r.el = tidy(r.el, 0);
		r.dof = tidy(r.dof, fq);
		r.focus = tidy(r.focus, fq);
		r.dose = tidy(r.dose, dq);
		if (n == cap) {
			cap = cap ? 2 * cap : 64;
			rows = xreallocarray(rows, (size_t)cap, sizeof *rows);
		}
		rows[n++] = r;
	}
	/* 5 % and 10 % are rows of the curve when EL_STEP divides them */
	have5 = best_rect(&g, 5, &r5);
	have10 = best_rect(&g, 10, &r10);
	fmt_fem_window_write(window_path, rows, n);
	if (plot_path) {
		struct plot_file *pf = fmt_plot_new(2);
		fmt_labels_set(&pf->labels, "Process window", "EL (%)", "DOF (um)", NULL);
		double b[4] = {0, n > 0 ? rows[n - 1].el : 1, 0, 0};
		for (int k = 0; k < n; k++)
			b[3] = fmax(b[3], rows[k].dof);
		if (b[1] <= 0)
			b[1] = 1;
		if (b[3] <= 0)
			b[3] = 1;
		struct plot_set *ps = fmt_plot_add_set(pf, b);
		double *xy = xreallocarray(NULL, (size_t)(n > 0 ? n : 1) * 2, sizeof *xy);
		for (int k = 0; k < n; k++) {
			xy[2 * k] = rows[k].el;
			xy[2 * k + 1] = rows[k].dof;
		}
		fmt_plot_add_curve(pf, ps, n, xy);
		free(xy);
		fmt_plot_write(plot_path, pf);
		fmt_plot_free(pf);
	}
	if (region_path)
		write_region(&g, &r5, have5, &r10, have10, region_path, region_template);
	printf("window: cd %.4g um +- %.4g %% (%.4g to %.4g um), %d foci x %d doses\n",
	       s->target, s->tol, g.lo, g.hi, g.nf, g.nd);
	report(&g, "5%", &r5, have5);
	report(&g, "10%", &r10, have10);
	if (emax >= 0)
		printf("max EL: %.2f %%\n", emax);
	else
		printf("max EL: none (no point in spec)\n");
	free(rows);
	grid_free(&g);
}
