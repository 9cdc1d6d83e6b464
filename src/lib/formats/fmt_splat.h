/*
 * fmt_splat.h - the input file of splat(L), the Hopkins aerial-image
 * program (thesis 2.2.1, 9.2-9.3), also read by drawmask(L) to draw the
 * mask.  One statement per line, '#' comments, case-insensitive keywords,
 * micrometres and degrees:
 *
 *   wavelength 0.436          na 0.28          sigma 0.5
 *   annular s_in s_out        quadrupole c r   dipole c r [x|y]
 *   defocus d
 *   imaging vector|scalar     immersion N      polarization x|y|te|tm|unpolarized
 *   reduction R|inf
 *   resist thickness T index n planes N     (an image stack, see stack.5)
 *   coma w field hx hy        astigmatism w field hx hy     spherical w
 *   curvature w field hx hy   distortion w field hx hy      zernike n c
 *   background dark|clear|T PHASE
 *   rect x1 y1 x2 y2 [T PHASE]
 *   polygon x1 y1 x2 y2 ... xn yn [t T PHASE]
 *   gds FILE layer L[/D] [cell NAME] [T PHASE]
 *   clip on|off
 *   window xmin xmax ymin ymax        window auto [margin m]
 *   grid nx ny
 *   contour FILE
 *   cutline x1 y1 x2 y2 npts FILE
 *
 * The mask is the background painted over by the rects, polygons and
 * gds unions in file order (later ones win).  It repeats with the period of the window.  See
 * man/man5/splat.5 for every statement, its defaults and its limits.
 */
#ifndef S3D_FMT_SPLAT_H
#define S3D_FMT_SPLAT_H

#include "poly.h"

/* Illumination shapes; sizes are in sigma units (fractions of NA). */
enum splat_source {
	SPLAT_SRC_CIRCLE,       /* disc of radius sigma (0: coherent) */
	SPLAT_SRC_ANNULAR,      /* ring s_in <= |s| <= s_out */
	SPLAT_SRC_QUADRUPOLE,   /* 4 discs of radius r at distance c on the diagonals */
	SPLAT_SRC_DIPOLE        /* 2 discs of radius r at (+-c, 0), or (0, +-c) */
};

/* Aberration terms (thesis 9.3); w is in waves. */
enum splat_aberr_kind {
	SPLAT_AB_SPHERICAL,     /* w rho^4 */
	SPLAT_AB_COMA,          /* w h rho^3 cos(theta - theta_h) */
	SPLAT_AB_ASTIGMATISM,   /* w h^2 rho^2 cos^2(theta - theta_h) */
	SPLAT_AB_CURVATURE,     /* w h^2 rho^2 */
	SPLAT_AB_DISTORTION,    /* w h^3 rho cos(theta - theta_h) */
	SPLAT_AB_ZERNIKE        /* fringe Zernike number n, coefficient w */
};

/* Polarisation of the illumination at the mask (vector imaging). */
enum splat_pol {
	SPLAT_POL_UNPOLARIZED,  /* the intensities of x and y averaged */
	SPLAT_POL_X, SPLAT_POL_Y,
	SPLAT_POL_TE,           /* (-s_y, s_x) / |s| for source point s */
	SPLAT_POL_TM            /* (s_x, s_y) / |s| */
};

struct splat_aberr {
	enum splat_aberr_kind kind;
	double w;               /* waves of optical path at the pupil edge */
	double hx, hy;          /* field point, fraction of the field radius */
	int zernike;            /* fringe Zernike number (SPLAT_AB_ZERNIKE) */
	long line;              /* input line, for messages */
};

/* One mask feature: rectangle x1 <= x <= x2, y1 <= y <= y2 (sorted on
 * reading), amplitude transmission t and phase in degrees. */
struct splat_rect {
	double x1, y1, x2, y2;  /* micrometres */
	double t;               /* amplitude transmission, 0..1 typically */
	double phase;           /* degrees */
	long line;
};

struct splat_cutline {
	double x1, y1, x2, y2;  /* micrometres */
	int npts;               /* >= 2, ends included */
	char *file;             /* 2D plot file written (owned) */
	long line;
};

