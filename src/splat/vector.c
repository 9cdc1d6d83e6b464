/*
 * vector.c - vector imaging (splat(5)'s imaging vector): the Abbe sum of
 * abbe.c with the field a vector, polarised at the mask, split into s and
 * p in the pupil and carried through the film stack by filmstack.c, so
 * that immersion lenses at high NA and the reflections of the stack are
 * in the image.  The conventions, which splat(5) states and the tests
 * check:
 *
 * 1. Abbe: for each source point s and mask order f the plane wave at
 *    pupil position g = s + f passes when |g| <= NA/lambda;
 *    sin(theta_imm) = lambda |g| / N_imm.
 * 2. Jones vectors at the mask: x = (1, 0), y = (0, 1), te = (-s_y, s_x)
 *    / |s|, tm = (s_x, s_y) / |s|, unpolarized = the intensities of x and
 *    y averaged (te and tm at s = 0 too).  Per plane wave u = g / |g| (x
 *    at g = 0), s_hat = (-u_y, u_x), a_s = e.s_hat, a_p = e.u; the lens
 *    keeps a_s and a_p.
 * 3. The radiometric amplitude factor sqrt(cos theta_obj / cos theta_imm),
 *    sin theta_obj = lambda |g| / R; exactly 1 for reduction inf.
 * 4. Defocus d in the immersion medium: the phase 2 pi (d / lambda)
 *    (sqrt(N_imm^2 - lambda^2 |g|^2) - N_imm) (pupil.c).
 * 5. Each plane wave crosses the stack at its own angle, s and p apart
 *    (filmstack.c); the field in the resist has the down- and up-going
 *    waves and, for p, the z component.  filmstack.c's time convention
 *    is exp(+i w t), splat's phases the opposite (a deeper plane gains
 *    +k_z z, pupil.c), so the film's response is conjugated before it
 *    multiplies the pupil: with N_imm = n_resist and no reflections this
 *    is the scalar stack's propagation (pupil_depth).
 * 6. I = (Re n_resist / N_imm) |E|^2 / |E_inc|^2, |E|^2 over x, y and z,
 *    E_inc the amplitude a clear mask gives at normal incidence (1 here),
 *    so a clear mask at normal incidence gives bleach's 1D thin-film
 *    intensity.  Without a film (no splat -bf) the resist is taken as
 *    lossless and without reflections: the plane waves keep their s and
 *    p amplitudes and only bend into it (Snell), and the clear field is
 *    1 as in the scalar stack: bleach applies its own thin-film factor.
 *
 * The source sum is abbe.c's: cells of side h, an order whose pupil edge
 * crosses a cell weighted by the part a inside it, the self terms' loss
 * |V|^2 (a - a^2) summed apart into the zero frequency.  Per source
 * point and plane each field is one inverse FFT: three for a single
 * polarisation, five unpolarised (vamp), against abbe.c's one, on a grid
 * that spans one source point's orders (vgrid); a source point with few
 * orders adds their pairs to the spectrum directly instead (vpairs).
 * Threads share the columns and rows of the transforms; every grid value
 * is summed in the same order whatever their count, and the direct pairs
 * on one thread in source-point order.
 */
#include "checked.h"
#include "fft.h"
#include "fmt_bleach.h"
#include "par.h"
#include "progress.h"
#include "splat.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Input files written with a few decimals must still agree. */
static const double VECTOR_MATCH = 1e-9;
/* The direct pair sum is used for a source point whose orders' count
 * squared is below this times the transforms' butterflies (measured on
 * the cases of tests/bench/vector.sh); the tests set it to 0 and to
 * infinity to compare the two paths. */
double vector_pair_fft = 0.5;
/* Planes a standing-wave period below which splat -bf warns: linear
 * interpolation of a sine sampled 4 times a period errs by up to 30 %
 * of its swing, 8 times by 8 %. */
static const double VECTOR_PLANES_PER_PERIOD = 4;

