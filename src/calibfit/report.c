/*
 * report.c - what calib leaves the user: calib.dat (the fitted values
 * with their 1-sigma errors, the rms misfit, the correlations) and the
 * pictures' plot files (measured against fitted CD per focus, and the
 * residuals), with the one-line warnings for parameters the data do not
 * determine.
 *
 * The errors are the usual linearised ones (Bard 1974; Press et al.,
 * Numerical Recipes 15.5): cov = s2 (J'J)^-1 with s2 = SSR / (N - p) and
 * J the finite-difference Jacobian at the solution, so they assume that
 * the model is right and the misfit is measurement noise.
 */
#include "calibfit.h"
#include "calibfit_report.h"
#include "fmt_plot.h"
#include "fmt_template.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Correlation above which two parameters are nearly unidentifiable. */
#define CALIB_WARN_CORR 0.999
/* A 1-sigma error above this fraction of the value: not constrained. */
#define CALIB_WARN_REL 0.10

static double rms_nm(const struct calib_points *s)
{
	return 1000 * sqrt(calib_ssr(s) / s->n);
}

static const int markers[] = {2, 5, 8, 11, 14, 17, 4, 7, 10, 13, 16};
enum { NMARKERS = sizeof markers / sizeof markers[0] };

/* The distinct doses of the points, ascending (they are sorted by focus
 * first): returns their count. */
static int doses_of(const struct calib_points *s, double *d)
{
	int nd = 0;
	for (int i = 0; i < s->n; i++) {
		int k = 0;
		while (k < nd && d[k] != s->p[i].dose)
			k++;
		if (k == nd)
			d[nd++] = s->p[i].dose;
	}
	for (int a = 1; a < nd; a++)
		for (int b = a; b > 0 && d[b - 1] > d[b]; b--) {
			double t = d[b];
			d[b] = d[b - 1];
			d[b - 1] = t;
		}
	return nd;
}

/* Curves of one dose: x focus, y what(point) (fit, measured or residual). */
static void dose_curve(struct plot_file *pf, struct plot_set *set, const struct calib_points *s,
		       double dose, int what, double *xy)
{
	int m = 0;
	for (int i = 0; i < s->n; i++) {
		if (s->p[i].dose != dose)
			continue;
		double y = what == 0 ? s->cd[i] : what == 1 ? s->p[i].cd
			 : 1000 * (s->cd[i] - s->p[i].cd);
		if (what == 0 && !(s->cd[i] > 0))
			continue;
		xy[2 * m] = s->p[i].focus;
		xy[2 * m + 1] = y;
		m++;
	}
	fmt_plot_add_curve(pf, set, m, xy);
}

static void entry(struct template *tp, int ln, int mkr, const char *what, double dose)
{
	char num[NUM_BUFSZ], label[NUM_BUFSZ + 32];
	snprintf(label, sizeof label, "%s %s mJ/cm2", what, num_fmt(num, dose));
	struct template_entry *e = &tp->e[tp->n++];
	e->ln_type = ln;
	e->mkr_type = mkr;
	e->label = xstrdup(label);
	e->line = 0;
}

static void write_template(const char *path, struct template *tp)
{
	fmt_template_write(path, tp);
	for (int k = 0; k < tp->n; k++)
		free(tp->e[k].label);
	free(tp->e);
}

/* bossung.2D/.tpl: per dose the fitted CD (a line) and the measured
 * (markers); residuals.2D/.tpl: cd_sim - cd_meas in nm, markers per dose,
 * over a zero line. */
