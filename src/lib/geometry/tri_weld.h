/*
 * tri_weld.h - the vertices of a triangle soup (9 doubles per triangle):
 * corners closer than eps (per coordinate) are one vertex, numbered in
 * the order of first appearance.  tri_decimate's first step.
 */
#ifndef S3D_TRI_WELD_H
#define S3D_TRI_WELD_H

#include <stddef.h>

/* Welds the n triangles v: *p gets the 3 coordinates of each vertex (the
 * first corner that made it), *tv the 3 vertex numbers of each triangle
 * (3n + 1 allocated); both to be freed.  Returns the vertex count. */
size_t tri_weld(const double *v, size_t n, double eps, double **p, int **tv);

#endif
