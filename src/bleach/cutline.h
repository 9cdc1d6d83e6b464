/*
 * cutline.h - bleach along a cutline (thesis 2.2.1, Figure 2.7): the
 * intensity along a cutline of splat (a 2D plot file) exposed, baked and
 * developed into a 2D rate array (rval with ny = 1) over (distance along
 * the cutline, z), for etch2d.
 */
#ifndef BLEACH_CUTLINE_H
#define BLEACH_CUTLINE_H

/* Runs the whole 2D bleach: cut is the plot file, input the bleach input
 * file, out the rate file (ascii: the ASCII form). */
void cutline_bleach(const char *cut, const char *input, const char *out, int ascii, int quiet);

#endif
