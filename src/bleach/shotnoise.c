/*
 * shotnoise.c - photon and acid shot noise of a chemically amplified
 * resist (bleach.5 stochastic): the exposure's photoacid 1 - M becomes a
 * count of molecules per voxel before the bake, which carries the
 * difference from the deterministic fields to first order
 * (peb_run_noise).
 *
 * A voxel is one cell of the bake's grid, dx dy dz, holding n = G0 dx dy
 * dz PAG molecules on average (G0 the car statement's pag, per nm^3).
 *
 * Photons.  Dill's C (cm2/mJ) is the PAG's effective absorption cross
 * section over the photon energy, sigma = C h c / lambda (a quantum yield
 * of one folded in), and the exposure gives -ln M = C E with E the local
 * dose (mJ/cm2) the node has seen, standing waves and bleaching included
 * (dM/dD = -C I M, thesis 2.1).  The voxel's PAG thus absorb the energy
 * n sigma E, that is N = n C E = n (-ln M) photons on average, Poisson.
 * Each absorbed photon converts a PAG of its voxel chosen at random; one
 * that hits a PAG already converted makes nothing.  With N photons on
 * n_v PAG the chance that a PAG is hit is 1 - (1 - 1/n_v)^N, and over
 * the Poisson N of mean n_v (-ln M) its mean is exactly 1 - M: the model
 * is unbiased at every dose, however few the photons (applying 1 - e^-x
 * to a Poisson photon count would not be).
 *
 * Acid.  The voxel's PAG count n_v is drawn (floor(n) plus one with the
 * probability of n's fraction: mean exactly n), its acid count is
 * binomial on n_v with that chance (1 - M without photon noise), and its
 * quencher count Poisson with mean q0 n.  The bake sees the counts over n.
 * Without acid noise the PAG count is n itself and the acid is the
 * photons' share, (1 - M) N / mean(N): each photon makes the mean acid
 * of a photon.
 *
 * Every voxel draws from its own stream of rng.h keyed by (seed, voxel
 * index), the nodes that repeat the first x and y nodes (the periodic
 * window) copying them: the result depends on neither the thread count
 * nor the order of the work.
 */
#include "bleach.h"
#include "par.h"
#include "rng.h"
#include "util.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* h c = 6.62607015e-34 J s x 299792458 m/s = 1.98644586e-25 J m, in mJ um */
#define HC_MJ_UM 1.98644586e-16
/* 1 eV in mJ */
#define EV_MJ 1.602176634e-16
/* cm2 in nm2, and 1/um in 1/nm */
#define CM2_NM2 1e14
#define PER_UM_NM 1e-3
/* -ln M at most this (M = 0 after an enormous dose): every PAG converted */
#define NOISE_MAX_LN 700.0

struct noise {
	const struct bleach_input *in;
	double *h, *q;
	int nx, ny, px, py;     /* grid, and its x and y periods in nodes */
	double n;               /* mean PAG a voxel */
	struct shotnoise_info *info;
};