void vector_film_read(struct vfilm *vf, struct splat_input *in, const char *input,
		      const char *bf)
{
	memset(vf, 0, sizeof *vf);
	if (!in->vector || !bf)
		return;
	if (!in->planes)
		die("%s: -bf with imaging vector writes the image inside the film: give the "
		    "resist statement (resist thickness T index n planes N) for its planes", input);
	struct bleach_input b;
	fmt_bleach_read(bf, &b);
	if (fabs(b.wavelength - in->wavelength) > VECTOR_MATCH * in->wavelength)
		die("%s: wavelength %g um, but %s has wavelength %g um", bf, b.wavelength, input,
		    in->wavelength);
	if (fabs(b.ambient - in->immersion) > VECTOR_MATCH * in->immersion)
		die("%s: ambient %g must equal the immersion index %g of %s (the medium "
		    "between the lens and the resist)", bf, b.ambient, in->immersion, input);
	if (fabs(b.thick - in->resist_thick) > VECTOR_MATCH * b.thick ||
	    fabs(b.index - in->resist_index) > VECTOR_MATCH * b.index)
		warn("%s:%ld: the resist statement's thickness %g um and index %g differ from "
		     "%s's %g um and %g: taking %s's", input, in->resist_line, in->resist_thick,
		     in->resist_index, bf, b.thick, b.index, bf);
	in->resist_thick = b.thick;
	in->resist_index = b.index;
	/* the stack holds the standing waves (period lambda / 2n): bleach
	 * interpolates between the planes, so they should sample it */
	double dz = b.thick / (in->planes - 1), period = b.wavelength / (2 * b.index);
	if (dz > period / VECTOR_PLANES_PER_PERIOD)
		warn("%s:%ld: resist: planes %g um apart, more than 1/%g of the standing-wave "
		     "period %g um that the stack through %s holds: use %d planes or more",
		     input, in->resist_line, dz, VECTOR_PLANES_PER_PERIOD, period, bf,
		     (int)ceil(b.thick / period * VECTOR_PLANES_PER_PERIOD) + 1);
	vf->have = 1;
	vf->layers = xreallocarray(NULL, (size_t)(b.nlayers ? b.nlayers : 1),
				   sizeof *vf->layers);
	fmt_bleach_film(&b, &vf->fs, vf->layers);
}

void vector_film_free(struct vfilm *vf)
{
	free(vf->layers);
	vf->layers = NULL;
}

/* The input polarisations of source point (sx, sy): Jones vectors and
 * the weights of their intensities; returns their count. */
static int jones(enum splat_pol pol, double sx, double sy, double cutoff, double ex[2],
		 double ey[2], double wt[2])
{
	double r = hypot(sx, sy);
	if ((pol == SPLAT_POL_TE || pol == SPLAT_POL_TM) && !(r > 1e-12 * cutoff))
		pol = SPLAT_POL_UNPOLARIZED;
	switch (pol) {
	case SPLAT_POL_X: ex[0] = 1; ey[0] = 0; break;
	case SPLAT_POL_Y: ex[0] = 0; ey[0] = 1; break;
	case SPLAT_POL_TE: ex[0] = -sy / r; ey[0] = sx / r; break;
	case SPLAT_POL_TM: ex[0] = sx / r; ey[0] = sy / r; break;
	case SPLAT_POL_UNPOLARIZED:
		ex[0] = 1; ey[0] = 0;
		ex[1] = 0; ey[1] = 1;
		wt[0] = wt[1] = 0.5;
		return 2;
	}
	wt[0] = 1;
	return 1;
}

/* What the sum needs about the optics beyond the pupil. */
struct vctx {
	const struct pupil *p;
	const struct splat_input *in;
	const struct vfilm *vf;
	int np;
	double *depth;          /* np plane depths, um */
	double nr;              /* the resist's (real) index without a film */
	double complex *ts, *tp, *zp;   /* scratch, np each */
};

/* The conjugated response of the plane wave of invariant beta = lambda
 * |g|, per unit s and p amplitude in the immersion medium, at every
 * plane l: r[3 l] along s_hat (s), r[3 l + 1] along u and r[3 l + 2]
 * along z, down (p). */
static void respond(struct vctx *c, double beta, double complex *r)
{
	int np = c->np;
	if (c->vf && c->vf->have) {
		filmstack_field(&c->vf->fs, FILM_S, beta, np, c->depth, c->ts, NULL);
		filmstack_field(&c->vf->fs, FILM_P, beta, np, c->depth, c->tp, c->zp);
		for (int l = 0; l < np; l++) {
			r[3 * l] = conj(c->ts[l]);
			r[3 * l + 1] = conj(c->tp[l]);
			r[3 * l + 2] = conj(c->zp[l]);
		}
		return;
	}
	/* no film: the down-going wave alone, bent into the resist, its
	 * phase taken relative to the axial wave as pupil_depth's is */
	double n = c->nr;
	double complex q = csqrt(n * n - beta * beta);
	if (cimag(q) < 0)
		q = conj(q);    /* conjugated convention: decays as exp(-|q| k0 z) */
	double k0 = 2 * M_PI / c->p->lambda;
	for (int l = 0; l < np; l++) {
		double complex e = cexp(I * k0 * (q - n) * c->depth[l]);
		r[3 * l] = e;
		r[3 * l + 1] = q / n * e;
		r[3 * l + 2] = -beta / n * e;
	}
}

