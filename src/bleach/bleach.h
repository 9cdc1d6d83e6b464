/*
 * bleach.h - the modules of bleach, the 3D exposure simulator (thesis
 * 2.1, 8.6): thin-film optics, Dill bleaching with its dose table, the
 * post-exposure bake, the development-rate models and the M = level
 * solid.  Shared by main.c and the unit tests in tests/bleach/.
 *
 * Depth convention inside the modules: node j of a column lies at depth
 * j * dz below the original resist top (j = 0 the top, j = nz - 1 the
 * resist-substrate interface).  Only run.c maps it to the rate file's
 * z, which runs from -thickness (k = 0) up to 0.
 */
#ifndef S3D_BLEACH_H
#define S3D_BLEACH_H

#include "fmt_bleach.h"

#include <stddef.h>

/* ---- run.c: the 3D pipeline, from the image to the rate array ---- */

/* What the command line asks of a 3D run (bleach(1)). */
struct bleach_opts {
	const char *contour;    /* the aerial image or image stack */
	const char *input;      /* the resist file (bleach.5) */
	const char *output;     /* the rate file, or NULL for the default name */
	int ascii, solid, quiet;
	double level;           /* M of the -solid surface */
	int have_dose;          /* -dose given: dose replaces the input's */
	double dose;            /* mJ/cm2 */
	long seed;              /* -seed: replaces the stochastic statement's; -1 if not given */
	int nz;                 /* -nz: points through the resist, replacing the
				   input's grid nz (0: the input's) */
};

/* Reads, exposes, bakes and writes the rate array (and mxyz.solid.3D);
 * dies on bad input. */
void bleach_run(const struct bleach_opts *o);

/* ---- thinfilm.c: characteristic-matrix standing waves (thesis 2.1) ---- */

struct thinfilm {
	double lambda;          /* um */
	double n0;              /* ambient index */
	double nr;              /* resist real index */
	int nz;                 /* resist nodes; nz - 1 sublayers */
	double dz;              /* sublayer thickness, um */
	int nlayers;
	const struct bleach_layer *layers;   /* under the resist, top first */
	double sub_n, sub_k;
};

void thinfilm_init(struct thinfilm *tf, const struct bleach_input *in, int nz);
/* Relative intensity (nr / n0) |E(z_j)|^2 / |E_incident|^2 at the nz
 * nodes, for the resist extinction kr[s] of sublayer s (between nodes s
 * and s + 1). */
void thinfilm_intensity(const struct thinfilm *tf, const double *kr, double *irel);

/* ---- expose.c: Dill ABC bleaching (thesis 2.1, Figure 2.2) ---- */

/* The exposure of one column, integrated over dose by RK4. */
struct exposure {
	struct thinfilm tf;
	int standing;           /* 0: Beer-Lambert, I(0) = 1, no reflections */
	double A, B, C;         /* 1/um, 1/um, cm2/mJ */
	double h;               /* largest dose step, mJ/cm2 */
	double *kr, *irel, *k1, *k2, *k3, *k4, *tmp;   /* work arrays */
};

/* Step accuracy: C * h * Imax stays below this.  RK4 and the Hermite
 * interpolation then err by ~1e-8 in M (measured: halving the step
 * changes M by ~3e-8 on Olin Hunt 6512), far below the 1e-4 in M that
 * tests/bleach/expose.c allows against the closed form and the halved
 * step. */
#define EXPOSE_STEP 0.1

/* Most dose steps of one run: beyond, C * dose is absurd (every column
 * bleached to nothing) and the run would take hours. */
#define EXPOSE_MAX_STEPS 1e7

/* dmax: the largest dose any column gets; step_scale multiplies the
 * default step (tests halve it).  Returns 0, or -1 (nothing allocated)
 * if the run would need more than EXPOSE_MAX_STEPS steps. */
int exposure_init(struct exposure *e, const struct bleach_input *in, int nz,
		   double dmax, double step_scale);
