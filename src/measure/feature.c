/*
 * feature.c - what measure reports about one feature (a hole, a space or a
 * line through a given point): its CD at each height, the sidewall angle
 * between the lowest and highest heights, the resist loss beside it and
 * whether it clears.  The geometry (sections, spans, areas, vertical
 * profiles) is the library's surf module; this file only decides which
 * figures a lithographer reads off it.
 */
#include "measure.h"
#include "budget.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>

/* Heights at the substrate are taken this fraction of the resist
 * thickness above it: the substrate itself is a face of the surface
 * (etch stops nodes there), and a section along a face belongs to the
 * side above it.  1e-6 of 0.7 um is 0.7 pm, far below any CD error. */
#define SUBSTRATE_LIFT 1e-6

/* Lines per hole for its area: the spacing is the hole's smaller extent
 * over HOLE_LINES (at most the box's side over BOX_LINES, at least over
 * MAX_LINES).  The midpoint rule across lines errs by about
 * (1/HOLE_LINES)^1.5 of the area on a round hole: 1.3e-4. */
enum { HOLE_LINES = 400, BOX_LINES = 2048, MAX_LINES = 65536 };

/* Seconds a triangle test of the ray test (surf_above), bisections of
 * disagreeing samples included, measured on the development machine
 * (2020 x86-64) with 300 random triangles measured with -force. */
static const double T_TEST = 6e-8;

static double lift(const struct surf *s, double z)
{
	double zlo = s->box[4] + SUBSTRATE_LIFT * (s->box[5] - s->box[4]);
	return z < zlo ? zlo : z;
}

double feature_height(const struct surf *s, double z) { return lift(s, z); }

static int box_edge(const struct surf *s, int axis, struct surf_span sp)
{
	return sp.lo <= s->box[2 * axis] || sp.hi >= s->box[2 * axis + 1];
}

static void measure_row(const struct surf *s, const struct options *o, double z,
			struct row *row)
{
	struct surf_section sec;
	row->zsec = lift(s, z);
	surf_section(s, row->zsec, &sec);
	row->z = z;
	row->cd = row->a = row->b = row->c = 0;
	row->edge = 0;
	row->rect[0] = row->rect[1] = o->x;
	row->rect[2] = row->rect[3] = o->y;
	if (o->kind == HOLE) {
		struct surf_span sx = surf_span_at(s, &sec, 0, o->y, o->x);
		struct surf_span sy = surf_span_at(s, &sec, 1, o->x, o->y);
		if (!sx.resist) {
			double ex = sx.hi - sx.lo, ey = sy.hi - sy.lo;
			double wy = s->box[3] - s->box[2];
			double h = fmin(wy / BOX_LINES, fmin(ex, ey) / HOLE_LINES);
			h = fmax(h, wy / MAX_LINES);
			/* a surface measured with -force crosses itself: its spans
			 * say little about the hole's size, so no finer than the
			 * box's lines, and the search within the estimate */
			if (o->force)
				h = fmax(h, wy / BOX_LINES);
			char what[96];
			double spans, tests = surf_region_tests(s, &sec, h, &spans);
			snprintf(what, sizeof what, "the hole's area at z = %g: %.3g triangle tests", z,
				 tests);
			budget_check(o->input, what, tests * T_TEST, spans * 2 * sizeof(struct surf_span));
			struct surf_region_box rg;
			surf_region_box(s, &sec, o->x, o->y, h, &rg);
			row->cd = sqrt(4 * rg.area / M_PI);
			row->a = rg.area;
			row->b = ex;
			row->c = ey;
			row->edge = rg.edge;
			/* the region, and the extents through the point (a
			 * line along y may reach a little past the bands) */
			row->rect[0] = fmin(rg.bbox[0], sx.lo);
			row->rect[1] = fmax(rg.bbox[1], sx.hi);
			row->rect[2] = fmin(rg.bbox[2], sy.lo);
			row->rect[3] = fmax(rg.bbox[3], sy.hi);
		}
	} else {
		double c = o->axis == 0 ? o->y : o->x, t = o->axis == 0 ? o->x : o->y;
		struct surf_span sp = surf_span_at(s, &sec, o->axis, c, t);
		if (sp.resist == (o->kind == LINE)) {
			row->cd = sp.hi - sp.lo;
			row->a = sp.lo;
			row->b = sp.hi;
			row->edge = box_edge(s, o->axis, sp);
			row->rect[2 * o->axis] = sp.lo;
			row->rect[2 * o->axis + 1] = sp.hi;
		}
	}
	surf_section_free(&sec);
}