/* The radiometric amplitude factor sqrt(cos theta_obj / cos theta_imm). */
static double radiometric(const struct splat_input *in, double beta)
{
	if (isinf(in->reduction))
		return 1;
	double so = beta / in->reduction, si = beta / in->immersion;
	return sqrt(sqrt(1 - so * so) / sqrt(1 - si * si));
}

/* The FFT grid of the fields.  One source point's orders lie within
 * R + reach of -s in the pupil (R = NA / lambda, reach the cell's half
 * diagonal), so counted from the order nearest to -s they span |m| <= mx
 * = floor((R + reach) Lx + 1/2), and their intensity |dm| <= 2 mx: a grid
 * of 4 mx + 1 holds it unaliased (a plane wave common to all orders does
 * not change |E|^2), where the orders of every source point together
 * need 4 M + 1, M = (R + s_max) Lx: for sigma 0.5 two thirds of the side.
 * Where mx would not be below M the orders stay where they are. */
struct vgrid {
	int mx, ny;
	size_t kx, ky;
};

static void vgrid_init(struct vgrid *vg, const struct orders *o, double R, double reach)
{
	/* the 1e-9 keeps a bound that is an integer in exact arithmetic */
	double bx = floor((R + reach) * o->lx + 0.5 + 1e-9), by = floor((R + reach) * o->ly + 0.5 + 1e-9);
	vg->mx = bx < o->mmax ? (int)bx : o->mmax;
	vg->ny = by < o->nmax ? (int)by : o->nmax;
	vg->kx = nice_length(4 * (size_t)vg->mx + 1);
	vg->ky = nice_length(4 * (size_t)vg->ny + 1);
}

struct vjob {
	size_t kx, ky;
	const struct fft_plan *px, *py;
	int nf;                 /* fields (grids) */
	double complex *e;      /* nf grids, ky rows of kx */
	double *wf;             /* weight of each field's |E|^2 */
	double *acc;            /* the plane's sum, ky rows of kx */
	double complex **work;  /* per worker */
	size_t *cols;
};

static void vcolumns(void *ctx, size_t lo, size_t hi, int worker)
{
	struct vjob *jb = ctx;
	double complex *col = jb->work[worker], *sub = col + jb->ky;
	size_t grid = jb->kx * jb->ky;
	for (int f = 0; f < jb->nf; f++) {
		double complex *e = jb->e + (size_t)f * grid;
		for (size_t c = lo; c < hi; c++) {
			size_t i = jb->cols[c];
			for (size_t j = 0; j < jb->ky; j++)
				col[j] = e[j * jb->kx + i];
			fft_exec(jb->py, col, sub);
			for (size_t j = 0; j < jb->ky; j++)
				e[j * jb->kx + i] = col[j];
		}
	}
}

static void vrows(void *ctx, size_t lo, size_t hi, int worker)
{
	struct vjob *jb = ctx;
	double complex *sub = jb->work[worker];
	size_t grid = jb->kx * jb->ky;
	for (size_t j = lo; j < hi; j++) {
		double *a = jb->acc + j * jb->kx;
		for (int f = 0; f < jb->nf; f++) {
			double complex *r = jb->e + (size_t)f * grid + j * jb->kx;
			double w = jb->wf[f];
			fft_exec(jb->px, r, sub);
			for (size_t i = 0; i < jb->kx; i++)
				a[i] += w * (creal(r[i]) * creal(r[i]) + cimag(r[i]) * cimag(r[i]));
		}
	}
}

/* One source point's orders: the amplitude that multiplies each
 * component's film response, per order and input polarisation. */
