/*
 * image.c - the aerial image from its spectrum,
 *   I(x, y) = sum_{dm, dn} A(dm, dn) exp(2 pi i (dm x / Lx + dn y / Ly)),
 * summed directly: the output grid includes both window ends and need not
 * match the period, so an FFT would not fit, and the separable sum (first
 * over dn for each grid row, then over dm) costs only
 * (4M+1)(4N+1) ny + (4M+1) nx ny complex products; the rows are shared
 * among threads, each row computed alone.  Rounding can leave
 * -1e-17 where the intensity |E|^2 is zero; it is clamped to 0.
 */
#include "checked.h"
#include "fft.h"
#include "splat.h"
#include "par.h"
#include "progress.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>

static double complex cis(double a)
{
	return cos(a) + I * sin(a);
}

double image_at(const struct spectrum *sp, double x, double y)
{
	int w = 4 * sp->mmax + 1, h = 4 * sp->nmax + 1;
	double sum = 0;
	for (int jn = 0; jn < h; jn++) {
		int dn = jn - 2 * sp->nmax;
		double complex row = 0;
		for (int im = 0; im < w; im++) {
			int dm = im - 2 * sp->mmax;
			double complex a = sp->a[(size_t)jn * w + im];
			if (a != 0)
				row += a * cis(2 * M_PI * dm * x / sp->lx);
		}
		sum += creal(row * cis(2 * M_PI * dn * y / sp->ly));
	}
	return sum > 0 ? sum : 0;
}

struct grid_job {
	const struct spectrum *sp;
	double ymin, ymax;
	int nx, ny;
	const double complex *ex;
	double complex *scratch;        /* per worker: ey (h) and b (w) */
	double *z;
	size_t row0;                    /* first row of the block */
};

/* rows row0 + lo .. row0 + hi - 1: each row alone, so the values do not
 * depend on how the rows are shared among threads */
static void grid_rows(void *ctx, size_t lo, size_t hi, int worker)
{
	const struct grid_job *g = ctx;
	const struct spectrum *sp = g->sp;
	size_t w = 4 * (size_t)sp->mmax + 1, h = 4 * (size_t)sp->nmax + 1;
	double complex *ey = g->scratch + (size_t)worker * (w + h), *b = ey + h;
	int nx = g->nx, ny = g->ny;
	for (size_t jj = lo; jj < hi; jj++) {
		size_t j = g->row0 + jj;
		double y = g->ymin + (g->ymax - g->ymin) * (double)j / (ny - 1);
		for (size_t jn = 0; jn < h; jn++)
			ey[jn] = cis(2 * M_PI * ((double)jn - 2 * sp->nmax) * y / sp->ly);
		for (size_t im = 0; im < w; im++) {
			double complex s = 0;
			for (size_t jn = 0; jn < h; jn++)
				s += sp->a[jn * w + im] * ey[jn];
			b[im] = s;
		}
		for (int i = 0; i < nx; i++) {
			const double complex *e = g->ex + (size_t)i * w;
			double s = 0;
			for (size_t im = 0; im < w; im++)
				s += creal(b[im]) * creal(e[im]) - cimag(b[im]) * cimag(e[im]);
			g->z[j * nx + i] = s > 0 ? s : 0;
		}
	}
}

void image_grid(const struct spectrum *sp, double xmin, double xmax, double ymin,
		double ymax, int nx, int ny, double *z)
{
	size_t w = 4 * (size_t)sp->mmax + 1, h = 4 * (size_t)sp->nmax + 1;
	double complex *ex = xreallocarray(NULL, w * (size_t)nx, sizeof *ex);
	int nt = par_threads();
	double complex *scratch = xreallocarray(NULL, (size_t)nt * (w + h), sizeof *scratch);
	for (int i = 0; i < nx; i++) {
		double x = xmin + (xmax - xmin) * i / (nx - 1);
		for (size_t im = 0; im < w; im++)
			ex[(size_t)i * w + im] = cis(2 * M_PI * ((double)im - 2 * sp->mmax) * x / sp->lx);
	}
	struct grid_job g = {sp, ymin, ymax, nx, ny, ex, scratch, z, 0};
	struct progress prog;
	progress_begin(&prog, "image rows", splat_quiet);
	/* blocks of rows between progress lines, the rows of a block shared
	 * among the threads */
	size_t block = 16 * (size_t)nt;
	for (size_t j = 0; j < (size_t)ny; j += block) {
		progress_step(&prog, (double)j, ny);
		g.row0 = j;
		size_t n = (size_t)ny - j < block ? (size_t)ny - j : block;
		par_for(n, 1, grid_rows, &g);
	}
	free(ex);
	free(scratch);
}

