/*
 * lcdu.c - the local CD uniformity of an array of holes at one height:
 * every developed region of the section that the box edge does not cut
 * is a hole; its CD is the diameter of the circle of its area, as -hole
 * measures one hole, and the LCDU is 3 times the sample standard
 * deviation (n - 1) of the CDs.
 *
 * The section is read on lines parallel to x (surf_regions): first
 * HOLE_SCAN of them to find the holes, then, as for -hole, enough that
 * the smallest hole's smaller extent holds HOLE_LINES of them (at most
 * MAX_LINES over the box), which puts each hole's area within about 1e-4
 * (the midpoint rule across the lines on a round hole).
 */
#include "rough.h"
#include "surf_lines.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>

enum { HOLE_SCAN = 2048, HOLE_LINES = 400, MAX_LINES = 65536 };

/* The holes among the nreg regions (those not cut by the box edge). */
static size_t holes_of(const struct surf_region *reg, size_t nreg, struct measure_hole *h)
{
	size_t n = 0;
	for (size_t i = 0; i < nreg; i++)
		if (!reg[i].edge)
			h[n++] = (struct measure_hole){reg[i].cx, reg[i].cy, sqrt(4 * reg[i].area / M_PI)};
	return n;
}

static int by_y(const void *p, const void *q)
{
	const struct measure_hole *a = p, *b = q;
	return (a->y > b->y) - (a->y < b->y);
}

static int by_x(const void *p, const void *q)
{
	const struct measure_hole *a = p, *b = q;
	return (a->x > b->x) - (a->x < b->x);
}

/* Rows of increasing y, each by x: a row is a run of holes (by y) whose
 * centroids lie within half the smallest CD of its first hole's y. */
static void order(struct measure_hole *h, size_t n)
{
	qsort(h, n, sizeof *h, by_y);
	for (size_t a = 0, b; a < n; a = b) {
		double cdmin = h[a].cd;
		for (b = a + 1; b < n && h[b].y - h[a].y < 0.5 * fmin(cdmin, h[b].cd); b++)
			cdmin = fmin(cdmin, h[b].cd);
		qsort(h + a, b - a, sizeof *h, by_x);
	}
}

void lcdu_measure(const struct surf *s, double z, struct lcdu *l)
{
	struct surf_section sec;
	surf_section(s, feature_height(s, z), &sec);
	struct surf_region *reg;
	size_t nreg = surf_regions(s, &sec, HOLE_SCAN, &reg);
	/* the lines the smallest hole needs */
	double wy = s->box[3] - s->box[2], hy = wy / HOLE_SCAN, need = HOLE_SCAN;
	for (size_t i = 0; i < nreg; i++)
		if (!reg[i].edge) {
			double ext = fmin(reg[i].xhi - reg[i].xlo, reg[i].yhi - reg[i].ylo + hy);
			need = fmax(need, ceil(wy * HOLE_LINES / ext));
		}
	if (need > HOLE_SCAN) {
		free(reg);
		nreg = surf_regions(s, &sec, (size_t)fmin(need, MAX_LINES), &reg);
	}
	surf_section_free(&sec);
	l->holes = xreallocarray(NULL, nreg ? nreg : 1, sizeof *l->holes);
	l->n = holes_of(reg, nreg, l->holes);
	free(reg);
	order(l->holes, l->n);
	l->lcdu = -1;
	if (l->n >= 2) {
		double mean = 0, ss = 0;
		for (size_t i = 0; i < l->n; i++)
			mean += l->holes[i].cd;
		mean /= (double)l->n;
		for (size_t i = 0; i < l->n; i++)
			ss += (l->holes[i].cd - mean) * (l->holes[i].cd - mean);
		l->lcdu = 3 * sqrt(ss / (double)(l->n - 1));
	}
}

void lcdu_free(struct lcdu *l)
{
	free(l->holes);
	l->holes = NULL;
	l->n = 0;
}