void exposure_free(struct exposure *e);
/* Relative intensity in the column for PAC M (nz values). */
void exposure_intensity(struct exposure *e, const double *M, double *irel);
/* dM/dD = -C I M for the column state M, into dM. */
void exposure_rhs(struct exposure *e, const double *M, double *dM);
/* M after dose D (mJ/cm2) from M = 1, by steps of at most e->h. */
void exposure_column(struct exposure *e, double D, double *M);

/* M(z; D) for D = 0, h, 2h, ..., tabulated with dM/dD, interpolated by
 * cubic Hermite: every column of a vertically propagating exposure
 * follows the same history scaled by its dose (thesis 2.1). */
struct dose_table {
	int nz, nd;             /* nd + 1 rows */
	double h;               /* dose step */
	double *M;              /* (nd + 1) * nz */
	double *dM;             /* dM/dD, same shape */
};
struct dose_table *dose_table_build(struct exposure *e, double dmax);
/* M at dose D into out (nz values); D is clamped to [0, dmax]. */
void dose_table_eval(const struct dose_table *t, double D, double *out);
/* M of node j alone at dose D: the same interpolation as dose_table_eval
 * (the same value, bit for bit). */
double dose_table_node(const struct dose_table *t, double D, int j);
void dose_table_free(struct dose_table *t);

/* ---- stack.c: the image inside the resist (an image stack, stack.5) ---- */

struct image_stack;

/* Dies naming both values if the stack's thickness or index differs from
 * the resist file's. */
void stack_check(const struct image_stack *st, const struct bleach_input *in,
		 const char *stack_name, const char *input_name);
/* film.c: a stack through the film (its header word film) divided, plane
 * by plane, by the unexposed film's normal-incidence factor, so that
 * stack_expose applies it as a plain stack; dies if in turns the
 * standing waves off. */
void stack_film_divide(struct image_stack *st, const struct bleach_input *in,
		       const char *stack_name, const char *input_name);
/* M of every node of the rate array, M[(nz - 1 - j) * ncol + q] for node
 * j (depth j dz) of column q: the column's intensity at that depth is the
 * linear interpolation in depth of the planes' intensities
 * I[q * st->n + k] (clear field 1), and the node is exposed to the local
 * dose dose * I by the dose table t, or in closed form when A = 0 (e is
 * the exposure t was built from).  A bake in z is then applied to every
 * column. */
void stack_expose(const struct image_stack *st, const struct bleach_input *in,
		  struct exposure *e, const struct dose_table *t, const double *I,
		  size_t ncol, int nz, double *M);
/* The bake in z of every column of f[k * ncol + q] (nz planes): the
 * Gaussian smoothing of bake_rows along k, applied to blocks of columns
 * at once. */
void bake_z_columns(double *f, size_t ncol, int nz, double dz, double sigma);

/* ---- bake.c: post-exposure bake (thesis 8.6, Figure 8.17) ---- */

/* n x n matrix of Gaussian smoothing, standard deviation sigma (um), on
 * n nodes spacing d with no flux through either end. */
double *bake_matrix_neumann(int n, double d, double sigma);
/* p x p matrix of the same smoothing on a period of p samples spacing d. */
double *bake_matrix_periodic(int p, double d, double sigma);
/* v[i * stride] for i < n replaced by S v. */
void bake_apply(const double *S, int n, double *v, size_t stride, double *work);
/* The whole array f[(k * ny + j) * nx + i] smoothed in x and y, periodic
 * with nx - 1 and ny - 1 samples a period (the last node repeats the
 * first, as splat's window does). */
void bake_xy(double *f, int nx, int ny, int nz, double dx, double dy, double sigma);

/* ---- bake_iir.c: the x-y bake of a fine grid, recursive (Deriche) ---- */
/* Exact taps per point beyond which bake_xy smooths recursively. */
#define BAKE_IIR_TAPS 64
/* Whether a pass over period p samples of spacing d is done recursively. */
int bake_iir_wanted(int p, double d, double sigma);
/* The x (y) pass of bake_xy by the recursive Gaussian, every plane. */
void bake_iir_x(double *f, int nx, int ny, int nz, double dx, double sigma);
void bake_iir_y(double *f, int nx, int ny, int nz, double dy, double sigma);
/* Each row of rows (nrows rows of n values, spacing d) smoothed. */
void bake_rows(double *rows, int nrows, int n, double d, double sigma);
/* The same for the rows of a and of b (b may be NULL), one matrix. */
void bake_rows2(double *a, double *b, int nrows, int n, double d, double sigma);

