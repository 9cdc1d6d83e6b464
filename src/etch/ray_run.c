/*
 * ray_run.c - the time loop of the ray-string algorithm (thesis 8.3): from the
 * initial surface, repeat [I] advance every node along its ray, [II] cut
 * and merge segments, [III] clip every n steps, [IV] deloop if asked
 * (deloop.h: at every print time, and every n steps with -deloop n),
 * until the etch time; write a set of plot curves at every print time.
 *
 * Steps are equal within each print interval and end exactly on the
 * print times.  The default step follows thesis 7.4.1: |grad R| dt < 1
 * keeps the rays from reflecting ([7.4]); ETCH_DT_GRAD of that bound is
 * used, and no node may move more than an ideal segment length in a step,
 * so that mesh modification keeps pace with the front.
 */
#include "etch.h"

#include "checked.h"
#include "deloop.h"
#include "fmm.h"
#include "progress.h"
#include "util.h"

#include <limits.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* A maximum of the standing waves stands this far above the minima
 * beside it in ln R (a factor 1.65 in rate): the scallops of an unbaked
 * resist swing by several units, a baked one's ripple by less. */
#define ETCH_SW_SWING 0.5
/* Segment length per standing-wave period: 0.4 of the unbaked contact's
 * 0.13 um period makes 0.1 um grid cells two segments, 0.05 um, where
 * 0.1 um lagged (standing_wave_period). */
#define ETCH_SEG_PER_PERIOD 0.4

/* The period (um) of the standing waves of the rates along z: in the
 * column where ln R swings most, the mean distance between successive
 * maxima of R that stand more than ETCH_SW_SWING in ln R above the
 * minima between them; 0 if there are fewer than two (a baked resist,
 * a uniform one).  A mesh whose segments are longer than a fraction of
 * it cannot follow the scallops: on the unbaked contact of
 * examples/contact (period 0.13 um) at 60 s, 0.1 um segments leave the
 * walls 0.1-0.2 um (up to two cells) inside the fast-marching ones along
 * y = 0, and the deloop classifier then takes whole patches of that
 * lagging front for loops (the hole deleted below z = -0.136);
 * 0.05 um segments put them within 0.03 um. */
static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static double standing_wave_period(const struct rfield *f)
{
	size_t plane = (size_t)f->n[0] * (size_t)f->n[1], best = 0;
	double swing = 0;
	for (size_t q = 0; q < plane; q++) {
		double lo = INFINITY, hi = -INFINITY;
		for (int k = 0; k < f->n[2]; k++) {
			double v = f->v[(size_t)k * plane + q];
			if (v >= FMM_RATE_FLOOR) {
				lo = fmin(lo, log(v));
				hi = fmax(hi, log(v));
			}
		}
		if (hi - lo > swing) {
			swing = hi - lo;
			best = q;
		}
	}
	/* maxima separated by dips of more than ETCH_SW_SWING; the median
	 * distance between successive ones (a dip too shallow merges two
	 * periods into one) */
	double *zmax = xreallocarray(NULL, (size_t)f->n[2] + 1, sizeof *zmax);
	double top = -INFINITY, dip = INFINITY, last = 0;
	int nmax = 0, rising = 1;
	for (int k = 0; k < f->n[2]; k++) {
		double v = f->v[(size_t)k * plane + best];
		double l = v >= FMM_RATE_FLOOR ? log(v) : -INFINITY;
		double z = f->lo[2] + k * f->h[2];
		if (rising) {
			if (l > top) {
				top = l;
				last = z;
			} else if (top - l > ETCH_SW_SWING) {
				zmax[nmax++] = last;
				rising = 0;
				dip = l;
			}
		} else if (l < dip) {
			dip = l;
		} else if (l - dip > ETCH_SW_SWING) {
			rising = 1;
			top = l;
			last = z;
		}
	}
	for (int i = 0; i + 1 < nmax; i++)
		zmax[i] = zmax[i + 1] - zmax[i];
	double period = 0;
	if (nmax >= 2) {
		qsort(zmax, (size_t)nmax - 1, sizeof *zmax, cmp_double);
		period = zmax[(nmax - 1) / 2];
	}
	free(zmax);
	return period;
}

