/*
 * abbe.c - the image by Abbe's method: a sum over source points of
 * coherent images, whose cost grows as the window's area
 * times its logarithm where the Hopkins pair sum (tcc.c) grows as the
 * area squared.
 *
 * For a source point s of weight w_s (the source integral's quadrature)
 * the field of the periodic mask is
 *   E_s(r) = sum_f c(f) P(s + f) exp(2 pi i f.r),
 * (the factor exp(2 pi i s.r) cancels in |E|^2), and
 *   I(r) = sum_s w_s |E_s(r)|^2 / sum_s w_s |P(s)|^2,
 * the denominator being the clear mask's image, so that a clear mask
 * images to exactly 1 as in tcc.c.  P is pupil.c's, zero outside
 * |g| < NA/lambda; plane k of an image stack multiplies it by
 * exp(i k dz pupil_depth(g)).  Expanding |E_s|^2 gives back Hopkins'
 * sum with TCC(f', f'') = sum_s w_s P(s + f') P*(s + f''): the two
 * methods differ only in how the source integral is done: exactly over
 * the region where both orders pass, in source.c, with nodes that depend
 * on the pair; by fixed source points here (below), since an FFT needs
 * the same source point for every order.
 *
 * On an FFT grid of Kx x Ky points over one period, Kx >= 4M + 1 and
 * Ky >= 4N + 1 (|m| <= M, |n| <= N the orders), each E_s is one inverse
 * 2D transform (only the 2M + 1 columns that hold orders need the column
 * pass) and |E_s|^2 is sampled without aliasing, so one forward transform
 * of the sum gives the image spectrum A(dm, dn), |dm| <= 2M, |dn| <= 2N,
 * exactly as tcc.c would hold it: image.c, the cutlines and the stacks
 * take it unchanged.
 *
 * The source points: the centres of square cells of side h tiling the
 * source (abbe_cell_default: 40 across the smallest source disc or the
 * pupil radius), each weighted by its area times the part of it inside
 * the source (the signed discs of source.c; an edge taken as straight
 * across a cell, abbe_cover).  A plain rule would see every pupil edge
 * |s + f| = NA/lambda as a step and converge as h; instead an order whose
 * edge crosses the cell enters E_s with amplitude a, the part of the cell
 * inside its pupil.  The cross terms c' c''* a' a'' are then right to
 * second order, and the self term |c|^2 a^2 misses |c|^2 (a - a^2), which
 * has no dependence on r: it is summed apart (diag) and added to A(0, 0).
 * A clear mask still gives exactly 1 (norm is the zero order's sum of
 * w a), and the image converges as h^2: about 2e-4 of the clear field
 * at 40 cells (tests/splat/abbe.c).  The pupil phase is taken at the
 * cell centre.
 *
 * Threads: within each source point, the column transforms, then the row
 * transforms with the accumulation of w_s |E_s|^2, are split among
 * threads by columns and rows; every grid value is summed over the
 * source points in the same order whatever the thread count, so the
 * result is byte-identical for any count.
 */
#include "checked.h"
#include "fft.h"
#include "par.h"
#include "progress.h"
#include "splat.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The smallest length >= n whose prime factors are 2, 3 and 5. */
static size_t nice_length(size_t n)
{
	for (size_t k = n < 1 ? 1 : n;; k++) {
		size_t m = k;
		while (m % 2 == 0) m /= 2;
		while (m % 3 == 0) m /= 3;
		while (m % 5 == 0) m /= 5;
		if (m == 1)
			return k;
	}
}

/* The fraction of a square of side h whose centre lies at signed distance
 * d inside a straight edge of unit normal (ux, uy): the projection of the
 * square on the normal is the sum of two uniform variables, half-widths
 * a >= b, whose distribution is a trapezoid. */
double abbe_cover(double d, double ux, double uy, double h)
{
	double a = 0.5 * h * fabs(ux), b = 0.5 * h * fabs(uy);
	if (b > a) {
		double t = a;
		a = b;
		b = t;
	}
	if (d <= -(a + b))
		return 0;
	if (d >= a + b)
		return 1;
	if (d < -(a - b))
		return (d + a + b) * (d + a + b) / (8 * a * b);
	if (d > a - b)
		return 1 - (a + b - d) * (a + b - d) / (8 * a * b);
	return (d + a) / (2 * a);
}

/* The part of the square cell (x, y, side h) inside the disc (cx, cy, r),
 * the disc's edge taken as straight across the cell (its curvature moves
 * the area by about h^3 / r). */
static double disc_cover(double x, double y, double h, double cx, double cy, double r)
{
	double dx = x - cx, dy = y - cy, rho = hypot(dx, dy);
	double reach = 0.7072 * h;
	if (rho <= r - reach)
		return 1;
	if (rho >= r + reach)
		return 0;
	if (rho == 0)
		return 1;
	return abbe_cover(r - rho, dx / rho, dy / rho, h);
}

