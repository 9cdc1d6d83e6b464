/*
 * tcc.c - the Hopkins sum over pairs of diffraction orders (thesis
 * 2.2.1; H.H. Hopkins 1953):
 *   I(r) = sum_{f', f''} TCC(f', f'') c(f') c*(f'') exp(2 pi i (f' - f'').r),
 *   TCC(f', f'') = integral J(s) P(s + f') P*(s + f'') ds / integral J |P|^2.
 * The pairs are collapsed at once into the image spectrum A(f' - f''), so
 * the image costs one Fourier sum however many pairs there are.  Only
 * pairs with f' <= f'' (in list order) are integrated; the others follow
 * from TCC(f'', f') = TCC(f', f'')*.  The normaliser is the TCC of the
 * zero order with itself, computed by the same call as the pair (0, 0),
 * so that a clear mask images to exactly 1.
 *
 * An image stack (splat(5)'s resist statement) computes every plane in
 * the same pass: each pair's source integral yields the TCC of all the
 * planes at once (source.c), and each plane gets its own spectrum.  The
 * depth phase cancels in TCC(0, 0), so one normaliser serves them all
 * and a clear mask gives exactly 1 at every depth.
 */
#include "splat.h"
#include "par.h"
#include "progress.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>

/* TCC(f', f'') of every plane into t[0 .. p->nplanes - 1]; row is
 * scratch of 2 p->nplanes + 2 q->ninner values. */
static void tcc(const struct pupil *p, const struct source *s,
		const struct quad *q, double f1x, double f1y,
		double f2x, double f2y, double complex *t, double complex *row)
{
	int np = p->nplanes;
	if (s->coherent) {
		/* a point source on axis: TCC = P(f') P*(f''); the orders kept
		 * all lie inside the pupil (mask_orders with fmax = NA/lambda) */
		double ph = pupil_phase(p, f1x, f1y) - pupil_phase(p, f2x, f2y);
		double dp = np > 1 ? pupil_depth(p, f1x, f1y) - pupil_depth(p, f2x, f2y) : 0;
		t[0] = cos(ph) + I * sin(ph);
		for (int k = 1; k < np; k++) {
			double a = ph + k * p->dz * dp;
			t[k] = cos(a) + I * sin(a);
		}
		return;
	}
	for (int k = 0; k < np; k++)
		t[k] = 0;
	for (int k = 0; k < s->ndisc; k++) {
		/* a disc's planes are summed apart, then added with its sign,
		 * in the same order as a single image */
		double complex *d = row;
		for (int l = 0; l < np; l++)
			d[l] = 0;
		source_disc3_planes(p, q, s->cx[k], s->cy[k], s->r[k], f1x, f1y, f2x, f2y, d,
				    row + np);
		for (int l = 0; l < np; l++)
			t[l] += s->sign[k] * d[l];
	}
}

int splat_quiet = 1;

/* The TCCs of the pairs (i, j) for j in a range of one row i of the pair
 * loop, computed by the threads into tb[(j - i) np + k]; the row is then
 * added to the spectra in order of j by one thread, so that every sum is
 * made in the same order whatever the thread count. */
struct row_job {
	const struct orders *o;
	const struct pupil *p;
	const struct source *s;
	const struct quad *q;
	int i;
	double complex *tb;
	double complex **scratch;       /* per worker */
};

static void row_tccs(void *ctx, size_t lo, size_t hi, int worker)
{
	struct row_job *r = ctx;
	const struct orders *o = r->o;
	int np = r->p->nplanes, i = r->i;
	for (size_t jj = lo; jj < hi; jj++) {
		int j = i + (int)jj;
		if (o->c[j] == 0)
			continue;
		tcc(r->p, r->s, r->q, o->fx[i], o->fy[i], o->fx[j], o->fy[j],
		    r->tb + jj * (size_t)np, r->scratch[worker]);
	}
}

/* Below this the source sends no light through the pupil (an annulus or
 * poles entirely outside NA): relative to the area of the pupil. */
static const double NORM_MIN = 1e-12;
/* Most memory for the planes' spectra of an image stack, bytes: a single
 * image's spectrum is far smaller than its grid, but a thousand planes of
 * a large window would not be. */
static const double STACK_SPECTRA_MAX = 2e9;

struct spectrum *tcc_spectrum(const struct orders *o, const struct pupil *p,
			      const struct source *s, const struct quad *q)
{
	int np = p->nplanes;
	double complex *t = xreallocarray(NULL, 3 * (size_t)np + 2 * (size_t)q->ninner, sizeof *t);
	double complex *row = t + np;
	/* TCC(0, 0) has no phase: the same normaliser for every plane */
	tcc(p, s, q, 0, 0, 0, 0, t, row);
	double norm = creal(t[0]);
	if (!(norm > NORM_MIN * M_PI * p->cutoff * p->cutoff) && !s->coherent) {
		free(t);
		return NULL;
	}
	size_t w = 4 * (size_t)o->mmax + 1, h = 4 * (size_t)o->nmax + 1;
	double bytes = (double)w * h * np * sizeof(double complex);
	if (np > 1 && bytes > STACK_SPECTRA_MAX) {
		free(t);
		die("the spectra of %d planes need %.3g GB, more than %g: use fewer planes "
		    "in the resist statement, or a smaller window", np, bytes / 1e9,
		    STACK_SPECTRA_MAX / 1e9);
	}
	struct spectrum *sp = spectrum_new(o, np);
	int nt = par_threads();
	double complex **scratch = xreallocarray(NULL, (size_t)nt, sizeof *scratch);
	for (int k = 0; k < nt; k++)
		scratch[k] = xreallocarray(NULL, 2 * (size_t)np + 2 * (size_t)q->ninner,
					   sizeof **scratch);
	double complex *tb = xreallocarray(NULL, (size_t)o->n * np, sizeof *tb);
	struct row_job rj = {o, p, s, q, 0, tb, scratch};
	struct progress prog;
	progress_begin(&prog, "TCC pairs", splat_quiet);
	for (int i = 0; i < o->n; i++) {
		/* pairs (i, j >= i) done so far, of n (n + 1) / 2 */
		progress_step(&prog, (double)i * (2.0 * o->n - i + 1) / 2,
			      (double)o->n * (o->n + 1) / 2);
		if (o->c[i] == 0)
			continue;
		rj.i = i;
		par_for((size_t)(o->n - i), 64, row_tccs, &rj);
		for (int j = i; j < o->n; j++) {
			if (o->c[j] == 0)
				continue;
			const double complex *tt = tb + (size_t)(j - i) * np;
			for (int k = 0; k < np; k++)
				t[k] = tt[k];
			sp->pairs++;
			int dm = o->m[i] - o->m[j], dn = o->k[i] - o->k[j];
			size_t at = (size_t)(dn + 2 * o->nmax) * w + (size_t)(dm + 2 * o->mmax);
			size_t mirror = (size_t)(-dn + 2 * o->nmax) * w + (size_t)(-dm + 2 * o->mmax);
			for (int k = 0; k < np; k++) {
				if (t[k] == 0)
					continue;
				double complex v = t[k] * o->c[i] * conj(o->c[j]) / norm;
				double complex *a = sp->a + (size_t)k * w * h;
				a[at] += v;
				if (j != i)
					a[mirror] += conj(v);
			}
		}
	}
	for (int k = 0; k < nt; k++)
		free(scratch[k]);
	free(scratch);
	free(tb);
	free(t);
	return sp;
}