/* The longer horizontal side / ETCH_SEG_DIVISIONS, but no longer than the
 * rate grid's horizontal spacing: a mesh coarser than the grid cannot
 * follow what the grid resolves.  On the thesis' contact without bake
 * (5 um box, 0.1 um grid, standing-wave period 0.13 um) box / 30 =
 * 0.167 um gave half the developed volume (0.68 against 1.40 um3
 * converged); 0.1 um gives 1.22.  Where the rates have standing waves
 * (above), the spacing divided by the least whole number that brings it
 * under ETCH_SEG_PER_PERIOD of their period. */
double etch_default_seg(const struct rfield *f)
{
	double w = fmax(f->hi[0] - f->lo[0], f->hi[1] - f->lo[1]);
	double h = fmax(f->h[0], f->h[1]);
	double p = standing_wave_period(f);
	/* a whole number of segments per grid cell, so that the deloop
	 * classifier's grid (deloop_classifier: cells of two segments or
	 * less) need not be refined laterally at 0.05 um on a 0.1 um grid */
	if (p > 0 && h > ETCH_SEG_PER_PERIOD * p)
		h /= ceil(h / (ETCH_SEG_PER_PERIOD * p));
	return fmin(w / ETCH_SEG_DIVISIONS, h);
}

double etch_default_dt(const struct rfield *f, double seg, double et)
{
	double dt = et;
	if (f->gmax > 0 && ETCH_DT_GRAD / f->gmax < dt)
		dt = ETCH_DT_GRAD / f->gmax;
	if (f->rmax > 0 && seg / f->rmax < dt)
		dt = seg / f->rmax;
	return dt;
}

static void check(const struct mesh *m, long step)
{
	const char *err = mesh_check(m);
	if (err)
		die("internal error: mesh inconsistent after step %ld: %s", step, err);
}

static void note_size(const struct mesh *m, struct etch_stats *st)
{
	if ((long)m->live_node > st->max_nodes)
		st->max_nodes = (long)m->live_node;
	if ((long)m->live_tri > st->max_tris)
		st->max_tris = (long)m->live_tri;
}

static void deloop_now(struct mesh *m, struct fmm *fm, const struct rfield *f,
		       double t, struct etch_stats *st)
{
	clock_t c0 = clock();
	struct deloop_report rep;
	deloop_run(m, fm, f, t, &rep);
	st->deloops++;
	st->loops += rep.loops;
	st->looped_tris += rep.removed_tris;
	st->crossings_left = rep.left;
	st->seam_joined += rep.joined;
	st->open_cut = rep.open_cut;
	st->open_left = rep.open_left;
	st->deloop_s += (double)(clock() - c0) / CLOCKS_PER_SEC;
}

/* The surface written at a print time with -deloop: a copy of the mesh,
 * delooped unless -deloop n has just delooped it (deloop_now), with its
 * open border closed (deloop_close_open).  The mesh that goes on
 * advancing keeps its loops: delooped in place at each print time it
 * kept the seams of the earlier deloops open (closing them in place
 * folded the closing's triangles into later steps), later fronts passed
 * through those gaps, and the unbaked contact with -pt 20 kept 8.3 um of
 * open border at 60 s (0 delooped once); a dense array of unbaked 1.0 um
 * holes came out 0.49 by 0.45 um wide at 90 % height against 0.66 both
 * ways by fast marching, and the 1.25 um array's closing rounds at 40 s
 * ran for minutes on the gaps.  A loop does not change the rays (they do
 * not depend on the surface), so the front advanced with its loops is
 * the same front, and each set is the surface a single deloop at its
 * time gives. */
static struct mesh *closed_copy(const struct mesh *m, struct fmm *fm,
				const struct rfield *f, double t, int fresh,
				struct etch_stats *st)
{
	struct mesh *c = mesh_copy(m);
	if (fresh) {
		deloop_now(c, fm, f, t, st);
		mesh_compact(c);
	}
	clock_t c0 = clock();
	struct deloop_report rep;
	memset(&rep, 0, sizeof rep);
	rep.left = st->crossings_left;
	rep.open_left = st->open_left;
	deloop_close_open(c, fm, f, t, &rep);
	mesh_compact(c);
	st->open_left = rep.open_left;
	st->open_worst = fmax(st->open_worst, rep.open_left);
	st->deloop_s += (double)(clock() - c0) / CLOCKS_PER_SEC;
	return c;
}

