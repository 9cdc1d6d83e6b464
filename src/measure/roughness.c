/*
 * roughness.c - the roughness of a space or line at one height: its two
 * edges sampled along the whole box, their line-edge roughness (LER),
 * the line-width roughness (LWR), their correlation length and power
 * spectral density.
 *
 * The edges are read on lines across the feature (surf_sample_lines:
 * every mesh row when the surface has evenly spaced rows, else evenly
 * spaced lines, at least ROUGH_LINES of them).  On each line the feature
 * is the span of its kind (developed for a space, resist for a line)
 * that holds the middle of its span on the neighbouring line, followed
 * outwards from the line nearest the point given: an edge that wanders
 * by more than the feature's width between lines is not followed, and
 * measure says where the feature is lost.
 *
 * Figures, with d the deviations of an edge from its mean over the n
 * lines, spaced dl apart over the box length L = n dl:
 *   LER = 3 sigma, sigma^2 = (1/n) sum d_j^2 (population);
 *   LWR = 3 sigma of the width, right - left;
 *   R(k) = sum_j d_j d_(j+k mod n) / sum_j d_j^2, the autocorrelation of
 *     the edge taken as periodic (the simulation cell repeats), whose
 *     first fall below 1/e, interpolated linearly between lags, is the
 *     correlation length (times dl);
 *   PSD(f_k) = (2 dl / n) |D_k|^2, D the discrete Fourier transform of d,
 *     at f_k = k / L for k = 1 .. n/2 (the last not doubled for even n),
 *     so that sum_k PSD(f_k) / L = sigma^2 (Parseval).
 * R is the inverse transform of |D|^2 (Wiener-Khinchin), one FFT each
 * way (src/lib/numerics/fft.c).
 */
#include "rough.h"
#include "fmt_plot.h"
#include "fft.h"
#include "surf_lines.h"
#include "util.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Lines at least (measure(1), Roughness), and at most: a few ray tests
 * per line, so the lines bound the time (tests/bench/measure-rough.sh:
 * 16384 lines about a second on a mesh of long thin strips). */
enum { ROUGH_LINES = 1024, ROUGH_LINES_MAX = 65536 };

/* The span of kind on line ln holding t, else the one overlapping
 * [plo, phi] most; -1 if none overlaps. */
static long pick_span(const struct surf_line *ln, int resist, double t, double plo, double phi)
{
	long best = -1;
	double most = 0;
	for (size_t k = 0; k < ln->n; k++) {
		const struct surf_span *sp = &ln->sp[k];
		if (sp->resist != resist)
			continue;
		if (sp->lo <= t && t < sp->hi)
			return (long)k;
		double ov = fmin(sp->hi, phi) - fmax(sp->lo, plo);
		if (ov > most) {
			most = ov;
			best = (long)k;
		}
	}
	return best;
}

struct follow {
	const struct surf *s;
	const struct options *o;
	const struct surf_line *lines;
	const double *c;
	struct roughness *r;
	char *err;
	size_t errsz;
};

/* Reads the feature on line l from the previous line's span; 0, or -1
 * with err set. */
static int follow_line(const struct follow *f, size_t l, double *plo, double *phi)
{
	const struct options *o = f->o;
	const char *what = o->kind == LINE ? "line" : "space";
	char along = o->axis == 0 ? 'y' : 'x';
	long k = pick_span(&f->lines[l], o->kind == LINE, 0.5 * (*plo + *phi), *plo, *phi);
	if (k < 0) {
		snprintf(f->err, f->errsz, "the %s through (%g, %g) is lost at %c = %g: no %s "
			 "there overlaps it on the neighbouring line", what, o->x, o->y, along,
			 f->c[l], what);
		return -1;
	}
	const struct surf_span *sp = &f->lines[l].sp[k];
	const double *box = f->s->box;
	if (sp->lo <= box[2 * o->axis] || sp->hi >= box[2 * o->axis + 1]) {
		snprintf(f->err, f->errsz, "the %s through (%g, %g) reaches the box edge at "
			 "%c = %g: its edges are not both inside the box", what, o->x, o->y,
			 along, f->c[l]);
		return -1;
	}
	f->r->edge[0][l] = *plo = sp->lo;
	f->r->edge[1][l] = *phi = sp->hi;
	return 0;
}

/* The line nearest to position p among the n ascending c[]. */
static size_t nearest(const double *c, size_t n, double p)
{
	size_t best = 0;
	for (size_t l = 1; l < n; l++)
		if (fabs(c[l] - p) < fabs(c[best] - p))
			best = l;
	return best;
}

/* The edges on every line, followed up and down from the line nearest
 * the point, starting from the table's span r0. */
static int follow_edges(const struct follow *f, const struct row *r0)
{
	size_t n = f->r->n;
	size_t l0 = nearest(f->c, n, f->o->axis == 0 ? f->o->y : f->o->x);
	double lo = r0->a, hi = r0->b;
	for (size_t l = l0; l < n; l++)
		if (follow_line(f, l, &lo, &hi))
			return -1;
	lo = f->r->edge[0][l0];
	hi = f->r->edge[1][l0];
	for (size_t l = l0; l-- > 0;)
		if (follow_line(f, l, &lo, &hi))
			return -1;
	return 0;
}

/* sigma of v[0..n-1] about its mean (population); the deviations into d. */
static double sigma_dev(const double *v, size_t n, double *d)
{
	double mean = 0, ss = 0;
	for (size_t j = 0; j < n; j++)
		mean += v[j];
	mean /= (double)n;
	for (size_t j = 0; j < n; j++) {
		d[j] = v[j] - mean;
		ss += d[j] * d[j];
	}
	return sqrt(ss / (double)n);
}

