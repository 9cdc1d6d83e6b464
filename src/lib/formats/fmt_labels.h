/*
 * fmt_labels.h - the labels a plot file or contour-file carries for the
 * programs that draw it: comment lines at the head of the file,
 *
 *   # labels title "Developed resist surface" x "x (um)" y "y (um)" z "height (um)"
 *
 * a '#' line before the first number.  After "labels" come pairs of a key
 * (title, x, y, z) and a quoted text; a key left out has no label.  Other
 * '#' lines at the head are free comments.  The plot programs take the
 * labels as their defaults (options win).  See plot3d(5), plot2d(5) and
 * contour(5).
 */
#ifndef S3D_FMT_LABELS_H
#define S3D_FMT_LABELS_H

#include <stdio.h>

enum { LABEL_MAX = 120 };       /* bytes of a label, its NUL included */

struct plot_labels {
	char title[LABEL_MAX];
	char axis[3][LABEL_MAX];    /* x, y, z; "" when not given */
};

struct lex;
/* Reads the '#' lines at the head of lx into l (cleared first); nz is 1
 * if the file has a z label (a 3D plot file, a contour-file's values), 0
 * if it has none (a 2D plot file).  Dies on a malformed labels line. */
void fmt_labels_read(struct lex *lx, struct plot_labels *l, int nz);
/* Writes the labels line if any label is set: nothing otherwise. */
void fmt_labels_put(FILE *f, const struct plot_labels *l);
/* Sets l from the texts (NULL or "" leaves a label unset); a text too
 * long or holding a '"' or a control character is an internal error. */
void fmt_labels_set(struct plot_labels *l, const char *title, const char *x,
		    const char *y, const char *z);
/* The labels of the simulators' outputs, one place so that every writer
 * says the same (micrometres; z up, the resist top at the top). */
enum label_kind {
	LABELS_SURFACE,     /* etch's curves.plot: the developed surface */
	LABELS_TOPVIEW,     /* etch's curves.plot.2D: the same seen from above */
	LABELS_CUT_X,       /* etch's curves.cut, cut at x = const: y, z */
	LABELS_CUT_Y,       /* cut at y = const: x, z */
	LABELS_IMAGE,       /* splat's aerial image (contour-file) */
	LABELS_CUTLINE,     /* splat's cutline: intensity along the cut */
	LABELS_PAC,         /* bleach -solid: a surface of constant PAC */
	LABELS_PROFILE2D    /* etch2d's profile.plot: x, z */
};
const struct plot_labels *fmt_labels_std(enum label_kind k);
/* 1 if no label is set. */
int fmt_labels_empty(const struct plot_labels *l);

#endif
