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

/* The same triangle by triangle, as a surface is extracted, so that the
 * soup is never held (a third of its memory is the welded mesh): the
 * vertices and triangles of tri_weld's of the same triangles in the same
 * order.  Zero-initialise, set eps, add triangles, then take the mesh
 * (tri_weld_take: the welder is empty again, its table kept for the next
 * surface) and at the end tri_weld_free. */
struct tri_weld {
	double eps;
	double *p;
	int *tv;
	size_t nv, nt;
	size_t pcap, tvcap;
	int *tab;               /* vertex numbers by bin, at most half full */
	size_t cap;
};
void tri_weld_add(struct tri_weld *w, const double tri[9]);
/* Hands over the vertices (*p, 3 per vertex) and triangles (*tv, 3 per
 * triangle, *nt of them), the caller's to free; returns the vertex count. */
size_t tri_weld_take(struct tri_weld *w, double **p, int **tv, size_t *nt);
void tri_weld_free(struct tri_weld *w);

#endif
