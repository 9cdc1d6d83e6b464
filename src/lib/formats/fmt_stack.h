/*
 * fmt_stack.h - the image stack: the aerial image at several depths inside
 * the resist, which splat writes for its resist statement and
 * bleach and contour read.  Text, one header line, then the planes top
 * first, each a depth line and a whole contour-file (fmt_contour.h):
 *
 *   stack planes N thickness T index n wavelength L
 *   depth 0
 *   xmin xmax ymin ymax
 *   nxpts nypts
 *   z ...
 *   depth z_1
 *   ...
 *
 * The word "stack" cannot begin a contour-file (whose first field is a
 * number), so every reader tells the two apart from the first token, and
 * plain contour-files are unchanged.  See man/man5/stack.5.
 */
#ifndef S3D_FMT_STACK_H
#define S3D_FMT_STACK_H

#include "fmt_contour.h"

/* Most planes (splat's SPLAT_MAX_PLANES). */
enum { STACK_MAX_PLANES = 1001 };

struct image_stack {
	int is_stack;           /* 0: read from a plain contour-file (n = 1) */
	int n;                  /* planes, >= 2 in a stack file */
	double thick;           /* resist thickness, micrometres (0: plain file) */
	double index;           /* resist real index (0: plain file) */
	double wavelength;      /* of the exposure, um (0: not recorded, as in
				 * stacks written before it was) */
	double *depth;          /* n depths below the resist top, um: 0 first,
				 * increasing, thick last */
	struct contour **plane; /* n images on one window and grid */
};

/* A stack of n planes at depths k thick / (n - 1), each a zero image on
 * the window and grid of like; wavelength 0 (the writer sets it). */
struct image_stack *fmt_stack_new(int n, double thick, double index,
				  const struct contour *like);
/* Reads an image stack, or a plain contour-file as a one-plane stack with
 * is_stack = 0; dies "prog: file:line: ..." on a malformed file, a plane
 * whose window or grid differs from the first's, or depths that do not
 * run from 0 up to the thickness. */
struct image_stack *fmt_stack_read(const char *path);
/* Writes a stack (n >= 2), or the plain contour-file when is_stack = 0. */
void fmt_stack_write(const char *path, const struct image_stack *s);
void fmt_stack_free(struct image_stack *s);

#endif
