/*
 * splat.h - the pieces of splat(L), the Hopkins aerial-image program
 * (thesis 2.2.1, 9.2-9.3), shared by its files and its unit tests.
 *
 * The computation runs in four stages, one file each:
 *   mask.c    Fourier coefficients c(f) of the periodic mask;
 *   pupil.c   the pupil P(g) = exp(i Phi(g)) inside NA/lambda, with the
 *             defocus and aberration phase Phi, and the propagation
 *             phase into the resist for an image stack;
 *   source.c  the effective source as signed discs, and the exact
 *             integral over the intersection of three discs (a source
 *             disc and two shifted pupils) that every TCC needs;
 *   tcc.c     the Hopkins sum over pairs of orders, collapsed into the
 *             image spectrum A(df) = sum TCC(f', f'') c(f') c*(f'') over
 *             the pairs with f' - f'' = df;
 *   image.c   the image I(r) = sum A(df) exp(2 pi i df.r) on the grid and
 *             along cutlines.
 */
#ifndef SPLAT_SPLAT_H
#define SPLAT_SPLAT_H

#include "fmt_splat.h"

#include <complex.h>

/* Diffraction orders f = (m/Lx, n/Ly) of the periodic mask that can
 * reach the pupil, with their Fourier coefficients. */
struct orders {
	double lx, ly;          /* period (window size), micrometres */
	int mmax, nmax;         /* |m| <= mmax, |n| <= nmax */
	int n;                  /* number of orders kept */
	int *m, *k;             /* order indices (x, y) */
	double *fx, *fy;        /* spatial frequency, 1/micrometre */
	double complex *c;      /* Fourier coefficient */
};

/* Orders with |f| <= fmax (1/um) and their coefficients c(f) =
 * (1/(Lx Ly)) integral over the window of t e^{i phase} e^{-2 pi i f.r}. */
struct orders *mask_orders(const struct splat_mask *m, double fmax);
void mask_orders_free(struct orders *o);
/* The distinct rect edges along x (axis 0) or y (1), window ends
 * included: the cells mask_orders sums over are their products. */
int mask_edge_count(const struct splat_mask *m, int axis);

struct pupil {
	double lambda, na;
	double cutoff;          /* NA/lambda, 1/um */
	double defocus;         /* micrometres */
	int naberr;
	const struct splat_aberr *aberr;
	int flat;               /* 1 if Phi == 0 everywhere (no defocus, no aberration) */
	double waves;           /* bound on |W + W_defocus| (+ |W_z| of the deepest plane) in waves */
	/* the image inside the resist (splat(5)'s resist statement): plane k
	 * at depth k dz adds 2 pi W_z with W_z = (z / lambda)(sqrt(n^2 -
	 * lambda^2 |g|^2) - n) */
	int nplanes;            /* 1: the single image at the resist top */
	double dz;              /* plane spacing, micrometres */
	double index;           /* resist index n */
};

void pupil_init(struct pupil *p, const struct splat_input *in);
/* Phi(g) in radians at pupil frequency g (1/um), |g| <= cutoff. */
double pupil_phase(const struct pupil *p, double gx, double gy);
/* The depth phase per micrometre, 2 pi W_z / z in radians per um, at
 * pupil frequency g (1/um): plane k adds k dz times it to Phi. */
double pupil_depth(const struct pupil *p, double gx, double gy);
/* Fringe Zernike term n (1..37) at normalised radius rho and angle theta. */
double pupil_zernike(int n, double rho, double theta);

/* The effective source as signed uniform discs (an annulus is a disc
 * minus a disc), in 1/um. */
enum { SOURCE_MAX_DISCS = 4 };
struct source {
	int coherent;           /* sigma 0: a single point at the origin */
	int ndisc;
	double cx[SOURCE_MAX_DISCS], cy[SOURCE_MAX_DISCS], r[SOURCE_MAX_DISCS];
	double sign[SOURCE_MAX_DISCS];
	double smax;            /* largest |s| on the source, 1/um */
};

void source_init(struct source *s, const struct splat_input *in, double cutoff);

/* Quadrature orders: Gauss-Legendre points per piece across (outer, y)
 * and along (inner, x) the source rows. */
struct quad {
	int nouter, ninner;
	double *uo, *wo, *ui, *wi;  /* nodes and weights on [-1, 1] */
	/* across, with t = uo pi/2: sin t, cos t and wo pi/2, computed once
	 * here instead of in every pair (source_disc3_planes) */
	double *so, *co, *wco;
};
void quad_init(struct quad *q, int nouter, int ninner);
void quad_free(struct quad *q);
/* Gauss-Legendre nodes and weights of order n on [-1, 1]. */
void quad_gauss(int n, double *u, double *w);
/* Default orders for a pupil, chosen from its phase excursion. */
void quad_default(const struct pupil *p, int *nouter, int *ninner);

/* Integral over the disc (cx, cy, r) intersected with the pupil discs of
 * orders f1 and f2 (centres -f1, -f2, radius cutoff) of
 * P(s + f1) P*(s + f2) ds. */