/* The top of the resist beside the feature along one line: for a line,
 * over the line itself; for a space or hole, over one feature width on
 * each side of it.  lo..hi is the feature's interval (lo > hi: absent,
 * then the whole line). */
static double top_beside(const struct surf *s, enum kind kind, int axis, double c,
			 double lo, double hi)
{
	double b0 = s->box[2 * axis], b1 = s->box[2 * axis + 1];
	if (lo > hi)
		return surf_top_along(s, axis, c, b0, b1);
	if (kind == LINE)
		return surf_top_along(s, axis, c, lo, hi);
	double w = hi - lo;
	double t0 = surf_top_along(s, axis, c, fmax(b0, lo - w), lo);
	double t1 = surf_top_along(s, axis, c, hi, fmin(b1, hi + w));
	return fmax(t0, t1);
}

/* The feature's interval along a line at the row of r chosen for the
 * resist loss: the highest height where a hole or space is open, the
 * lowest where a line stands (its foot). */
static int pick_row(const struct options *o, const struct result *r)
{
	int best = -1;
	for (int i = 0; i < r->nrows; i++) {
		if (!(r->rows[i].cd > 0))
			continue;
		if (best < 0 || (o->kind == LINE ? r->rows[i].z < r->rows[best].z
						 : r->rows[i].z > r->rows[best].z))
			best = i;
	}
	return best;
}

static double resist_loss(const struct surf *s, const struct options *o,
			  const struct result *r)
{
	int i = pick_row(o, r);
	double top;
	if (o->kind == HOLE) {
		/* the hole's intervals through the point along x and y */
		struct surf_section sec;
		double tx, ty;
		if (i >= 0) {
			surf_section(s, lift(s, r->rows[i].z), &sec);
			struct surf_span sx = surf_span_at(s, &sec, 0, o->y, o->x);
			struct surf_span sy = surf_span_at(s, &sec, 1, o->x, o->y);
			surf_section_free(&sec);
			tx = top_beside(s, HOLE, 0, o->y, sx.lo, sx.hi);
			ty = top_beside(s, HOLE, 1, o->x, sy.lo, sy.hi);
		} else {
			tx = top_beside(s, HOLE, 0, o->y, 1, 0);
			ty = top_beside(s, HOLE, 1, o->x, 1, 0);
		}
		top = fmax(tx, ty);
	} else {
		double c = o->axis == 0 ? o->y : o->x;
		double lo = i >= 0 ? r->rows[i].a : 1, hi = i >= 0 ? r->rows[i].b : 0;
		top = top_beside(s, o->kind, o->axis, c, lo, hi);
	}
	double loss = s->box[5] - top;
	return loss > 0 ? loss : 0;
}

/* Whether the opening reaches the substrate: for a hole or space, the
 * point just above the substrate is developed; for a line, its foot ends
 * inside the box on both sides (developed resist beside it). */
static int cleared(const struct surf *s, const struct options *o)
{
	double zb = lift(s, s->box[4]);
	if (o->kind != LINE)
		return !(surf_above(s, o->x, o->y, zb) & 1);
	struct surf_section sec;
	surf_section(s, zb, &sec);
	double c = o->axis == 0 ? o->y : o->x, t = o->axis == 0 ? o->x : o->y;
	struct surf_span sp = surf_span_at(s, &sec, o->axis, c, t);
	surf_section_free(&sec);
	return !sp.resist || !box_edge(s, o->axis, sp);
}

void measure_feature(const struct surf *s, const struct options *o,
		     const double *z, struct result *r)
{
	r->nrows = o->nh;
	r->rows = xcalloc((size_t)o->nh, sizeof *r->rows);
	for (int i = 0; i < o->nh; i++)
		measure_row(s, o, z[i], &r->rows[i]);
	/* sidewall angle between the lowest and highest heights */
	int lo = 0, hi = 0;
	for (int i = 1; i < o->nh; i++) {
		if (z[i] < z[lo])
			lo = i;
		if (z[i] > z[hi])
			hi = i;
	}
	double dz = z[hi] - z[lo];
	r->have_swa = o->nh >= 2 && dz > 0;
	r->swa_known = r->have_swa && r->rows[lo].cd > 0 && r->rows[hi].cd > 0;
	r->swa = 0;
	if (r->swa_known) {
		/* a line narrowing upwards and a hole or space widening upwards
		 * both have walls below 90 degrees */
		double d = o->kind == LINE ? r->rows[lo].cd - r->rows[hi].cd
					   : r->rows[hi].cd - r->rows[lo].cd;
		r->swa = 90 - atan(0.5 * d / dz) * 180 / M_PI;
	}
	r->resist_loss = resist_loss(s, o, r);
	r->cleared = cleared(s, o);
}
