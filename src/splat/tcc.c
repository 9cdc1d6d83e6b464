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
 */
#include "splat.h"
#include "progress.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>

static double complex tcc(const struct pupil *p, const struct source *s,
			  const struct quad *q, double f1x, double f1y,
			  double f2x, double f2y)
{
	if (s->coherent) {
		/* a point source on axis: TCC = P(f') P*(f''); the orders kept
		 * all lie inside the pupil (mask_orders with fmax = NA/lambda) */
		double ph = pupil_phase(p, f1x, f1y) - pupil_phase(p, f2x, f2y);
		return cos(ph) + I * sin(ph);
	}
	double complex t = 0;
	for (int k = 0; k < s->ndisc; k++)
		t += s->sign[k] * source_disc3(p, q, s->cx[k], s->cy[k], s->r[k],
					       f1x, f1y, f2x, f2y);
	return t;
}

int splat_quiet = 1;

/* Below this the source sends no light through the pupil (an annulus or
 * poles entirely outside NA): relative to the area of the pupil. */
static const double NORM_MIN = 1e-12;

struct spectrum *tcc_spectrum(const struct orders *o, const struct pupil *p,
			      const struct source *s, const struct quad *q)
{
	double norm = creal(tcc(p, s, q, 0, 0, 0, 0));
	if (!(norm > NORM_MIN * M_PI * p->cutoff * p->cutoff) && !s->coherent)
		return NULL;
	struct spectrum *sp = xcalloc(1, sizeof *sp);
	sp->lx = o->lx;
	sp->ly = o->ly;
	sp->mmax = o->mmax;
	sp->nmax = o->nmax;
	size_t w = 4 * (size_t)o->mmax + 1, h = 4 * (size_t)o->nmax + 1;
	sp->a = xcalloc(w * h, sizeof *sp->a);
	struct progress prog;
	progress_begin(&prog, "TCC pairs", splat_quiet);
	for (int i = 0; i < o->n; i++) {
		/* pairs (i, j >= i) done so far, of n (n + 1) / 2 */
		progress_step(&prog, (double)i * (2.0 * o->n - i + 1) / 2,
			      (double)o->n * (o->n + 1) / 2);
		if (o->c[i] == 0)
			continue;
		for (int j = i; j < o->n; j++) {
			if (o->c[j] == 0)
				continue;
			double complex t = tcc(p, s, q, o->fx[i], o->fy[i], o->fx[j], o->fy[j]);
			sp->pairs++;
			if (t == 0)
				continue;
			double complex v = t * o->c[i] * conj(o->c[j]) / norm;
			int dm = o->m[i] - o->m[j], dn = o->k[i] - o->k[j];
			sp->a[(size_t)(dn + 2 * o->nmax) * w + (size_t)(dm + 2 * o->mmax)] += v;
			if (j != i)
				sp->a[(size_t)(-dn + 2 * o->nmax) * w +
				      (size_t)(-dm + 2 * o->mmax)] += conj(v);
		}
	}
	return sp;
}

void spectrum_free(struct spectrum *sp)
{
	if (!sp)
		return;
	free(sp->a);
	free(sp);
}

struct spectrum *splat_spectrum(const struct splat_input *in, int nouter, int ninner,
				int *norders)
{
	struct pupil p;
	struct source s;
	struct quad q;
	pupil_init(&p, in);
	source_init(&s, in, p.cutoff);
	if (nouter <= 0 || ninner <= 0)
		quad_default(&p, &nouter, &ninner);
	quad_init(&q, nouter, ninner);
	/* an order reaches the pupil from some source point if |f + s| < NA/lambda */
	struct orders *o = mask_orders(&in->mask, p.cutoff + s.smax);
	if (norders)
		*norders = o->n;
	struct spectrum *sp = tcc_spectrum(o, &p, &s, &q);
	mask_orders_free(o);
	quad_free(&q);
	return sp;
}
