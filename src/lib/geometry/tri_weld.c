/*
 * tri_weld.c - welding of a triangle soup (tri_weld.h) through a hash of
 * bins 1024 weld distances wide: a point is looked up in its bin and in
 * the neighbours it lies within the weld distance of, so two such points
 * always meet; of several within reach, the lowest-numbered vertex wins.
 */
#include "tri_weld.h"
#include "util.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static uint64_t bin_hash(int64_t a, int64_t b, int64_t c)
{
	uint64_t h = (uint64_t)a * 0x9E3779B97F4A7C15u ^ (uint64_t)b * 0xC2B2AE3D27D4EB4Fu ^
		     (uint64_t)c * 0x165667B19E3779F9u;
	return h ^ (h >> 29);
}

static void bin_of(const double *x, double cell, int64_t b[3])
{
	for (int d = 0; d < 3; d++)
		b[d] = (int64_t)floor(x[d] / cell);
}

size_t tri_weld(const double *v, size_t n, double eps, double **pp, int **tvp)
{
	/* a table of vertex numbers, at most half full (3n vertices if no
	 * two triangles share one; a closed surface has about n/2) */
	size_t cap = 16, pcap = 0;
	while (cap < 6 * n + 16)
		cap *= 2;
	int *tab = xreallocarray(NULL, cap, sizeof *tab);
	for (size_t i = 0; i < cap; i++)
		tab[i] = -1;
	double *p = NULL;
	int *tv = xreallocarray(NULL, 3 * n + 1, sizeof *tv);
	/* bins much larger than eps (still far smaller than the triangles):
	 * the neighbouring bins are searched only along the axes where the
	 * point lies within eps of its bin's side */
	double cell = eps > 0 ? 1024 * eps : 1e-300;
	size_t nv = 0;
	for (size_t c = 0; c < 3 * n; c++) {
		const double *x = v + 3 * c;
		int64_t b[3];
		bin_of(x, cell, b);
		int lo[3], hi[3];
		for (int d = 0; d < 3; d++) {
			lo[d] = floor((x[d] - eps) / cell) < (double)b[d] ? -1 : 0;
			hi[d] = floor((x[d] + eps) / cell) > (double)b[d] ? 1 : 0;
		}
		int found = -1;
		for (int dz = lo[2]; dz <= hi[2]; dz++)
			for (int dy = lo[1]; dy <= hi[1]; dy++)
				for (int dx = lo[0]; dx <= hi[0]; dx++) {
					int64_t k[3] = {b[0] + dx, b[1] + dy, b[2] + dz};
					size_t s = bin_hash(k[0], k[1], k[2]) & (cap - 1);
					for (; tab[s] >= 0; s = (s + 1) & (cap - 1)) {
						int w = tab[s];
						const double *y = p + 3 * (size_t)w;
						int64_t bw[3];
						bin_of(y, cell, bw);
						if (bw[0] != k[0] || bw[1] != k[1] || bw[2] != k[2])
							continue;
						if (fabs(y[0] - x[0]) <= eps && fabs(y[1] - x[1]) <= eps &&
						    fabs(y[2] - x[2]) <= eps && (found < 0 || w < found))
							found = w;
					}
				}
		if (found < 0) {
			found = (int)nv;
			xgrow(&p, &pcap, 3 * (nv + 1), sizeof *p);
			memcpy(p + 3 * nv, x, 3 * sizeof *x);
			size_t s = bin_hash(b[0], b[1], b[2]) & (cap - 1);
			while (tab[s] >= 0)
				s = (s + 1) & (cap - 1);
			tab[s] = found;
			nv++;
		}
		tv[c] = found;
	}
	free(tab);
	*pp = p;
	*tvp = tv;
	return nv;
}