/* The PSD (n/2 values) and the correlation length of the deviations
 * d[0..n-1] of one edge (see the note at the head). */
static double spectrum(const double *d, size_t n, double dl, double *psd)
{
	struct fft_plan *fw = fft_plan_new(n, -1), *bw = fft_plan_new(n, +1);
	size_t nw = fft_work_size(fw) > fft_work_size(bw) ? fft_work_size(fw) : fft_work_size(bw);
	double complex *x = xreallocarray(NULL, n, sizeof *x);
	double complex *work = xreallocarray(NULL, nw ? nw : 1, sizeof *work);
	for (size_t j = 0; j < n; j++)
		x[j] = d[j];
	fft_exec(fw, x, work);
	for (size_t k = 0; k < n; k++) {
		double p = creal(x[k]) * creal(x[k]) + cimag(x[k]) * cimag(x[k]);
		if (k >= 1 && k <= n / 2)
			psd[k - 1] = (2 * k == n ? 1 : 2) * dl / (double)n * p;
		x[k] = p;
	}
	fft_exec(bw, x, work);
	double corr = -1, r0 = creal(x[0]), e = exp(-1);
	for (size_t k = 1; r0 > 0 && k <= n / 2; k++) {
		double a = creal(x[k - 1]) / r0, b = creal(x[k]) / r0;
		if (b < e) {
			corr = ((double)(k - 1) + (a - e) / (a - b)) * dl;
			break;
		}
	}
	free(work);
	free(x);
	fft_plan_free(fw);
	fft_plan_free(bw);
	return corr;
}

static void figures(struct roughness *r)
{
	size_t n = r->n;
	double *d = xreallocarray(NULL, n, sizeof *d);
	double *w = xreallocarray(NULL, n, sizeof *w);
	for (int e = 0; e < 2; e++) {
		r->ler[e] = 3 * sigma_dev(r->edge[e], n, d);
		r->psd[e] = xcalloc(n / 2 + 1, sizeof *r->psd[e]);
		r->corr[e] = spectrum(d, n, r->step, r->psd[e]);
	}
	for (size_t j = 0; j < n; j++)
		w[j] = r->edge[1][j] - r->edge[0][j];
	r->lwr = 3 * sigma_dev(w, n, d);
	free(w);
	free(d);
}

int roughness_measure(const struct surf *s, const struct options *o, double z,
		      const struct row *r0, struct roughness *r, char *err, size_t errsz)
{
	memset(r, 0, sizeof *r);
	if (!(r0->cd > 0)) {
		snprintf(err, errsz, "no %s through (%g, %g) at z = %g: no edges to measure",
			 o->kind == LINE ? "line" : "space", o->x, o->y, z);
		return -1;
	}
	int fa = 1 - o->axis;   /* the feature runs along this coordinate */
	double *c = surf_sample_lines(s, fa, ROUGH_LINES, ROUGH_LINES_MAX, &r->n, &r->rows);
	r->step = (s->box[2 * fa + 1] - s->box[2 * fa]) / (double)r->n;
	struct surf_section sec;
	surf_section(s, feature_height(s, z), &sec);
	struct surf_line *lines = surf_lines_spans(s, &sec, o->axis, c, r->n);
	surf_section_free(&sec);
	r->edge[0] = xreallocarray(NULL, r->n, sizeof *r->edge[0]);
	r->edge[1] = xreallocarray(NULL, r->n, sizeof *r->edge[1]);
	struct follow f = {s, o, lines, c, r, err, errsz};
	int st = follow_edges(&f, r0);
	surf_lines_free(lines, r->n);
	free(c);
	if (st) {
		roughness_free(r);
		return -1;
	}
	figures(r);
	return 0;
}

void roughness_psd(const char *path, const struct roughness *r)
{
	double length = r->step * (double)r->n;
	size_t m = r->n / 2;
	double *p = xreallocarray(NULL, 2 * (m ? m : 1), sizeof *p);
	double lo = INFINITY, hi = 0;
	for (int e = 0; e < 2; e++)
		for (size_t k = 0; k < m; k++)
			if (r->psd[e][k] > 0) {
				lo = fmin(lo, r->psd[e][k]);
				hi = fmax(hi, r->psd[e][k]);
			}
	if (!(hi > 0))
		lo = 0, hi = 1;
	double bounds[4] = {1 / length, (double)m / length, lo, hi};
	struct plot_writer *w = fmt_plot_open(path, 2);
	struct plot_labels lab;
	fmt_labels_set(&lab, "Edge roughness PSD (1: left edge, 2: right)", "f (1/um)",
		       "PSD (um3)", NULL);
	fmt_plot_labels(w, &lab);
	fmt_plot_begin_set(w, bounds, 2);
	for (int e = 0; e < 2; e++) {
		for (size_t k = 0; k < m; k++) {
			p[2 * k] = (double)(k + 1) / length;
			p[2 * k + 1] = r->psd[e][k];
		}
		fmt_plot_curve(w, (int)m, p);
	}
	fmt_plot_close(w);
	free(p);
}

void roughness_free(struct roughness *r)
{
	for (int e = 0; e < 2; e++) {
		free(r->edge[e]);
		free(r->psd[e]);
		r->edge[e] = r->psd[e] = NULL;
	}
}