double abbe_cell_default(const struct pupil *p, const struct source *s)
{
	/* the phase across a cell must stay small where the pupil turns */
	double cells = ABBE_CELLS + 4 * ceil(2 * M_PI * p->waves);
	if (cells > 4 * ABBE_CELLS)
		cells = 4 * ABBE_CELLS;
	/* across the smallest source disc, and no coarser than that across
	 * the pupil's radius (the pupil edges set the error where the source
	 * is large: sigma 0.5 is both) */
	double dmin = p->cutoff;
	for (int k = 0; k < s->ndisc; k++)
		if (2 * s->r[k] < dmin)
			dmin = 2 * s->r[k];
	return s->coherent ? 1 : dmin / cells;
}

int abbe_nodes(const struct source *s, double h, double *sx, double *sy, double *w)
{
	if (s->coherent) {
		if (sx) {
			sx[0] = sy[0] = 0;
			w[0] = 1;
		}
		return 1;
	}
	double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
	for (int k = 0; k < s->ndisc; k++) {
		xmin = fmin(xmin, s->cx[k] - s->r[k]);
		xmax = fmax(xmax, s->cx[k] + s->r[k]);
		ymin = fmin(ymin, s->cy[k] - s->r[k]);
		ymax = fmax(ymax, s->cy[k] + s->r[k]);
	}
	/* cells centred on i h, j h: the origin is a node and the grid is
	 * symmetric like the source shapes */
	long i0 = (long)floor(xmin / h) - 1, i1 = (long)ceil(xmax / h) + 1;
	long j0 = (long)floor(ymin / h) - 1, j1 = (long)ceil(ymax / h) + 1;
	int n = 0;
	for (long j = j0; j <= j1; j++)
		for (long i = i0; i <= i1; i++) {
			double x = i * h, y = j * h, f = 0;
			for (int k = 0; k < s->ndisc; k++)
				f += s->sign[k] * disc_cover(x, y, h, s->cx[k], s->cy[k], s->r[k]);
			if (fabs(f) < 1e-12)
				continue;
			if (sx) {
				sx[n] = x;
				sy[n] = y;
				w[n] = f * h * h;
			}
			n++;
		}
	return n;
}

/* The part of the cell at g (side h) inside the pupil |g| < R. */
static double pupil_cover(double gx, double gy, double R, double rin2, double rout2, double h,
			  int point)
{
	double g2 = gx * gx + gy * gy;
	if (point)
		return g2 < R * R;
	if (g2 <= rin2)
		return 1;
	if (g2 >= rout2)
		return 0;
	double g = sqrt(g2);
	if (g == 0)
		return 1;
	return abbe_cover(R - g, gx / g, gy / g, h);
}

struct job {
	const struct orders *o;
	const struct pupil *p;
	size_t kx, ky;
	const struct fft_plan *px, *py;
	double complex *e;       /* the field's grid, ky rows of kx */
	double *acc;             /* sum of w |E|^2, ky rows of kx */
	double w;
	double complex **work;   /* per worker */
	size_t *cols;            /* the columns that hold orders */
	size_t ncols;
};

static void columns(void *ctx, size_t lo, size_t hi, int worker)
{
	struct job *jb = ctx;
	double complex *col = jb->work[worker], *sub = col + jb->ky;
	for (size_t c = lo; c < hi; c++) {
		size_t i = jb->cols[c];
		for (size_t j = 0; j < jb->ky; j++)
			col[j] = jb->e[j * jb->kx + i];
		fft_exec(jb->py, col, sub);
		for (size_t j = 0; j < jb->ky; j++)
			jb->e[j * jb->kx + i] = col[j];
	}
}

static void rows(void *ctx, size_t lo, size_t hi, int worker)
{
	struct job *jb = ctx;
	double complex *sub = jb->work[worker];
	for (size_t j = lo; j < hi; j++) {
		double complex *r = jb->e + j * jb->kx;
		double *a = jb->acc + j * jb->kx;
		fft_exec(jb->px, r, sub);
		for (size_t i = 0; i < jb->kx; i++)
			a[i] += jb->w * (creal(r[i]) * creal(r[i]) + cimag(r[i]) * cimag(r[i]));
	}
}