/* The draws of one voxel, node at, stream key. */
static void voxel(const struct noise *z, size_t at, uint64_t key)
{
	const struct bleach_input *in = z->in;
	struct rng r;
	rng_init(&r, (uint64_t)in->seed, key);
	double n = z->n, M = 1 - z->h[at];
	if (!(M < 1))
		M = 1;
	double L = M > 0 ? -log(M) : NOISE_MAX_LN;
	if (L > NOISE_MAX_LN)
		L = NOISE_MAX_LN;
	long npag = 0, nph = 0, nacid = 0;
	double h;
	if (in->noise_acid) {
		double fl = floor(n);
		npag = (long)fl + (rng_uniform(&r) < n - fl);
	}
	if (in->noise_photons) {
		double lam = (in->noise_acid ? (double)npag : n) * L;
		nph = rng_poisson(&r, lam);
		if (in->noise_acid) {
			/* the chance 1 - (1 - 1/n_v)^N that a PAG is hit */
			double p = nph == 0 || npag == 0 ? 0 : npag == 1 ? 1 :
				   -expm1((double)nph * log1p(-1.0 / (double)npag));
			nacid = rng_binomial(&r, npag, p);
			h = (double)nacid / n;
		} else {
			h = lam > 0 ? (1 - M) * (double)nph / lam : 0;
		}
	} else {
		nacid = rng_binomial(&r, npag, 1 - M);
		h = (double)nacid / n;
	}
	z->h[at] = h;
	long nq = 0;
	if (in->noise_acid) {
		nq = rng_poisson(&r, in->q0 * n);
		z->q[at] = (double)nq / n;
	}
	struct shotnoise_info *f = z->info;
	if (f && f->pag) {
		f->pag[at] = in->noise_acid ? npag : -1;
		f->photons[at] = nph;
		f->acid[at] = nacid;
		f->quencher[at] = nq;
	}
}

/* Rows (k, j) of the period, j < py: each voxel from its own stream. */
static void noise_rows(void *ctx, size_t lo, size_t hi, int worker)
{
	(void)worker;
	const struct noise *z = ctx;
	for (size_t r = lo; r < hi; r++) {
		size_t k = r / (size_t)z->py, j = r % (size_t)z->py;
		size_t base = (k * (size_t)z->ny + j) * (size_t)z->nx;
		for (int i = 0; i < z->px; i++)
			voxel(z, base + (size_t)i, (uint64_t)r * (uint64_t)z->px + (uint64_t)i);
	}
}

/* The nodes past the period (the last x node, the last y row) copy the
 * first ones: they are the same voxel of the periodic window. */
static void copy_periodic(double *v, long *c, int nx, int ny, int nz, int px, int py)
{
	for (int k = 0; k < nz; k++) {
		size_t plane = (size_t)k * (size_t)nx * (size_t)ny;
		for (int j = 0; j < ny; j++) {
			size_t row = plane + (size_t)j * nx, src = plane + (size_t)(j % py) * nx;
			for (int i = j < py ? px : 0; i < nx; i++) {
				if (v)
					v[row + i] = v[src + i % px];
				if (c)
					c[row + i] = c[src + i % px];
			}
		}
	}
}

double *shotnoise_apply(const struct bleach_input *in, double *h, int nx, int ny, int nz,
			double dx, double dy, double dz, struct shotnoise_info *info)
{
	struct shotnoise_info dummy = {0};
	if (!info)
		info = &dummy;
	size_t np = (size_t)nx * (size_t)ny * (size_t)nz;
	struct noise z = {in, h, NULL, nx, ny, nx > 1 ? nx - 1 : 1, ny > 1 ? ny - 1 : 1, 0, info};
	info->voxel_nm3 = dx * dy * dz * 1e9;
	z.n = info->npag = in->pag * info->voxel_nm3;
	double hnu = HC_MJ_UM / in->wavelength;            /* mJ */
	info->photon_ev = hnu / EV_MJ;
	double alpha = in->A + in->B;                      /* 1/um, unexposed */
	info->yield = alpha > 0 ? in->pag * in->C * hnu * CM2_NM2 / (alpha * PER_UM_NM) : 0;
	if (in->noise_acid)
		z.q = xreallocarray(NULL, np, sizeof *z.q);
	par_for((size_t)nz * (size_t)z.py, 1, noise_rows, &z);
	copy_periodic(h, NULL, nx, ny, nz, z.px, z.py);
	if (z.q)
		copy_periodic(z.q, NULL, nx, ny, nz, z.px, z.py);
	if (info->pag) {
		long *c[4] = {info->pag, info->photons, info->acid, info->quencher};
		for (int a = 0; a < 4; a++)
			copy_periodic(NULL, c[a], nx, ny, nz, z.px, z.py);
	}
	return z.q;
}