/* ---- peb.c: reaction-diffusion bake of a CA positive resist ---- */

struct peb_params {
	double q0, kamp, p, kloss, kq;  /* car: -, 1/s, -, 1/s, 1/s */
	double t, dh, dq;               /* peb: s, um2/s, um2/s */
	int noisy;                      /* 1: a stochastic run (its noise: peb_run_noise) */
};
/* The whole bake for peb_choose_steps' estimate: points of the grid,
 * seconds a point and step in closed form, the input for the refusal
 * (points 0: no estimate, the default). */
void peb_set_budget(double points, double t_point, const char *where);
/* Seconds of one point's reaction over tau beyond t_point: the Gauss-
 * Legendre subintervals of order p != 1 (at most about 400 with the tail
 * in closed form), for the largest of h0max's fractions. */
double peb_react_seconds(const struct peb_params *pp, double h0max, double tau);
void peb_params_from(struct peb_params *pp, const struct bleach_input *in);
/* The exact reaction of one point over tau seconds: h and q replaced by
 * their values at the end (negative inputs count as 0), the integral of
 * max(h, 0)^p dt over the step returned. */
double peb_react(const struct peb_params *pp, double tau, double *h, double *q);
/* The bake of f[(k * ny + j) * nx + i] (nz planes of nx * ny, periodic in
 * x and y with the last node repeating the first, no flux in z): h0 in,
 * m out.  nouter x-y diffusion steps, each of ninner column steps.  hout
 * (NULL or nx ny nz values): the acid at the end of the bake. */
void peb_run(const struct peb_params *pp, double *f, int nx, int ny, int nz,
	     double dx, double dy, double dz, int nouter, int ninner, double *hout);
/* peb_run with the shot noise of the acid and the quencher at the start,
 * dh and dq (same shape as f, the noisy values less h0 and q0; NULL: no
 * noise), carried through the bake to first order (the linear-noise
 * bake, bleach(1)): m = exp(-kamp max(A + dA, 0)) with A the deterministic
 * integral of h^p and dA its first-order change.  dh and dq are used as
 * scratch. */
void peb_run_noise(const struct peb_params *pp, double *f, double *dh, double *dq, int nx,
		   int ny, int nz, double dx, double dy, double dz, int nouter, int ninner,
		   double *hout);
/* peb_run with the quencher at the start given point by point (q0, same
 * shape as f, never NULL) and the acid h0 not clamped at one: the
 * ordinary, nonlinear bake of the noisy fields (stochastic bake full,
 * bleach(1)). */
void peb_run_field(const struct peb_params *pp, double *f, const double *q0, int nx, int ny,
		   int nz, double dx, double dy, double dz, int nouter, int ninner, double *hout);
/* peb_xy.c: f (nz planes of nx * ny, periodic in x and y with the last
 * node repeating the first) after diffusing D (um2/s) for t seconds in x
 * and y, spacing hx, hy: each Fourier mode times e^{-D kappa^2 t}. */
void peb_diffuse_xy(double *f, int nx, int ny, int nz, double hx, double hy, double D, double t);
/* Periods (samples) up to this are applied as circulant matrices, not by
 * FFT: a short FFT costs mostly its calls. */
#define PEB_XY_CIRC_MAX 48
/* The bake of ncol independent columns f[k * ncol + q] (no x-y
 * diffusion), in nsteps Strang steps. */
void peb_columns(const struct peb_params *pp, double *f, size_t ncol, int nz, double dz,
		 int nsteps);
/* Steps so that m of sample columns (least, most acid and quantiles)
 * changes by less than PEB_TOL from the count to its double; returns the
 * doubled count, the last change in *change. */
