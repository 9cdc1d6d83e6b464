/*
 * estimate.c - what a run of etch will cost, from its input alone, before
 * it starts: seconds and bytes for budget_check (budget.h), which refuses
 * beyond an hour or the machine's memory unless -big.  The costs per
 * operation are measured constants: re-measure them when an engine gets
 * much faster or slower.
 */
#include "budget.h"
#include "etch.h"

#include <math.h>
#include <stdio.h>

/* Seconds of one core per triangle and time step of the ray-string
 * engine, per rate point read and made into the rate field (the whole
 * of a run of one step), and per (refined) grid node of fast marching,
 * measured on the development machine with the contact's rate on 51^2 x
 * 300 and 201^2 x 150 points (tests/bench/estimate.sh prints them beside
 * the runs: 1.0e-7 to 1.5e-7 s a triangle and step, 6e-8 s a rate point,
 * 1.4e-6 s a node); bytes per triangle (with its nodes and segments) and
 * per fast-marching node. */
static const double T_TRI_STEP = 1.2e-7, T_RATE = 7e-8, T_FMM_NODE = 1.5e-6;
static const double B_TRI = 400, B_FMM_NODE = 48;

/* The estimate of the run before it starts (budget.h): time steps times
 * the triangles of the start, or the refined grid of fast marching. */
void etch_estimate(const struct ratefile *r, const struct rfield *f,
		   const struct etch_opts *o)
{
	char what[128];
	double secs, bytes;
	double sets = o->pt > 0 ? ceil(o->et / o->pt) : 1;
	if (o->method == METHOD_FMM || o->xcheck) {
		int refine[3];
		etch_fmm_refinement(r, o, refine);
		double pts = (double)r->nx * r->ny * r->nz * refine[0] * refine[1] * refine[2];
		snprintf(what, sizeof what, "%.3g fast-marching nodes", pts);
		budget_check(o->input, what, pts * T_FMM_NODE, pts * B_FMM_NODE + sets * 16);
		if (o->method == METHOD_FMM)
			return;
	}
	double seg = o->seg > 0 ? o->seg : etch_default_seg(f);
	double dt = o->dt > 0 ? o->dt : etch_default_dt(f, seg, o->et);
	double steps = fmax(o->et / dt, sets);
	double wx = f->hi[0] - f->lo[0], wy = f->hi[1] - f->lo[1], wz = f->hi[2] - f->lo[2];
	double tris = o->seed ? 20.0 * o->seed : 2 * (wx / seg + 1) * (wy / (seg * sqrt(3) / 2) + 1);
	double bound = ETCH_MESH_FACTOR * 2 * (wx * wy + wx * wz + wy * wz) / (sqrt(3) / 4 * seg * seg);
	secs = steps * tris * T_TRI_STEP + (double)r->nx * r->ny * r->nz * T_RATE;
	bytes = fmin(bound, 1e9) * B_TRI + sets * 16;
	snprintf(what, sizeof what, "%.3g time steps of a mesh of %.3g triangles", steps, tris);
	budget_check(o->input, what, secs, bytes);
}