struct vorder {
	size_t cell;            /* grid index */
	double complex base;    /* c cov rad P */
	double as[2], ap[2];    /* a_s, a_p per input polarisation */
	double sx, sy, ux, uy;  /* s_hat and u */
	double c2cov;           /* |c|^2 (cov - cov^2) rad^2: the self term's loss */
	int m, n;               /* the order's indices */
};

/* The fields' amplitudes of one plane, amp[q nf + f] for order q and
 * field f: for a single input polarisation e its x, y and z components
 * (nf = 3, weights 1); unpolarised (npol 2, x and y
 * averaged) the same in 5 grids instead of 6: with alpha = (r_s + r_pt)
 * / 2, beta = (r_pt - r_s) / 2 and 2 phi the angle of u doubled, the x-y
 * part of the order's 3 x 2 Jones-to-field matrix is alpha 1 + beta
 * [cos 2phi, sin 2phi; sin 2phi, -cos 2phi], whose Frobenius norm summed
 * over the orders is 2 (|A|^2 + |B_c|^2 + |B_s|^2), A = sum c alpha,
 * B_c = sum c beta cos 2phi, B_s = sum c beta sin 2phi; the z row adds
 * |sum c r_pz u_x|^2 + |sum c r_pz u_y|^2.  Halved for the average: A,
 * B_c, B_s weigh 1 and the z fields 1/2 (vfield_weights).  The self
 * terms' loss goes to *diag. */
static int vamp(const struct vorder *vo, int no, const double complex *r, int np, int l,
		int npol, const double *wt, double w, double complex *amp, double *diag)
{
	int nf = npol == 2 ? 5 : 3;
	for (int q = 0; q < no; q++) {
		const struct vorder *o = &vo[q];
		const double complex *rq = r + ((size_t)q * np + l) * 3;
		double complex rs = rq[0], rpt = rq[1], rpz = rq[2];
		double complex *g = amp + (size_t)q * nf;
		double d = 0;
		if (npol == 2) {
			double c2 = o->ux * o->ux - o->uy * o->uy, s2 = 2 * o->ux * o->uy;
			double complex al = o->base * (rs + rpt) / 2, be = o->base * (rpt - rs) / 2;
			double complex z = o->base * rpz;
			g[0] = al;
			g[1] = be * c2;
			g[2] = be * s2;
			g[3] = z * o->ux;
			g[4] = z * o->uy;
		}
		for (int j = 0; j < npol; j++) {
			double complex s = o->as[j] * rs, p = o->ap[j] * rpt, z = o->ap[j] * rpz;
			if (npol == 1) {
				g[0] = o->base * (s * o->sx + p * o->ux);
				g[1] = o->base * (s * o->sy + p * o->uy);
				g[2] = o->base * z;
			}
			d += wt[j] * (creal(s * conj(s)) + creal(p * conj(p)) + creal(z * conj(z)));
		}
		*diag += w * o->c2cov * d;
	}
	return nf;
}

/* The amplitudes onto the nf grids of the FFT path. */
static void vscatter(const struct vorder *vo, int no, int nf, const double complex *amp,
		     double complex *e, size_t grid)
{
	memset(e, 0, (size_t)nf * grid * sizeof *e);
	for (int q = 0; q < no; q++)
		for (int f = 0; f < nf; f++)
			e[(size_t)f * grid + vo[q].cell] = amp[(size_t)q * nf + f];
}

/* The direct path, for a source point with few orders: its intensity's
 * spectrum sum_f w_f sum_{q, q'} a_qf a*_q'f at dm = m - m', dn = n - n'
 * added to the plane's sacc ((4 ny + 1) rows of 4 mx + 1). */
static void vpairs(const struct vorder *vo, int no, int nf, const double complex *amp,
		   const double *wf, double complex *sacc, int mx, int ny)
{
	size_t wd = 4 * (size_t)mx + 1;
	size_t mid = (size_t)(2 * ny) * wd + (size_t)(2 * mx);
	for (int q = 0; q < no; q++) {
		const double complex *a = amp + (size_t)q * nf;
		double d = 0;
		for (int f = 0; f < nf; f++)
			d += wf[f] * (creal(a[f]) * creal(a[f]) + cimag(a[f]) * cimag(a[f]));
		sacc[mid] += d;
		/* the pair (p, q) is the conjugate of (q, p), at -dm, -dn */
		for (int p = 0; p < q; p++) {
			const double complex *b = amp + (size_t)p * nf;
			double complex t = 0;
			for (int f = 0; f < nf; f++)
				t += wf[f] * a[f] * conj(b[f]);
			long k = (long)(vo[q].n - vo[p].n) * (long)wd + (vo[q].m - vo[p].m);
			sacc[(size_t)((long)mid + k)] += t;
			sacc[(size_t)((long)mid - k)] += conj(t);
		}
	}
}