int peb_choose_steps(const struct peb_params *pp, const double *h0, size_t ncol, int nz,
		     double dz, double *change);
#define PEB_TOL 1e-3
#define PEB_MIN_STEPS 8
#define PEB_MAX_STEPS 65536
/* The x-y diffusion steps for n column steps: n itself when both periods
 * are at most PEB_XY_CIRC_MAX (an x-y step then costs about a column
 * step, less than choosing fewer would); otherwise starting from kmin
 * (0: n / PEB_OUTER_START), doubled until m of the x-z and y-z slices through the
 * steepest image edge changes by less than PEB_TOL; the doubled count
 * (at most n), the last change in *change. */
int peb_choose_outer(const struct peb_params *pp, const double *h0, int nx, int ny, int nz,
		     double dx, double dy, double dz, int n, int kmin, double *change);
#define PEB_OUTER_START 16
/* The extrapolated bake of a deterministic run (Richardson, peb_steps.c):
 * for the counts n and nouter that peb_choose_steps and peb_choose_outer
 * chose, the smallest fine count nf such that m of the samples from nf / 2
 * and nf steps extrapolated is within PEB_TOL of m from nf and 2 nf
 * extrapolated, nf at most n / 2 (so that the two bakes, 1.5 nf steps,
 * cost less than n); returns nf, 0 if none is.  counts: the fine bake's
 * steps and x-y steps, then the coarse one's; the estimate in *change. */
int peb_choose_extrapolated(const struct peb_params *pp, const double *h0, int nx, int ny,
			    int nz, double dx, double dy, double dz, int n, int nouter, int counts[4],
			    double *change);
/* m from a bake in n steps (coarse) and one in 2n (fine), extrapolated,
 * within [0, 1] */
double peb_extrapolate(double coarse, double fine);

/* ---- shotnoise.c: photon and acid shot noise (bleach.5 stochastic) ---- */

/* What shotnoise_apply drew, for the progress line and the tests. */
struct shotnoise_info {
	double voxel_nm3;       /* dx dy dz */
	double npag;            /* mean PAG molecules a voxel, G0 dx dy dz */
	double photon_ev;       /* h c / lambda */
	double yield;           /* PAG conversions per photon the fresh resist absorbs */
	/* NULL, or arrays of the field's shape filled with the voxels' counts
	 * (PAG, absorbed photons, acid, quencher) */
	long *pag, *photons, *acid, *quencher;
};
/* h (nx ny nz values, [k * nx ny + j nx + i], x and y periodic with the
 * last node repeating the first) holds the deterministic photoacid
 * 1 - M of a grid of spacing dx dy dz (um); replaced by the acid drawn
 * from the voxels' PAG, photons and acid (counts over the mean PAG count
 * G0 dx dy dz).  Returns the relative quencher drawn the same way (a new
 * array), or NULL without acid noise (q0 everywhere). */
double *shotnoise_apply(const struct bleach_input *in, double *h, int nx, int ny, int nz,
			double dx, double dy, double dz, struct shotnoise_info *info);

/* ---- devrate.c: development-rate models (thesis 2.1, Table 9.1) ---- */

/* Precomputed constants of the negative CA resist. */
struct devrate {
	enum bleach_model model;
	double par[6];
	int npar;
	double kt;              /* k(T) t of the crosslinking, dimensionless */
	double order;
};
void devrate_init(struct devrate *d, const struct bleach_input *in);
/* Rate (um/s) for PAC M at depth below the original top (um). */
double devrate(const struct devrate *d, double M, double depth);
/* Kim surface factor S(M, depth). */
double devrate_kim_surface(const double *par, int npar, double M, double depth);
/* Boltzmann constant in eV/K, for the Arrhenius rate. */
#define BOLTZMANN_EV 8.617333262e-5

/* ---- solid.c: mxyz.solid.3D (thesis Figure 8.15) ---- */

/* Writes the closed surface M = level of f (grid as in iso.h) to path
 * as pdraw triangles; returns the triangle count. */
long solid_write(const char *path, const double *f, int nx, int ny, int nz,
		 const double bounds[6], double level);

#endif