struct spectrum *abbe_spectrum(const struct orders *o, const struct pupil *p,
			       const struct source *s, double h)
{
	int np = p->nplanes;
	int nn = abbe_nodes(s, h, NULL, NULL, NULL);
	double *sx = xreallocarray(NULL, (size_t)nn, 3 * sizeof *sx), *sy = sx + nn, *sw = sy + nn;
	abbe_nodes(s, h, sx, sy, sw);
	double R = p->cutoff, R2 = R * R;
	/* a cell lies wholly inside (outside) the pupil circle of an order
	 * if its centre is within R - reach (beyond R + reach) */
	double reach = s->coherent ? 0 : 0.7072 * h;
	double rin2 = R > reach ? (R - reach) * (R - reach) : 0, rout2 = (R + reach) * (R + reach);
	/* the clear mask's image: the zero order alone, |P| = 1 in the pupil */
	double norm = 0;
	for (int k = 0; k < nn; k++)
		norm += sw[k] * pupil_cover(sx[k], sy[k], R, rin2, rout2, h, s->coherent);
	/* sum of w c^2 (cover - cover^2): the self terms of the orders that a
	 * cell sees in part (see the top) */
	double diag = 0;
	if (!(norm > 1e-12 * M_PI * R2) && !s->coherent) {
		free(sx);
		return NULL;
	}
	size_t kx = nice_length(4 * (size_t)o->mmax + 1), ky = nice_length(4 * (size_t)o->nmax + 1);
	size_t wd = 4 * (size_t)o->mmax + 1, ht = 4 * (size_t)o->nmax + 1;
	struct fft_plan *px = fft_plan_new(kx, 1), *py = fft_plan_new(ky, 1);
	struct fft_plan *fx = fft_plan_new(kx, -1), *fy = fft_plan_new(ky, -1);
	size_t grid = ck_mul(kx, ky, "Abbe FFT grid");
	double complex *e = xreallocarray(NULL, grid, sizeof *e);
	double *acc = xcalloc(ck_mul(grid, (size_t)np, "Abbe FFT grid planes"), sizeof *acc);
	int nt = par_threads();
	size_t nw = ky + (fft_work_size(px) > fft_work_size(py) ? fft_work_size(px)
							   : fft_work_size(py));
	size_t nw2 = fft_work2_size(fx, fy);
	if (nw2 > nw)
		nw = nw2;
	double complex **work = xreallocarray(NULL, (size_t)nt, sizeof *work);
	for (int t = 0; t < nt; t++)
		work[t] = xreallocarray(NULL, nw, sizeof **work);
	/* the columns m mod kx that hold orders */
	size_t *cols = xreallocarray(NULL, 2 * (size_t)o->mmax + 1, sizeof *cols);
	size_t ncols = 0;
	for (int m = -o->mmax; m <= o->mmax; m++)
		cols[ncols++] = (size_t)(m < 0 ? m + (long)kx : m);
	struct job jb = {o, p, kx, ky, px, py, e, acc, 0, work, cols, ncols};

	struct progress prog;
	progress_begin(&prog, "source points", splat_quiet);
	for (int k = 0; k < nn; k++) {
		progress_step(&prog, k, nn);
		for (int l = 0; l < np; l++) {
			memset(e, 0, grid * sizeof *e);
			int any = 0;
			for (int q = 0; q < o->n; q++) {
				if (o->c[q] == 0)
					continue;
				double gx = sx[k] + o->fx[q], gy = sy[k] + o->fy[q];
				double cov = pupil_cover(gx, gy, R, rin2, rout2, h, s->coherent);
				if (cov == 0)
					continue;
				if (l == 0 && cov < 1) {
					double c2 = creal(o->c[q]) * creal(o->c[q]) +
						cimag(o->c[q]) * cimag(o->c[q]);
					diag += sw[k] * c2 * (cov - cov * cov);
				}
				double ph = pupil_phase(p, gx, gy);
				if (l > 0)
					ph += l * p->dz * pupil_depth(p, gx, gy);
				double complex v = o->c[q] * cov;
				if (ph != 0)
					v *= cos(ph) + I * sin(ph);
				size_t i = (size_t)(o->m[q] < 0 ? o->m[q] + (long)kx : o->m[q]);
				size_t j = (size_t)(o->k[q] < 0 ? o->k[q] + (long)ky : o->k[q]);
				e[j * kx + i] = v;
				any = 1;
			}
			if (!any)
				continue;
			jb.e = e;
			jb.acc = acc + (size_t)l * grid;
			jb.w = sw[k];
			par_for(ncols, 8, columns, &jb);
			par_for(ky, 8, rows, &jb);
		}
	}
	struct spectrum *sp = spectrum_new(o, np);
	sp->pairs = nn;         /* source points, for the log line */
	for (int l = 0; l < np; l++) {
		const double *a = acc + (size_t)l * grid;
		for (size_t i = 0; i < grid; i++)
			e[i] = a[i];
		fft_exec2(fx, fy, e, work[0]);
		double complex *out = sp->a + (size_t)l * wd * ht;
		double scale = 1 / ((double)grid * norm);
		e[0] += diag * (double)grid;
		for (long dn = -2 * (long)o->nmax; dn <= 2 * (long)o->nmax; dn++) {
			size_t j = (size_t)(dn < 0 ? dn + (long)ky : dn);
			for (long dm = -2 * (long)o->mmax; dm <= 2 * (long)o->mmax; dm++) {
				size_t i = (size_t)(dm < 0 ? dm + (long)kx : dm);
				out[(size_t)(dn + 2 * o->nmax) * wd + (size_t)(dm + 2 * o->mmax)] =
					e[j * kx + i] * scale;
			}
		}
	}
	for (int t = 0; t < nt; t++)
		free(work[t]);
	free(work);
	free(cols);
	free(e);
	free(acc);
	free(sx);
	fft_plan_free(px);
	fft_plan_free(py);
	fft_plan_free(fx);
	fft_plan_free(fy);
	return sp;
}