/* The weights of vamp's fields' |E|^2 for a source point of weight w. */
static int vfield_weights(int npol, double w, double *wf)
{
	if (npol == 2) {
		wf[0] = wf[1] = wf[2] = w;
		wf[3] = wf[4] = w / 2;
		return 5;
	}
	wf[0] = wf[1] = wf[2] = w;
	return 3;
}

/* The orders of source point (sx, sy) that pass the pupil, with their
 * responses at every plane; returns their count. */
static int vorders(struct vctx *c, const struct orders *o, double sx, double sy, double h,
		   double rin2, double rout2, int coherent, int npol, const double *ex,
		   const double *ey, const struct vgrid *vg, struct vorder *vo, double complex *r)
{
	size_t kx = vg->kx, ky = vg->ky;
	/* the grid's origin: the order nearest to -s (vgrid) */
	long m0 = vg->mx < o->mmax ? lround(-sx * o->lx) : 0;
	long n0 = vg->ny < o->nmax ? lround(-sy * o->ly) : 0;
	const struct pupil *p = c->p;
	int np = c->np, no = 0;
	for (int q = 0; q < o->n; q++) {
		if (o->c[q] == 0)
			continue;
		double gx = sx + o->fx[q], gy = sy + o->fy[q];
		double cov = pupil_cover(gx, gy, p->cutoff, rin2, rout2, h, coherent);
		if (cov == 0)
			continue;
		struct vorder *v = &vo[no];
		double g = sqrt(gx * gx + gy * gy), beta = p->lambda * g;
		v->ux = g > 0 ? gx / g : 1;
		v->uy = g > 0 ? gy / g : 0;
		v->sx = -v->uy;
		v->sy = v->ux;
		for (int j = 0; j < npol; j++) {
			v->as[j] = ex[j] * v->sx + ey[j] * v->sy;
			v->ap[j] = ex[j] * v->ux + ey[j] * v->uy;
		}
		double rad = radiometric(c->in, beta);
		double ph = pupil_phase(p, gx, gy);
		v->base = o->c[q] * cov * rad;
		if (ph != 0)
			v->base *= cos(ph) + I * sin(ph);
		double c2 = creal(o->c[q]) * creal(o->c[q]) + cimag(o->c[q]) * cimag(o->c[q]);
		v->c2cov = c2 * (cov - cov * cov) * rad * rad;
		long mm = o->m[q] - m0, nn = o->k[q] - n0;
		if (labs(mm) > vg->mx || labs(nn) > vg->ny)
			die("vector.c: order (%d, %d) beyond the grid of source point (%g, %g)",
			    o->m[q], o->k[q], sx, sy);
		size_t i = (size_t)(mm < 0 ? mm + (long)kx : mm);
		size_t j = (size_t)(nn < 0 ? nn + (long)ky : nn);
		v->cell = j * kx + i;
		v->m = o->m[q];
		v->n = o->k[q];
		respond(c, beta, r + (size_t)no * np * 3);
		no++;
	}
	return no;
}

/* The image spectrum of every plane from the sums acc (np grids) and the
 * self terms' loss diag, scaled by factor / norm (abbe.c's assembly). */