double complex source_disc3(const struct pupil *p, const struct quad *q,
			    double cx, double cy, double r,
			    double f1x, double f1y, double f2x, double f2y);
/* The same for every plane of the pupil at once, added to sum[k] for
 * k < p->nplanes: the region and the quadrature nodes are shared, only
 * the depth phase differs; row is scratch of p->nplanes + 2 q->ninner
 * values. */
void source_disc3_planes(const struct pupil *p, const struct quad *q,
			 double cx, double cy, double r,
			 double f1x, double f1y, double f2x, double f2y,
			 double complex *sum, double complex *row);

/* The image spectrum: A[(dn + 2 nmax) * (4 mmax + 1) + dm + 2 mmax],
 * one such array per plane of an image stack, top plane first.  Made by
 * tcc.c or abbe.c; spectrum.c allocates it, compute.c runs either. */
struct spectrum {
	double lx, ly;
	int mmax, nmax;         /* |dm| <= 2 mmax, |dn| <= 2 nmax */
	int nplanes;            /* 1 without a resist statement */
	double complex *a;      /* nplanes arrays */
	long pairs;             /* TCC pairs computed, for the progress line */
};
/* Plane k of a stack's spectrum as a one-plane spectrum (a view sharing
 * the arrays: not to be freed) for image_at and image_grid. */
struct spectrum spectrum_plane(const struct spectrum *sp, int k);

/* Hopkins: the spectrum for orders o, pupil p, source s, normalised so
 * that a clear mask images to exactly 1.  Returns NULL if no light from
 * the source passes the pupil. */
struct spectrum *tcc_spectrum(const struct orders *o, const struct pupil *p,
			      const struct source *s, const struct quad *q);
/* A zero spectrum of np planes for orders o (|dm| <= 2 mmax, |dn| <= 2 nmax). */
struct spectrum *spectrum_new(const struct orders *o, int np);
void spectrum_free(struct spectrum *sp);
/* 0: tcc_spectrum prints a progress line on long runs (progress.h);
 * splat's main sets it from -q, the tests leave it 1. */
extern int splat_quiet;

/* The whole computation for an input, with quadrature orders (0: the
 * defaults); used by main and the tests. */
struct spectrum *splat_spectrum(const struct splat_input *in, int nouter, int ninner,
				int *norders);

/* Abbe (abbe.c): the same spectrum as a sum over source points of
 * coherent images, by FFT.  The source points are the centres of square
 * cells of side h (1/um); by default ABBE_CELLS across the smallest
 * source disc or across the pupil's radius, whichever is smaller. */
enum { ABBE_CELLS = 40 };
double abbe_cell_default(const struct pupil *p, const struct source *s);
/* The part of a square of side h, centre at signed distance d inside a
 * straight edge of unit normal (ux, uy). */
double abbe_cover(double d, double ux, double uy, double h);
/* The nodes (sx, sy) in 1/um and their signed weights (cell area times
 * the source's cover); returns their count (only the count when sx is
 * NULL). */
int abbe_nodes(const struct source *s, double h, double *sx, double *sy, double *w);
struct spectrum *abbe_spectrum(const struct orders *o, const struct pupil *p,
			       const struct source *s, double h);

/* The imaging method: -method hopkins|abbe|auto (auto: the cheaper by
 * splat_estimate). */
enum splat_method { SPLAT_AUTO, SPLAT_HOPKINS, SPLAT_ABBE };
/* As splat_spectrum by method (not SPLAT_AUTO); for abbe, nouter is the
 * number of cells across the smallest source disc (0: the default). */
struct spectrum *splat_spectrum_method(const struct splat_input *in, enum splat_method method,
				       int nouter, int ninner, int *norders);

/* The work of a run estimated from its input (estimate.c): orders and
 * pairs of orders, seconds and bytes. */
void splat_estimate(const struct splat_input *in, double *orders, double *pairs,
		    double *seconds, double *bytes);

/* The same for the Abbe method: source cells, seconds and bytes. */
void splat_estimate_abbe(const struct splat_input *in, double *nodes, double *seconds,
			 double *bytes);

/* Intensity at one point, and on the contour grid (z[j*nx + i]). */
double image_at(const struct spectrum *sp, double x, double y);
void image_grid(const struct spectrum *sp, double xmin, double xmax, double ymin,
		double ymax, int nx, int ny, double *z);
/* The same when the grid spans exactly one period (xmax = xmin + lx, ymax
 * = ymin + ly, as splat's output grid does), by one inverse FFT of the
 * spectrum folded onto the nx - 1 by ny - 1 points of the period: cost
 * about nx ny log(nx ny) instead of (4M+1) nx ny; equal to image_grid to
 * rounding, not byte for byte (the -method abbe output uses it). */
void image_grid_fft(const struct spectrum *sp, double xmin, double ymin, int nx, int ny,
		    double *z);

#endif