struct mesh *etch_run(const struct rfield *f, const struct etch_opts *o,
		      struct etch_stats *st)
{
	double seg = o->seg > 0 ? o->seg : etch_default_seg(f);
	st->seg = seg;
	if (o->seg > 0 && o->deloop && !o->quiet) {
		double p = standing_wave_period(f);
		if (p > 0 && o->seg > ETCH_SEG_PER_PERIOD * p * (1 + 1e-9))
			fprintf(stderr, "%s: warning: -seg %g is coarse for the standing waves "
				"(period %.3g um): the front will lag them and -deloop may take it "
				"for loops; the default is %g\n", util_prog(), o->seg, p,
				etch_default_seg(f));
	}
	st->dt_grad = f->gmax > 0 ? 1 / f->gmax : 0;
	st->dt = o->dt > 0 ? o->dt : etch_default_dt(f, seg, o->et);
	/* the bound of the mesh (ETCH_MESH_FACTOR) */
	double wx = f->hi[0] - f->lo[0], wy = f->hi[1] - f->lo[1], wz = f->hi[2] - f->lo[2];
	double faces = 2 * (wx * wy + wx * wz + wy * wz);
	st->max_live_tri = (long)fmin(ETCH_MESH_FACTOR * faces / (sqrt(3) / 4 * seg * seg) + 1000, 1e9);
	struct progress prog;
	progress_begin(&prog, "time steps", o->quiet);
	struct mesh *m = mesh_new();
	for (int k = 0; k < o->seed; k++)
		start_seed(m, o->seedp[k]);
	if (!o->seed)
		start_flat(m, f, seg);
	if (o->check)
		check(m, 0);
	deloop_set_check(o->check);
	note_size(m, st);
	struct etch_out *out = out_open(o, f);
	struct fmm *fm = NULL;
	if (o->deloop) {
		clock_t c0 = clock();
		if (!o->rate)
			die("internal error: -deloop without the rate array");
		fm = deloop_classifier(o->rate, seg, o->seed ? &o->seedp[0][0] : NULL, o->seed);
		st->deloop_fmm_s = (double)(clock() - c0) / CLOCKS_PER_SEC;
		st->deloop_s += st->deloop_fmm_s;
	}
	double t = 0;
	long since_clip = 0;
	for (long k = 1;; k++) {
		/* print times pt, 2 pt, ... and the etch time, hit exactly */
		double tp = o->pt > 0 ? k * o->pt : o->et;
		if (tp > o->et * (1 - 1e-12))
			tp = o->et;
		double span = tp - t;
		/* checked: a huge rate gives a step count beyond a long */
		long n = ck_long(ceil(span / st->dt * (1 - 1e-12)), LONG_MIN / 2, LONG_MAX / 2,
				 "time steps");
		if (n < 1)
			n = 1;
		for (long i = 1; i <= n; i++) {
			/* each step of span / n, the last ending on tp exactly */
			double h = i < n ? span / n : tp - (t + (n - 1) * (span / n));
			advance_mesh(m, f, h, o, st);
			modify_mesh(m, f, seg, o, st);
			if (++since_clip >= o->clip_every || i == n) {
				clip_mesh(m, f, st);
				since_clip = 0;
			}
			/* the advancing mesh is delooped only with -deloop n (every
			 * n steps and at the print times); otherwise each print
			 * time's set is delooped on a copy (below) */
			if (fm && o->deloop_every > 0 &&
			    (i == n || (st->steps + 1) % o->deloop_every == 0))
				deloop_now(m, fm, f, i < n ? t + i * (span / n) : tp, st);
			/* compaction rewrites the arrays from the first dead slot on:
			 * done when the dead are many, and before a print and a
			 * deloop pass; it keeps the live objects' order, which is all
			 * the other passes see, so the result does not change */
			if (i == n || (fm && (i == n - 1 || (o->deloop_every > 0 &&
						(st->steps + 2) % o->deloop_every == 0))) ||
			    mesh_dead_share(m) > MESH_DEAD_SHARE)
				mesh_compact(m);
			st->steps++;
			note_size(m, st);
			if ((long)m->live_tri > 2 * st->max_live_tri) {
				/* freed first: die exits at once, and the leak checker
				 * of the sanitizer runs would count the mesh */
				double tnow = t + i * (span / n);
				mesh_free(m);
				die("%s: at t = %g s the mesh grew past its bound of %ld triangles "
				    "(%d times the box's faces in S_ideal triangles): the rate varies "
				    "faster than S_ideal %g um resolves (a spike?); try -method fmm",
				    o->input ? o->input : "etch", tnow,
				    2 * st->max_live_tri, ETCH_MESH_FACTOR, seg);
			}
			if (o->check)
				check(m, st->steps);
			progress_step(&prog, t + i * (span / n), o->et);
		}
		t = tp;
		struct mesh *shown = m;
		if (fm && (!o->last || tp >= o->et)) {
			shown = closed_copy(m, fm, f, tp, o->deloop_every <= 0, st);
			if (o->check)
				check(shown, st->steps);
		}
		if (!o->last || tp >= o->et)    /* -last: only the final set */
			out_write(out, shown);
		if (shown != m && tp >= o->et) {
			mesh_free(m);
			m = shown;
		} else if (shown != m) {
			mesh_free(shown);
		}
		if (!o->quiet)
			fprintf(stderr, "%s: t = %g s: %zu nodes, %zu triangles\n",
				util_prog(), t, m->live_node, m->live_tri);
		if (tp >= o->et)
			break;
	}
	out_close(out);
	/* the classifier marches as the deloops query it (fmm_solve_lazy):
	 * its time is the setup's and the march's, within deloop_s */
	if (fm)
		st->deloop_fmm_s += fm->march_s;
	fmm_free(fm);
	return m;
}