static void pictures(const struct calib_points *s, const char *dir)
{
	double *d = xreallocarray(NULL, (size_t)s->n, sizeof *d);
	double *xy = xreallocarray(NULL, (size_t)s->n * 2, sizeof *xy);
	int nd = doses_of(s, d);
	double b[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY}, rb[4];
	for (int i = 0; i < s->n; i++) {
		b[0] = fmin(b[0], s->p[i].focus);
		b[1] = fmax(b[1], s->p[i].focus);
		b[2] = fmin(b[2], fmin(s->p[i].cd, s->cd[i] > 0 ? s->cd[i] : s->p[i].cd));
		b[3] = fmax(b[3], fmax(s->p[i].cd, s->cd[i]));
	}
	if (!(b[1] > b[0])) {
		b[0] -= 0.1;
		b[1] += 0.1;
	}
	memcpy(rb, b, sizeof rb);
	rb[2] = rb[3] = 0;
	for (int i = 0; i < s->n; i++) {
		rb[2] = fmin(rb[2], 1000 * (s->cd[i] - s->p[i].cd));
		rb[3] = fmax(rb[3], 1000 * (s->cd[i] - s->p[i].cd));
	}
	if (!(rb[3] > rb[2]))
		rb[3] = rb[2] + 1;
	size_t path_len = strlen(dir) + 32;
	char *path = xmalloc(path_len);

	struct plot_file *pf = fmt_plot_new(2);
	fmt_labels_set(&pf->labels, "measured and fitted CD", "focus (um)", "CD (um)", NULL);
	struct plot_set *set = fmt_plot_add_set(pf, b);
	struct template tp = {0, xcalloc((size_t)nd * 2, sizeof *tp.e)};
	for (int k = 0; k < nd; k++) {
		dose_curve(pf, set, s, d[k], 0, xy);
		entry(&tp, 1 + k % 10, 0, "fit", d[k]);
		dose_curve(pf, set, s, d[k], 1, xy);
		entry(&tp, 0, markers[k % NMARKERS], "measured", d[k]);
	}
	snprintf(path, path_len, "%s/bossung.2D", dir);
	fmt_plot_write(path, pf);
	fmt_plot_free(pf);
	snprintf(path, path_len, "%s/bossung.tpl", dir);
	write_template(path, &tp);

	pf = fmt_plot_new(2);
	fmt_labels_set(&pf->labels, "residuals: fitted - measured CD", "focus (um)",
		       "residual (nm)", NULL);
	set = fmt_plot_add_set(pf, rb);
	tp.n = 0;
	tp.e = xcalloc((size_t)nd + 1, sizeof *tp.e);
	double zero[4] = {rb[0], 0, rb[1], 0};
	fmt_plot_add_curve(pf, set, 2, zero);
	tp.e[tp.n++] = (struct template_entry){1, 0, xstrdup("zero"), 0};
	for (int k = 0; k < nd; k++) {
		dose_curve(pf, set, s, d[k], 2, xy);
		entry(&tp, 0, markers[k % NMARKERS], "dose", d[k]);
	}
	snprintf(path, path_len, "%s/residuals.2D", dir);
	fmt_plot_write(path, pf);
	fmt_plot_free(pf);
	snprintf(path, path_len, "%s/residuals.tpl", dir);
	write_template(path, &tp);
	free(path);
	free(xy);
	free(d);
}

static void warnings(int p, const struct calib_free *f, const double *v, const double *se,
		     const double *cov)
{
	for (int a = 0; a < p; a++)
		for (int b = a + 1; b < p; b++) {
			double c = cov[a * p + b] / (se[a] * se[b]);
			if (fabs(c) > CALIB_WARN_CORR)
				warn("warning: %s %d and %s %d are nearly unidentifiable (correlation %.5f)",
				     f[a].stmt, f[a].k, f[b].stmt, f[b].k, c);
		}
	for (int j = 0; j < p; j++)
		if (!(se[j] <= CALIB_WARN_REL * fabs(v[j])))
			warn("warning: the data do not constrain %s %d: its stderr %g is above %g %% of its value %g",
			     f[j].stmt, f[j].k, se[j], 100 * CALIB_WARN_REL, v[j]);
}

void calib_report(const struct calib_report_in *in)
{
	int p = in->p, n = in->fit->n;
	const struct calib_free *f = in->free;
	double ssr = calib_ssr(in->fit);
	double cov[CALIB_MAX_FREE * CALIB_MAX_FREE], se[CALIB_MAX_FREE];
	calib_covariance(p, n, in->J, ssr / (n - p), cov);
	for (int j = 0; j < p; j++)
		se[j] = sqrt(cov[j * p + j]);
	size_t path_len = strlen(in->dir) + 32;
	char *path = xmalloc(path_len);
	snprintf(path, path_len, "%s/calib.dat", in->dir);
	struct aout *a = aout_open(path);
	char x[NUM_BUFSZ];
	fputs("# statement k value stderr\n", a->f);
	for (int j = 0; j < p; j++)
		fprintf(a->f, "%s %d %s %s\n", f[j].stmt, f[j].k, num_fmt(x, in->v[j]),
			isfinite(se[j]) ? num_fmt((char[NUM_BUFSZ]){0}, se[j]) : "inf");
	fprintf(a->f, "# rms_nm %.4f\n", rms_nm(in->fit));
	if (in->val)
		fprintf(a->f, "# validate_rms_nm %.4f\n", rms_nm(in->val));
	fprintf(a->f, "# points %d free %d ssr_um2 %s iterations %d\n", n, p, num_fmt(x, ssr),
		in->iterations);
	fputs("# correlation", a->f);
	for (int j = 0; j < p; j++)
		fprintf(a->f, " %s:%d", f[j].stmt, f[j].k);
	fputc('\n', a->f);
	for (int r = 0; r < p; r++) {
		fputc('#', a->f);
		for (int c = 0; c < p; c++)
			fprintf(a->f, " %.6f", cov[r * p + c] / (se[r] * se[c]));
		fputc('\n', a->f);
	}
	aout_commit(a);
	free(path);
	pictures(in->fit, in->dir);
	warnings(p, f, in->v, se, cov);
	if (in->fit->uncleared)
		die("%d of the %d measured points do not clear with the fitted values", in->fit->uncleared, n);
	if (in->val && in->val->uncleared)
		die("%d of the %d validation points do not clear with the fitted values",
		    in->val->uncleared, in->val->n);
}
