/*
 * fmt_bleach.h - the bleach input file: the resist, the film stack under
 * it, the exposure, the post-exposure bake and the development-rate
 * model (thesis 2.1, 8.6, Table 9.1, 9.3.2).  The thesis says only that
 * it "has the format of SAMPLE", whose manual is lost, so the format is
 * ours: keyword statements one a line, as in splat's input, '#' starts a
 * comment.  See man/man5/bleach.5 for every statement.
 *
 *   wavelength 0.436
 *   resist thickness 0.70 index 1.68 dill 0.64 0.040 0.010
 *   layer 0.0741 1.47 0.0
 *   substrate 4.73 0.14
 *   dose 240
 *   bake diffusion 0.08
 *   develop kim 0.062 0.0001 8.5
 *   grid nz 300
 *
 * Lengths in micrometres, A and B in 1/um, C in cm2/mJ, doses in mJ/cm2,
 * rates in um/s.  Every error names the file and line.
 */
#ifndef S3D_FMT_BLEACH_H
#define S3D_FMT_BLEACH_H

#include <stddef.h>

/* filmstack.h's (not included here: it brings complex.h, whose macro I
 * the programs use as a name) */
struct filmstack;
struct film_layer;

/* Boltzmann constant in eV/K (Arrhenius rates of car and peb). */
#define BLEACH_KB_EV 8.617333262e-5

enum {
	BLEACH_MAX_LAYERS = 64,
	BLEACH_MAX_NZ = 100000,     /* points through the thickness */
	BLEACH_MAX_NXY = 100000     /* resampled x or y points */
};
/* Largest seed of the stochastic statement: 2^53 - 1, so that any seed
 * is written back exactly. */
#define BLEACH_MAX_SEED 9007199254740991L

/* Development-rate models (devrate.c). */
enum bleach_model {
	BLEACH_KIM,         /* R1 R2 R3 [R4 R5 R6] */
	BLEACH_MACK,        /* Rmax Rmin Mth n */
	BLEACH_DILL,        /* E1 E2 E3 */
	BLEACH_CANEG,       /* Rmax Rmin p, plus the crosslink statement */
	BLEACH_MACKENH,     /* Rmax Rmin Rresin n l (Mack 1992, enhanced) */
	BLEACH_NOTCH        /* Rmax Rmin n Mth_notch n_notch */
};

/* Post-exposure bake. */
enum bleach_bake { BAKE_NONE, BAKE_Z, BAKE_3D };

struct bleach_layer {
	double thick;       /* um */
	double n, k;        /* complex index n - ik */
};

struct bleach_input {
	double wavelength;          /* um */
	double ambient;             /* index of the medium above (1, air) */
	double thick, index;        /* resist thickness (um), real index */
	double A, B, C;             /* Dill: 1/um, 1/um, cm2/mJ */
	int nlayers;                /* films under the resist, top first */
	struct bleach_layer layers[BLEACH_MAX_LAYERS];
	double sub_n, sub_k;        /* substrate */
	double dose;                /* mJ/cm2 at clear-field intensity 1 */
	int standing;               /* 1: thin-film optics; 0: Beer-Lambert */
	enum bleach_bake bake;
	double diffusion;           /* bake diffusion length sqrt(2Dt), um */
	enum bleach_model model;
	int npar;                   /* rate parameters given */
	double par[6];
	/* crosslinking of the negative CA resist (thesis 9.3.2):
	 * X = 1 - exp(-k t a^m), k = k0 exp(-Ea / (kB T)) */
	int have_crosslink;
	double k0;                  /* 1/s */
	double ea;                  /* eV */
	double order;               /* m */
	double temp;                /* degrees Celsius */
	double time;                /* s */
	/* chemically amplified positive resist: the car and peb
	 * statements, rates already evaluated at the bake temperature */
	int have_car;               /* car and peb given (they need each other) */
	double q0;                  /* quencher, relative to the photoacid generator */
	double kamp;                /* amplification, 1/s */
	double porder;              /* reaction order p in acid */
	double kloss;               /* acid loss, 1/s */
	double kq;                  /* acid-quencher neutralisation, 1/s */
	double peb_time;            /* s */
	double dacid, dquench;      /* diffusivities, um2/s */
	double peb_temp;            /* Celsius; NaN when not given */
	long line_car, line_peb;
	/* shot noise (bleach.5 stochastic): the PAG concentration of the car
	 * statement's pag pair, molecules per nm^3 (0: not given), and the
	 * stochastic statement's seed and switches */
	double pag;
	int stochastic;             /* the stochastic statement is there */
	long seed;                  /* 0 to BLEACH_MAX_SEED */
	int noise_photons, noise_acid;
	int bake_full;              /* bake full: the nonlinear bake of the noisy
				     * fields (0: bake linear, the default) */
	long line_stochastic;
	int nx, ny, nz;             /* 0 for nx, ny: the contour-file's grid */
	long line_nz;               /* line of the grid statement (0: default) */
	long line_dose;             /* line of the dose statement */
};

/* Reads and checks a bleach input file; dies naming file:line. */
void fmt_bleach_read(const char *path, struct bleach_input *in);
/* Parses a file already in memory (tests). */
void fmt_bleach_parse(const char *name, const char *text, struct bleach_input *in);
/* Writes the statements back (round trip, documentation). */
void fmt_bleach_write(const char *path, const struct bleach_input *in);
/* The film stack of the file for filmstack.h (layers: BLEACH_MAX_LAYERS
 * entries, or at least in->nlayers), with the unexposed resist's
 * extinction k = (A + B) lambda / (4 pi): what splat -bf images through
 * and what bleach divides such an image stack by. */
void fmt_bleach_film(const struct bleach_input *in, struct filmstack *fs,
		     struct film_layer *layers);
/* The default nz when no grid statement gives it: at least 40 points per
 * standing-wave period lambda / (2 n), and at least 50. */
int fmt_bleach_default_nz(const struct bleach_input *in);

/* The numbered statements, for calib(1): the K-th number (from 1) on the
 * line whose first word is stmt, numbers counted as they appear on the
 * line and words skipped ("develop mack 0.1 0.0001 0.5 8": K = 3 is 0.5).
 * text is the whole file; name is used in messages.  Dies "name:line:
 * what" when no line or more than one starts with stmt, or the line has
 * fewer than k numbers.  Returns the value; *off and *len give where its
 * characters are in text, *line its line. */
double fmt_bleach_number(const char *name, const char *text, const char *stmt, int k,
			 size_t *off, size_t *len, long *line);
/* A copy of text (malloc'd) with that number replaced by v in num_fmt's
 * shortest form, every other byte kept. */
char *fmt_bleach_set_number(const char *name, const char *text, const char *stmt, int k,
			    double v);

#endif
