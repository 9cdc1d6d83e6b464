/*
 * etch2d.h - 2D development of a resist cross-section (a rate array with
 * ny = 1) by the five etching algorithms the thesis compared (chapters
 * 3, 4, 6 and 7, Table 10.1) and a fast-marching reference:
 *
 *   cell.c       Dill's cell removal (3.2), fastest boundary cell first
 *   huygens.c    the modified (Huygens) cell method (4.3), constant step
 *   string.c     the string (6.2): nodes along the bisector normal
 *   ray.c        the ray (6.3): independent rays, joined in order
 *   raystring.c  the ray-string (7.3-7.5): rays joined by a cut, merged,
 *                clipped, flattened and delooped string
 *   fmm2d.c      second-order fast marching on a node grid: the reference
 *
 * The files are in layers, each using only those below it:
 *   run.c        (this header) the dispatch to the method of -method
 *   methods.h    the six algorithms above, one file each
 *   front.h      what the surface methods share: front.c (the string of
 *                nodes: the ray advance, clipping, delooping, cutting and
 *                merging) and front_start.c (its start: the top, a seed,
 *                a -start profile)
 *   e2.h         what every method shares: common.c (box, rate, print
 *                times, limits), start.c (the -start profile as a
 *                region), profile.c (polylines from segments: staircases
 *                of cells, contours of arrival times; the plot sets)
 *
 * Coordinates: x across, z up, z = zmax the resist top, zmin the
 * substrate; um, s, um/s.  The rate is the library's rfield (bilinear in
 * x-z for a 2D array) at y = ymin.
 */
#ifndef ETCH2D_H
#define ETCH2D_H

#include "e2.h"

/* Runs the method of e->o (fills e->pf and e->st). */
void e2_run(struct e2 *e);

#endif