void etch_report(const struct etch_opts *o, const struct rfield *f,
		 const struct mesh *m, const struct etch_stats *st)
{
	if (!o->quiet && st->capped)
		fprintf(stderr, "%s: the mesh reached its bound of %ld triangles "
			"(%d times the box's faces): %ld cuts not made; the rate "
			"varies faster than S_ideal %g um resolves\n", util_prog(),
			st->max_live_tri, ETCH_MESH_FACTOR, st->capped, st->seg);
	if (!o->quiet) {
		fprintf(stderr, "%s: done: %g s in %ld steps of %g s (%s); S_ideal %g um\n",
			util_prog(), o->et, st->steps, st->dt,
			o->dt > 0 ? "-dt" : "default: 0.25 / max|grad R|, at most S_ideal / max R",
			st->seg);
		fprintf(stderr, "%s: max|grad R| %g /s, max R %g um/s; %ld ray substeps, "
			"%ld recursive halvings\n", util_prog(), f->gmax, f->rmax,
			st->substeps, st->halvings);
		fprintf(stderr, "%s: final mesh %zu nodes, %zu segments, %zu triangles "
			"(largest %ld nodes, %ld triangles)\n", util_prog(),
			m->live_node, m->live_seg, m->live_tri, st->max_nodes, st->max_tris);
		fprintf(stderr, "%s: %ld cuts, %ld merges (%ld refused), %ld clips removing "
			"%ld triangles, %ld nodes stopped at the substrate\n",
			util_prog(), st->cuts, st->merges, st->refused, st->clips,
			st->clipped_tris, st->stopped);
		if (o->deloop)
			fprintf(stderr, "%s: deloop: %ld passes removed %ld loops (%ld "
				"triangles) in %.3g s (classifier %.3g s); %ld crossings "
				"left, %ld seam segments joined, %.3g um of border left "
				"open (the most of any set written)\n", util_prog(), st->deloops,
				st->loops, st->looped_tris, st->deloop_s, st->deloop_fmm_s,
				st->crossings_left, st->seam_joined, st->open_worst);
	}
}