/* A polygon statement, or the shapes of a gds statement: one union (its
 * overlaps count once), painted with t and phase over the background and
 * over the first `after` rects and every earlier layer. */
struct splat_layer {
	struct poly_set shapes;         /* micrometres, clipped to the window */
	double t, phase;                /* amplitude transmission, degrees */
	int after;                      /* rects that come before it in the file */
	long line;
	/* the statement, for fmt_splat_write */
	int is_gds;
	double *pxy;                    /* polygon: the vertices as given */
	int pn;
	char *gds_file;                 /* gds: the file, resolved against the input's folder */
	char *cell;                     /* gds: NULL for the single top cell */
	int layer, datatype;            /* gds: datatype -1 for all */
};

/* The mask alone: what drawmask needs. */
struct splat_mask {
	double xmin, xmax, ymin, ymax;  /* window = one period (micrometres) */
	double bg_t, bg_phase;          /* background transmission, degrees */
	int nrects;
	struct splat_rect *rects;       /* in file order, later paints over earlier */
	int nlayers;
	struct splat_layer *layers;     /* in file order, interleaved with the rects by `after` */
};

struct splat_input {
	/* optics */
	double wavelength;              /* micrometres (default 0.436) */
	double na;                      /* 0 < na < 1 (default 0.28) */
	enum splat_source source;
	double sigma;                   /* CIRCLE: radius (default 0.5) */
	double s_in, s_out;             /* ANNULAR */
	double pole_c, pole_r;          /* QUADRUPOLE, DIPOLE: centre distance, radius */
	int dipole_y;                   /* DIPOLE: 1 if the poles lie on the y axis */
	double defocus;                 /* micrometres, + away from the lens */
	int naberr;
	struct splat_aberr *aberr;      /* in file order; terms add up */

	struct splat_mask mask;

	/* output */
	int nx, ny;                     /* grid points, ends included (default 51x51) */
	char *contour;                  /* contour-file name (default "splat.cont"), owned */
	int contour_set;                /* 1 if the file named it */
	int ncutlines;
	struct splat_cutline *cutlines;

	/* "resist thickness T index n planes N": the image inside the resist
	 * at N depths k T/(N-1), written as an image stack (stack.5) */
	int planes;                     /* 0: a single image; else 2..SPLAT_MAX_PLANES */
	double resist_thick;            /* T, micrometres */
	double resist_index;            /* n, real refractive index */
	long resist_line;
	/* polygon and layout statements */
	int clip;                       /* clip on: polygons may cross the window */
	int window_auto;                /* window auto: from the gds shapes' bounding box */
	double margin;                  /* window auto margin, micrometres (-1: 2 lambda/NA) */
	/* vector imaging: imaging, immersion, polarization, reduction */
	int vector;                     /* imaging vector: 1; scalar (default): 0 */
	double immersion;               /* real index between lens and resist (default 1) */
	enum splat_pol polarization;    /* default unpolarized */
	double reduction;               /* lens reduction R (default 4); INFINITY for inf */
	long na_line;                   /* line of the na statement (0: default) */
};

/* Largest grid side: far beyond any use, small enough that nx*ny doubles
 * cannot overflow or exhaust memory by accident (the grid statement and
 * splat -grid); an image stack's planes * nx * ny is bounded by its square. */
enum { SPLAT_MAX_GRID = 10001 };

/* Most planes of an image stack: far beyond any use (a plane every
 * nanometre of a micrometre film), small enough to bound the memory. */
enum { SPLAT_MAX_PLANES = 1001 };

/* Reads and checks the whole file; dies "prog: file:line: ..." on any
 * error (unknown statement, wrong count of values, na >= 1, negative
 * sigma, grid under 2x2, zero-area window, feature outside the window,
 * missing window).  The caller frees the result with fmt_splat_free. */
struct splat_input *fmt_splat_read(const char *path);
void fmt_splat_free(struct splat_input *in);

/* Writes the input back in canonical form (round-trip tests). */
void fmt_splat_write(const char *path, const struct splat_input *in);

/* Mask amplitude transmission and phase (degrees) at (x, y), taken inside
 * the window (the last rect or layer containing the point wins, rect
 * edges included). */
void fmt_splat_mask_at(const struct splat_mask *m, double x, double y,
		       double *t, double *phase);

#endif
