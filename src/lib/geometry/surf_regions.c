/*
 * surf_regions.c - every developed region of a horizontal section: the
 * holes of an array at one height (see surf_lines.h).
 *
 * The section is read on lines parallel to x at the middles of equal
 * bands of the box's y side, as surf_region_area reads one region: each
 * developed span stands for the band of its line (the midpoint rule
 * across the lines, exact along them), and spans on neighbouring lines
 * that overlap are joined into one region (union-find).  Area, centroid
 * and extents are summed per region in the order of the spans, line by
 * line, so the figures do not depend on the thread count.
 */
#include "surf_lines.h"
#include "unionfind.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>


/* The developed spans of all lines, line after line: dev[lstart[l] ..
 * lstart[l + 1] - 1] are line l's, ascending in x.  Returns dev. */
static struct surf_span *developed(const struct surf_line *lines, size_t nl, size_t *lstart,
				   size_t *ndev)
{
	struct surf_span *dev = NULL;
	size_t cap = 0;
	*ndev = 0;
	for (size_t l = 0; l < nl; l++) {
		lstart[l] = *ndev;
		for (size_t k = 0; k < lines[l].n; k++)
			if (!lines[l].sp[k].resist) {
				xgrow(&dev, &cap, *ndev + 1, sizeof *dev);
				dev[(*ndev)++] = lines[l].sp[k];
			}
	}
	lstart[nl] = *ndev;
	return dev;
}

/* Joins the spans of neighbouring lines that overlap along x. */
static void join_lines(const struct surf_span *dev, const size_t *lstart, size_t nl,
		       size_t *parent)
{
	for (size_t l = 0; l + 1 < nl; l++) {
		size_t a = lstart[l], b = lstart[l + 1];
		while (a < lstart[l + 1] && b < lstart[l + 2]) {
			if (fmax(dev[a].lo, dev[b].lo) < fmin(dev[a].hi, dev[b].hi))
				uf_join(parent, a, b);
			if (dev[a].hi < dev[b].hi)
				a++;
			else
				b++;
		}
	}
}

size_t surf_regions(const struct surf *s, const struct surf_section *sec, size_t nl,
		    struct surf_region **out)
{
	const double *box = s->box;
	double hy = (box[3] - box[2]) / (double)nl;
	double *c = xreallocarray(NULL, nl ? nl : 1, sizeof *c);
	for (size_t l = 0; l < nl; l++)
		c[l] = box[2] + ((double)l + 0.5) * hy;
	struct surf_line *lines = surf_lines_spans(s, sec, 0, c, nl);
	size_t *lstart = xreallocarray(NULL, nl + 1, sizeof *lstart), ndev;
	struct surf_span *dev = developed(lines, nl, lstart, &ndev);
	surf_lines_free(lines, nl);

	size_t *parent = xreallocarray(NULL, ndev ? ndev : 1, sizeof *parent);
	for (size_t k = 0; k < ndev; k++)
		parent[k] = k;
	join_lines(dev, lstart, nl, parent);

	/* region numbers in order of each region's first span; a root is
	 * its region's smallest span index, so it is met first */
	size_t *id = xreallocarray(NULL, ndev ? ndev : 1, sizeof *id), nreg = 0;
	struct surf_region *reg = NULL;
	size_t cap = 0;
	for (size_t l = 0; l < nl; l++)
		for (size_t k = lstart[l]; k < lstart[l + 1]; k++) {
			size_t root = uf_find(parent, k);
			if (root == k) {
				xgrow(&reg, &cap, nreg + 1, sizeof *reg);
				reg[nreg] = (struct surf_region){0, 0, 0, dev[k].lo, dev[k].hi,
								 c[l], c[l], 0};
				id[k] = nreg++;
			} else {
				id[k] = id[root];
			}
			struct surf_region *g = &reg[id[k]];
			double w = dev[k].hi - dev[k].lo, a = w * hy;
			g->area += a;
			g->cx += a * 0.5 * (dev[k].lo + dev[k].hi);
			g->cy += a * c[l];
			g->xlo = fmin(g->xlo, dev[k].lo);
			g->xhi = fmax(g->xhi, dev[k].hi);
			g->yhi = c[l];
			if (dev[k].lo <= box[0] || dev[k].hi >= box[1] || l == 0 || l + 1 == nl)
				g->edge = 1;
		}
	for (size_t i = 0; i < nreg; i++)
		if (reg[i].area > 0) {
			reg[i].cx /= reg[i].area;
			reg[i].cy /= reg[i].area;
		}
	free(id);
	free(parent);
	free(dev);
	free(lstart);
	free(c);
	*out = reg;
	return nreg;
}
