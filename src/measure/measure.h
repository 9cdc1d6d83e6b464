/*
 * measure.h - CD metrology on a developed resist surface: the options,
 * one measured row per height, and the figures of the whole feature.
 * See man/man1/measure.1.
 */
#ifndef S3D_MEASURE_H
#define S3D_MEASURE_H

#include "surf.h"

#include <stdio.h>

enum kind { HOLE, SPACE, LINE };

struct options {
	long set;               /* 1-based; 0: the last */
	double *h;              /* heights: um (-at) or percent (-rel) */
	int nh;
	int rel;                /* -rel given */
	enum kind kind;
	int have_kind;
	double x, y;            /* the point in the feature */
	int axis;               /* -space/-line: 0 along x, 1 along y */
	const char *out;        /* table, "-" stdout */
	const char *plot;       /* 2D plot file or NULL */
	int force;              /* measure a surface with crossings */
	int ler;                /* -ler: edge roughness (rough.h) */
	const char *psd;        /* -psd file or NULL */
	int holes;              /* -holes: every hole of the section */
	int lcdu;               /* -lcdu */
	/* -accuracy P|check with -coarse TABLE [-ratio R]: the err column */
	const char *coarse;     /* the table measured on the coarser solve */
	double accuracy;        /* percent; 0 for check (estimate only) */
	int have_accuracy;
	double ratio;           /* coarse / fine grid spacing (default 2) */
	/* -coarser TABLE [-ratio2 Q]: a third solve, the order observed */
	const char *coarser;    /* the table of the solve coarser than -coarse */
	double ratio2;          /* coarser / coarse grid spacing (default 2) */
	/* -coarser-fine TABLE: the coarser change is cd(TABLE) - cd(-coarser)
	 * rather than cd(-coarse) - cd(-coarser): refinement by axis, where
	 * the earlier change of one axis was solved at another level of the
	 * others */
	const char *coarser_fine;
	/* -plus TABLE: its err column (the estimate along the other axes) is
	 * added to each row's err */
	const char *plus;
	double order;           /* -order: assumed from two solves (default 1) */
	const char *input;
};

/* One height. */
struct row {
	double z;               /* the height asked, um */
	double cd;              /* um */
	/* hole: area (um2), extents along x and y through the point;
	 * space/line: the ends of the interval along the axis */
	double a, b, c;
	int edge;               /* the feature reaches the box edge here */
	double zsec;            /* the height of the section taken, um */
	/* the x-y rectangle of the section that decided cd (xmin xmax ymin
	 * ymax): a hole's region, the stretch of a space or line, the point
	 * alone where the feature is absent */
	double rect[4];
	double err;             /* um, the estimated discretisation error */
};

struct roughness;

struct result {
	struct row *rows;
	int nrows;
	int have_swa;           /* two heights or more */
	int swa_known;          /* the feature is present at both ends */
	double swa;             /* degrees */
	double resist_loss;     /* um */
	int cleared;
	const struct roughness *rough;  /* -ler: its lines follow the table */
	int have_err;           /* err estimated (-accuracy) */
};

/* Measures the feature of o on surface s at every height (heights in um,
 * in the box). */
void measure_feature(const struct surf *s, const struct options *o,
		     const double *z, struct result *r);

/* z raised off the substrate as the table's sections are (feature.c). */
double feature_height(const struct surf *s, double z);
/* The orders of convergence the estimate trusts: below 0.5 a halving
 * shrinks the change by less than 1.41 and the estimate would be more
 * than 2.4 times the change, with the order itself uncertain; above 2,
 * the highest order in the chain (the image and the rates are
 * interpolated linearly), the coarser change is not yet asymptotic and
 * order 1 is used (accuracy.c). */
#define ACCURACY_ORDER_MIN 0.5
#define ACCURACY_ORDER_MAX 2

/* accuracy.c: the Richardson estimate of each row's discretisation
 * error from the coarse table (and the coarser one: the order observed);
 * returns the number of rows whose estimate is over o->accuracy percent
 * of their cd or whose solves are not in the asymptotic range (0 for
 * check). */
int accuracy_estimate(const struct options *o, struct result *r);

/* The table on o->out, and the plot file if o->plot. */
void report_table(const struct options *o, const struct result *r);
void report_plot(const struct options *o, const struct surf *s, const struct result *r);

#endif