static struct spectrum *vassemble(const struct orders *o, int np, const struct vgrid *vg,
				  double *acc, const double complex *sacc, const double *diag,
				  double factor, double norm, double complex *e,
				  double complex *work)
{
	size_t swd = 4 * (size_t)vg->mx + 1, sgrid = swd * (4 * (size_t)vg->ny + 1);
	size_t kx = vg->kx, ky = vg->ky, grid = kx * ky;
	size_t wd = 4 * (size_t)o->mmax + 1, ht = 4 * (size_t)o->nmax + 1;
	struct fft_plan *fx = fft_plan_new(kx, -1), *fy = fft_plan_new(ky, -1);
	struct spectrum *sp = spectrum_new(o, np);
	for (int l = 0; l < np; l++) {
		const double *a = acc + (size_t)l * grid;
		for (size_t i = 0; i < grid; i++)
			e[i] = a[i];
		fft_exec2(fx, fy, e, work);
		e[0] += diag[l] * (double)grid;
		double complex *out = sp->a + (size_t)l * wd * ht;
		double scale = factor / ((double)grid * norm);
		for (long dn = -2 * (long)vg->ny; dn <= 2 * (long)vg->ny; dn++) {
			size_t j = (size_t)(dn < 0 ? dn + (long)ky : dn);
			for (long dm = -2 * (long)vg->mx; dm <= 2 * (long)vg->mx; dm++) {
				size_t i = (size_t)(dm < 0 ? dm + (long)kx : dm);
				/* the transforms' sum and the direct pairs' */
				double complex d = sacc[(size_t)l * sgrid +
							(size_t)(dn + 2 * vg->ny) * swd +
							(size_t)(dm + 2 * vg->mx)];
				out[(size_t)(dn + 2 * o->nmax) * wd + (size_t)(dm + 2 * o->mmax)] =
					(e[j * kx + i] + d * (double)grid) * scale;
			}
		}
	}
	fft_plan_free(fx);
	fft_plan_free(fy);
	return sp;
}

/* The largest FFT work any worker needs, columns and the final 2D. */
static size_t vwork_size(size_t kx, size_t ky, const struct fft_plan *px,
			 const struct fft_plan *py)
{
	struct fft_plan *fx = fft_plan_new(kx, -1), *fy = fft_plan_new(ky, -1);
	size_t nw = ky + (fft_work_size(px) > fft_work_size(py) ? fft_work_size(px)
							       : fft_work_size(py));
	size_t nw2 = fft_work2_size(fx, fy);
	fft_plan_free(fx);
	fft_plan_free(fy);
	return nw2 > nw ? nw2 : nw;
}

