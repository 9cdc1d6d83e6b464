/*
 * unionfind.h - a disjoint-set forest over indices 0..n-1 (parent[i] = i
 * at the start), with path halving; a join keeps the smaller index as the
 * root, so the roots, and the order regions come out in, do not depend on
 * the order of the joins.  Used by the section's region search
 * (surf_section.c) and the whole-section regions (surf_regions.c).
 */
#ifndef S3D_UNIONFIND_H
#define S3D_UNIONFIND_H

#include <stddef.h>

static inline size_t uf_find(size_t *parent, size_t i)
{
	while (parent[i] != i) {
		parent[i] = parent[parent[i]];
		i = parent[i];
	}
	return i;
}

static inline void uf_join(size_t *parent, size_t a, size_t b)
{
	a = uf_find(parent, a);
	b = uf_find(parent, b);
	if (a != b)
		parent[a < b ? b : a] = a < b ? a : b;
}

#endif