/* image_grid_fft: the spectrum folded onto the grid's period, then one
 * inverse 2D FFT, rows and then columns shared among threads */
struct fold_job {
	const struct fft_plan *plan;
	double complex *g;
	size_t nx, ny;          /* the period's points */
	double complex **work;  /* per worker */
};

static void fold_rows(void *ctx, size_t lo, size_t hi, int worker)
{
	struct fold_job *f = ctx;
	for (size_t j = lo; j < hi; j++)
		fft_exec(f->plan, f->g + j * f->nx, f->work[worker]);
}

static void fold_cols(void *ctx, size_t lo, size_t hi, int worker)
{
	struct fold_job *f = ctx;
	double complex *col = f->work[worker], *sub = col + f->ny;
	for (size_t i = lo; i < hi; i++) {
		for (size_t j = 0; j < f->ny; j++)
			col[j] = f->g[j * f->nx + i];
		fft_exec(f->plan, col, sub);
		for (size_t j = 0; j < f->ny; j++)
			f->g[j * f->nx + i] = col[j];
	}
}

void image_grid_fft(const struct spectrum *sp, double xmin, double ymin, int nx, int ny,
		    double *z)
{
	size_t w = 4 * (size_t)sp->mmax + 1, h = 4 * (size_t)sp->nmax + 1;
	size_t px = (size_t)nx - 1, py = (size_t)ny - 1;
	double complex *g = xcalloc(ck_mul(px, py, "image grid"), sizeof *g);
	double complex *ex = xreallocarray(NULL, w + h, sizeof *ex), *ey = ex + w;
	for (size_t im = 0; im < w; im++)
		ex[im] = cis(2 * M_PI * ((double)im - 2 * sp->mmax) * xmin / sp->lx);
	for (size_t jn = 0; jn < h; jn++)
		ey[jn] = cis(2 * M_PI * ((double)jn - 2 * sp->nmax) * ymin / sp->ly);
	/* A(dm, dn) at the bin (dm mod px, dn mod py): the sum at grid point
	 * (i, j) is then exactly the image there, aliasing or not */
	for (size_t jn = 0; jn < h; jn++) {
		long dn = (long)jn - 2 * sp->nmax;
		size_t j = (size_t)(((dn % (long)py) + (long)py) % (long)py);
		for (size_t im = 0; im < w; im++) {
			double complex a = sp->a[jn * w + im];
			if (a == 0)
				continue;
			long dm = (long)im - 2 * sp->mmax;
			size_t i = (size_t)(((dm % (long)px) + (long)px) % (long)px);
			g[j * px + i] += a * ex[im] * ey[jn];
		}
	}
	struct fft_plan *fx = fft_plan_new(px, 1), *fy = fft_plan_new(py, 1);
	int nt = par_threads();
	size_t nw = py + (fft_work_size(fx) > fft_work_size(fy) ? fft_work_size(fx)
							       : fft_work_size(fy));
	double complex **work = xreallocarray(NULL, (size_t)nt, sizeof *work);
	for (int t = 0; t < nt; t++)
		work[t] = xreallocarray(NULL, nw, sizeof **work);
	struct fold_job f = {fx, g, px, py, work};
	par_for(py, 8, fold_rows, &f);
	f.plan = fy;
	par_for(px, 8, fold_cols, &f);
	for (size_t j = 0; j < (size_t)ny; j++)
		for (size_t i = 0; i < (size_t)nx; i++) {
			double s = creal(g[(j % py) * px + i % px]);
			z[j * (size_t)nx + i] = s > 0 ? s : 0;
		}
	for (int t = 0; t < nt; t++)
		free(work[t]);
	free(work);
	fft_plan_free(fx);
	fft_plan_free(fy);
	free(ex);
	free(g);
}