struct spectrum *vector_spectrum(const struct orders *o, const struct pupil *p,
				 const struct source *s, double h, const struct splat_input *in,
				 const struct vfilm *vf)
{
	int np = p->nplanes;
	int nn = abbe_nodes(s, h, NULL, NULL, NULL);
	double *sx = xreallocarray(NULL, (size_t)nn, 3 * sizeof *sx), *sy = sx + nn, *sw = sy + nn;
	abbe_nodes(s, h, sx, sy, sw);
	double R = p->cutoff;
	double reach = s->coherent ? 0 : 0.7072 * h;
	double rin2 = R > reach ? (R - reach) * (R - reach) : 0, rout2 = (R + reach) * (R + reach);
	double norm = 0;
	for (int k = 0; k < nn; k++)
		norm += sw[k] * pupil_cover(sx[k], sy[k], R, rin2, rout2, h, s->coherent);
	if (!(norm > 1e-12 * M_PI * R * R) && !s->coherent) {
		free(sx);
		return NULL;
	}
	struct vctx c = {p, in, vf, np, NULL, in->planes ? in->resist_index : in->immersion,
			 NULL, NULL, NULL};
	c.depth = xreallocarray(NULL, (size_t)np, sizeof *c.depth);
	c.ts = xreallocarray(NULL, (size_t)np, 3 * sizeof *c.ts);
	c.tp = c.ts + np;
	c.zp = c.tp + np;
	for (int l = 0; l < np; l++)
		c.depth[l] = l == np - 1 && np > 1 ? in->resist_thick
			   : np > 1 ? l * in->resist_thick / (np - 1) : 0;
	struct vgrid vg;
	vgrid_init(&vg, o, R, reach);
	size_t kx = vg.kx, ky = vg.ky;
	size_t grid = ck_mul(kx, ky, "vector FFT grid");
	struct fft_plan *px = fft_plan_new(kx, 1), *py = fft_plan_new(ky, 1);
	double complex *e = xreallocarray(NULL, ck_mul(grid, 5, "vector FFT grids"), sizeof *e);
	double *acc = xcalloc(ck_mul(grid, (size_t)np, "vector FFT grid planes"), sizeof *acc);
	double *diag = xcalloc((size_t)np, sizeof *diag);
	int nt = par_threads();
	size_t nw = vwork_size(kx, ky, px, py);
	double complex **work = xreallocarray(NULL, (size_t)nt, sizeof *work);
	for (int t = 0; t < nt; t++)
		work[t] = xreallocarray(NULL, nw, sizeof **work);
	size_t *cols = xreallocarray(NULL, 2 * (size_t)vg.mx + 1, sizeof *cols);
	size_t ncols = 0;
	for (int m = -vg.mx; m <= vg.mx; m++)
		cols[ncols++] = (size_t)(m < 0 ? m + (long)kx : m);
	struct vorder *vo = xreallocarray(NULL, (size_t)(o->n ? o->n : 1), sizeof *vo);
	double complex *r = xreallocarray(NULL, ck_mul((size_t)(o->n ? o->n : 1),
						       3 * (size_t)np, "vector responses"),
					  sizeof *r);
	double complex *amp = xreallocarray(NULL, ck_mul((size_t)(o->n ? o->n : 1), 5,
							 "vector amplitudes"), sizeof *amp);
	size_t sgrid = (4 * (size_t)vg.mx + 1) * (4 * (size_t)vg.ny + 1);
	double complex *sacc = xcalloc(ck_mul(sgrid, (size_t)np, "vector spectra"), sizeof *sacc);
	/* the transforms' work a field, in pair products (about equal costs
	 * a butterfly and a product, measured: tests/bench/vector.sh) */
	double fft_cost = vector_pair_fft * ((double)ncols * ky * log2((double)ky) +
					     (double)ky * kx * (log2((double)kx) + 1));
	double wf[5];
	struct vjob jb = {kx, ky, px, py, 0, e, wf, acc, work, cols};

	struct progress prog;
	progress_begin(&prog, "source points", splat_quiet);
	for (int k = 0; k < nn; k++) {
		progress_step(&prog, k, nn);
		double ex[2], ey[2], wt[2];
		int npol = jones(in->polarization, sx[k], sy[k], R, ex, ey, wt);
		int no = vorders(&c, o, sx[k], sy[k], h, rin2, rout2, s->coherent, npol, ex, ey,
				 &vg, vo, r);
		if (!no)
			continue;
		jb.nf = vfield_weights(npol, sw[k], wf);
		/* few orders: their pairs directly, cheaper than the transforms */
		int direct = (double)no * no < fft_cost;
		for (int l = 0; l < np; l++) {
			vamp(vo, no, r, np, l, npol, wt, sw[k], amp, &diag[l]);
			if (direct) {
				vpairs(vo, no, jb.nf, amp, wf, sacc + (size_t)l * sgrid, vg.mx, vg.ny);
				continue;
			}
			vscatter(vo, no, jb.nf, amp, e, grid);
			jb.acc = acc + (size_t)l * grid;
			par_for(ncols, 8, vcolumns, &jb);
			par_for(ky, 8, vrows, &jb);
		}
	}
	/* Re n_resist / N_imm: the intensity in the resist of a unit field */
	double factor = vf && vf->have ? vf->fs.nr / in->immersion : 1;
	struct spectrum *sp = vassemble(o, np, &vg, acc, sacc, diag, factor, norm, e, work[0]);
	sp->pairs = nn;
	for (int t = 0; t < nt; t++)
		free(work[t]);
	free(work);
	free(cols);
	free(vo);
	free(r);
	free(amp);
	free(sacc);
	free(e);
	free(acc);
	free(diag);
	free(c.depth);
	free(c.ts);
	free(sx);
	fft_plan_free(px);
	fft_plan_free(py);
	return sp;
}

struct spectrum *splat_spectrum_vector(const struct splat_input *in, const struct vfilm *vf,
				       int ncells, int *norders)
{
	struct pupil p;
	struct source s;
	pupil_init(&p, in);
	source_init(&s, in, p.cutoff);
	struct orders *o = mask_orders(&in->mask, p.cutoff + s.smax);
	if (norders)
		*norders = o->n;
	double h = abbe_cell_default(&p, &s);
	if (ncells > 0 && !s.coherent)
		h *= (double)ABBE_CELLS / ncells;
	struct spectrum *sp = vector_spectrum(o, &p, &s, h, in, vf);
	mask_orders_free(o);
	return sp;
}

void splat_estimate_vector(const struct splat_input *in, double *nodes, double *seconds,
			   double *bytes)
{
	splat_estimate_abbe(in, nodes, seconds, bytes);
	/* three fields for one polarisation, five unpolarised, each an FFT
	 * where abbe.c has one */
	double nf = in->polarization == SPLAT_POL_UNPOLARIZED ? 5 : 3;
	*seconds *= nf;
	*bytes *= 2;
}
