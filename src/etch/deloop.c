/*
 * deloop.c - mesh delooping (thesis 7.5.3, 8.4.3), the passes of a run:
 * from the self-intersections (deloop_grid.c, deloop_near.c), split the
 * mesh into patches along the intersection curves, classify each patch by
 * the arrival time of the fast-marching engine, cut the crossing segments
 * on the curves, delete the loop patches and join the cut sheets
 * (deloop_zip.c); then the local passes for what is left, and the
 * classifier's solve.  See deloop.h for the design.
 *
 * The thesis' pass tested all pairs of triangles (O(N^2)), decided which
 * side of an intersection to delete from the motion of the two triangles,
 * and so broke on pinwheeling triangles and on three or more triangles
 * crossing at one place, and on a real contact deleted most of the mesh
 * (Figure 8.19).  Here the only per-crossing geometry is the exact
 * segment/triangle crossing; what to delete is a volumetric verdict per
 * patch.
 */
#include "deloop_grid.h"

#include "fmm.h"
#include "rfield.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A patch is a loop when the median of its nodes' signed distances to the
 * fast-marching front is below minus a margin: DELOOP_TOL_SPREAD times the
 * median |distance| over all the mesh's nodes (most of them are on the
 * true front, so that is the two engines' typical disagreement on this
 * mesh, and a true front patch's median is of that size), but at least
 * DELOOP_TOL_MIN and at most DELOOP_TOL_MAX cells of the classifier's grid
 * (the engines agree to half a cell in median at the refinement of
 * fmm_auto_refine, the cross-check of etch -xcheck). */
#define DELOOP_TOL_SPREAD 4.0
#define DELOOP_TOL_MIN 0.05
#define DELOOP_TOL_MAX 1.0
/* A cut node the joining (deloop_zip.c) leaves open is moved this
 * fraction of the way back from the crossing towards the kept node: the
 * kept sheets end on chords of the curved intersection curve, and two
 * chords of the same curve, one in each sheet, would otherwise cross each
 * other by a rounding-sized or curvature-sized margin.  A tenth of a
 * segment leaves a gap under 0.1 S_max between the sheets (well inside
 * the 2-segment and 1% checks). */
#define DELOOP_PULLBACK 0.1
/* The classifier's cells may be this many ideal segments across before
 * its grid is refined laterally: the margin follows the engines' actual
 * disagreement (DELOOP_TOL_SPREAD), which on the rate grids of bleach is
 * a small fraction of a cell, so a cell of two segments still resolves
 * loops a segment deep. */
#define DELOOP_CELL_SEGS 2.0
/* ... but by at most this factor per axis for that reason (memory and
 * time grow with its cube; z refinement for standing waves is separate,
 * fmm_auto_refine). */
#define DELOOP_MAX_REFINE 4
/* Largest classifier grid (nodes): 8 bytes each, and fast marching at a
 * few million nodes a second. */
#define DELOOP_MAX_FMM_NODES 4.0e7
/* Arrival times beyond this are the engine's "never reached". */
#define UNREACHED_T (0.5 * FMM_UNREACHED)
/* Passes: the patch pass, then local passes for folds shallower than the
 * margin, each on the crossings the previous left; two or three suffice
 * in every case tested, the cap bounds the work. */
#define DELOOP_PASSES 12
/* Rounds of closing the open border the passes leave (deloop_close_open): each
 * round closes what it can cleanly, then forces the rest and deloops
 * the crossings that makes; three rounds close the examples. */
#define DELOOP_CLOSE_ROUNDS 32
/* ... stopping after this many rounds that left no less border open. */
#define DELOOP_CLOSE_STALE 6
/* A round improves on the best only by closing more than this (um): a
 * round that changes nothing sums the same segments in another order,
 * and a rounding-sized "gain" restarted the count, so that the 1.25 um
 * unbaked hole array ran every one of the 32 rounds at each print time
 * on an unchanging mesh.  A millionth of a micrometre is far below any
 * segment. */
#define DELOOP_CLOSE_GAIN 1e-6

/* Local passes that first try to merge the chosen nodes away
 * (merge_away); the later ones delete them, which always progresses. */
#define DELOOP_MERGE_PASSES 6
/* ... and only nodes on or next to a seam joined in the same run, and
 * this many segment lengths or less past the other sheet: the folds a
 * join leaves at its seam are that shallow (a few hundredths of a
 * segment on the two seeds), while other folds, left by the classifier's
 * margin on rough fronts, have layers that merging one node would leave
 * in place (merged rather than deleted, they add 2-3% to the contact's
 * developed volume). */
#define DELOOP_MERGE_DEPTH 0.05

/* Cuts nearer than this fraction of the segment to the kept node are not
 * made (a near zero-length segment would come of it). */
#define MIN_CUT 1e-3

/* Union-find with path halving. */
static int find(int *up, int x)
{
	while (up[x] != x) {
		up[x] = up[up[x]];
		x = up[x];
	}
	return x;
}

/* The k-th smallest of v[0 .. n) (k < n), v partly reordered so that
 * v[0 .. k) are the smaller ones (quickselect: the median of a patch
 * without sorting it, the same value). */
static double kth_smallest(double *v, size_t n, size_t k)
{
	long lo = 0, hi = (long)n - 1, kk = (long)k;
	while (hi > lo) {
		long mid = lo + (hi - lo) / 2;
		double a = v[lo], b = v[mid], c = v[hi];
		double piv = a < b ? (b < c ? b : (a < c ? c : a)) : (a < c ? a : (b < c ? c : b));
		long i = lo, j = hi;
		while (i <= j) {
			while (v[i] < piv)
				i++;
			while (v[j] > piv)
				j--;
			if (i <= j) {
				double x = v[i];
				v[i++] = v[j];
				v[j--] = x;
			}
		}
		if (kk <= j)
			hi = j;
		else if (kk >= i)
			lo = i;
		else
			break;
	}
	return v[k];
}

/* The median of v[0 .. k) (k > 0), v reordered. */
static double median(double *v, size_t k)
{
	double b = kth_smallest(v, k, k / 2);
	if (k & 1)
		return b;
	double a = v[0];
	for (size_t i = 1; i < k / 2; i++)
		a = fmax(a, v[i]);
	return 0.5 * (a + b);
}

/* Signed distance (um) of node i to the fast-marching front at time t:
 * negative inside developed resist.  *vote 0 for nodes on the top or the
 * substrate: those are developed surface wherever a node lies on them
 * (T < t there), so they cast no vote. */
static double node_dist(const struct mesh *m, int i, struct fmm *fm,
			const struct rfield *f, double t, int *vote)
{
	const struct node *nd = &m->node[i];
	*vote = nd->alive && !(nd->flags & (ON_TOP | ON_SUB));
	if (!*vote)
		return 0;
	double tp = fmm_time_at_settled(fm, nd->p);
	if (tp >= UNREACHED_T)
		return HUGE_VAL;
	return (tp - t) * rfield_eval(f, nd->p, NULL);
}

/* The patch verdict (deloop.h, stage 2): which nodes are in loops. */
static unsigned char *classify_patches(const struct mesh *m, const struct deloop_pierce *pc,
				       size_t np, struct fmm *fm, const struct rfield *f,
				       double t, struct deloop_report *rep)
{
	size_t nn = m->nnode;
	/* patches: nodes joined by segments no other sheet crosses */
	unsigned char *cut = xcalloc(m->nseg, 1);
	for (size_t i = 0; i < np; i++)
		cut[pc[i].s] = 1;
	int *up = xreallocarray(NULL, nn, sizeof *up);
	for (size_t i = 0; i < nn; i++)
		up[i] = (int)i;
	for (size_t s = 0; s < m->nseg; s++)
		if (m->seg[s].alive && !cut[s]) {
			int a = find(up, m->seg[s].n[0]), b = find(up, m->seg[s].n[1]);
			if (a != b)
				up[a > b ? a : b] = a < b ? a : b;
		}
	free(cut);
	/* each patch's signed distances, grouped by a counting sort */
	size_t *first = xcalloc(nn + 1, sizeof *first);
	double *dist = xreallocarray(NULL, nn + 1, sizeof *dist);
	int *root = xreallocarray(NULL, nn + 1, sizeof *root);
	for (size_t i = 0; i < nn; i++) {
		int vote;
		dist[i] = node_dist(m, (int)i, fm, f, t, &vote);
		root[i] = vote ? find(up, (int)i) : -1;
		if (vote)
			first[root[i] + 1]++;
	}
	for (size_t i = 0; i < nn; i++)
		first[i + 1] += first[i];
	size_t *fill = xreallocarray(NULL, nn + 1, sizeof *fill);
	double *sorted = xreallocarray(NULL, 2 * nn + 1, sizeof *sorted);
	memcpy(fill, first, (nn + 1) * sizeof *fill);
	for (size_t i = 0; i < nn; i++)
		if (root[i] >= 0)
			sorted[fill[root[i]]++] = dist[i];
	free(fill);
	double cell = fmax(fm->h[0], fmax(fm->h[1], fm->h[2]));
	size_t nv = first[nn];
	for (size_t i = 0; i < nv; i++)
		sorted[nv + i] = fabs(sorted[i]);
	double spread = 0;
	if (nv > 0)
		spread = kth_smallest(sorted + nv, nv, nv / 2);
	double tol = fmin(fmax(DELOOP_TOL_SPREAD * spread, DELOOP_TOL_MIN * cell),
			  DELOOP_TOL_MAX * cell);
	unsigned char *loop = xcalloc(nn, 1);   /* per patch root */
	for (size_t r = 0; r < nn; r++) {
		size_t k = first[r + 1] - first[r];
		if (k == 0)
			continue;
		double med = median(sorted + first[r], k);
		if (med < -tol) {
			loop[r] = 1;
			rep->loops++;
		}
		rep->margin = tol;
	}
	free(first);
	free(dist);
	free(sorted);
	free(root);
	unsigned char *gone = xcalloc(nn, 1);  /* per node */
	for (size_t i = 0; i < nn; i++)
		if (m->node[i].alive)
			gone[i] = loop[find(up, (int)i)];
	free(loop);
	free(up);
	return gone;
}

/* The fallback for crossings left between two kept patches (a fold no
 * deeper than the margin, so both sides pass as front): of each crossing
 * segment the node deeper in developed resist goes.  Such folds lie
 * within the margin of the true front, so nothing further from it than
 * the margin is deleted. */
static unsigned char *classify_local(const struct mesh *m, const struct deloop_pierce *pc,
				     size_t np, struct fmm *fm, const struct rfield *f,
				     double t, long *folds)
{
	unsigned char *gone = xcalloc(m->nnode, 1);
	(*folds)++;
	for (size_t i = 0; i < np; i++) {
		if (i > 0 && pc[i].s == pc[i - 1].s)
			continue;
		int a = m->seg[pc[i].s].n[0], b = m->seg[pc[i].s].n[1], va, vb;
		double da = node_dist(m, a, fm, f, t, &va), db = node_dist(m, b, fm, f, t, &vb);
		if (va && (!vb || da < db)) {
			gone[a] = 1;
		} else if (vb) {
			gone[b] = 1;
		} else {
			/* a segment on the substrate (or the top) crossing
			 * another sheet: the crossed triangle's deepest voting
			 * node goes, or if none votes its last node, so that
			 * every pass makes progress */
			const struct triangle *tr = &m->tri[pc[i].t];
			int pick = tr->n[0];
			double dp = HUGE_VAL;
			for (int j = 0; j < 3; j++) {
				int v;
				double d = node_dist(m, tr->n[j], fm, f, t, &v);
				if (v && d < dp) {
					dp = d;
					pick = tr->n[j];
				} else if (dp == HUGE_VAL && tr->n[j] > pick) {
					pick = tr->n[j];
				}
			}
			gone[pick] = 1;
		}
	}
	return gone;
}

/* Stage 3: cut every crossing segment from a kept node to a gone one at
 * the crossing nearest the kept node, delete every triangle with a gone
 * node, join the two sheets along the cuts and pull back the cut nodes
 * left open. */
static void cut_and_remove(struct mesh *m, const struct deloop_pierce *pc, size_t np,
			   const unsigned char *gone, struct deloop_report *rep, int first,
			   int join, unsigned char **seam, size_t *nseam)
{
	size_t nn = m->nnode;
	/* decided before any split, as the splits add segments */
	struct { int s; double u; int kept, node; } *todo =
		xreallocarray(NULL, np + 1, sizeof *todo);
	size_t ntodo = 0;
	/* a loop node on which a crossing from a kept node ends lies on the
	 * other sheet, i.e. on the intersection curve: in the patch pass it
	 * is kept and ends its sheet there, as a kept node on the other
	 * sheet does (below).  Cutting each of its segments there instead
	 * would put several nodes at one place, which no join can pair
	 * (two seeds a radius apart: vertices of the two start meshes meet
	 * on the curve).  The local passes delete what they chose, so that
	 * each pass makes progress. */
	unsigned char *gn = xreallocarray(NULL, nn + 1, 1);
	memcpy(gn, gone, nn);
	for (size_t i = 0; first && i < np; ) {
		size_t j = i;
		while (j < np && pc[j].s == pc[i].s)
			j++;
		const struct segment *sg = &m->seg[pc[i].s];
		int g0 = gone[sg->n[0]], g1 = gone[sg->n[1]];
		if (g0 != g1) {
			double u = g0 ? 0 : 1;
			for (size_t k = i; k < j; k++)
				u = g0 ? fmax(u, pc[k].u) : fmin(u, pc[k].u);
			if ((g0 ? 1 - u : u) >= 1 - MIN_CUT)
				gn[g0 ? sg->n[0] : sg->n[1]] = 0;
		}
		i = j;
	}
	gone = gn;
	for (size_t i = 0; i < np; ) {
		size_t j = i;
		while (j < np && pc[j].s == pc[i].s)
			j++;
		const struct segment *sg = &m->seg[pc[i].s];
		int g0 = gone[sg->n[0]], g1 = gone[sg->n[1]];
		if (g0 != g1) {
			double u = g0 ? 0 : 1;
			for (size_t k = i; k < j; k++)
				u = g0 ? fmax(u, pc[k].u) : fmin(u, pc[k].u);
			/* a crossing at the kept node itself (it lies on the
			 * other sheet) is no place for a new node: the kept
			 * node ends the sheet */
			double from_kept = g0 ? 1 - u : u;
			if (from_kept > MIN_CUT) {
				todo[ntodo].s = pc[i].s;
				todo[ntodo].u = u;
				todo[ntodo].kept = g0 ? sg->n[1] : sg->n[0];
				ntodo++;
			}
		}
		i = j;
	}
	for (size_t i = 0; i < ntodo; i++) {
		int s = todo[i].s;
		double u = todo[i].u;
		const struct node *a = &m->node[m->seg[s].n[0]], *b = &m->node[m->seg[s].n[1]];
		double p[3], r[3];
		for (int d = 0; d < 3; d++) {
			p[d] = a->p[d] + u * (b->p[d] - a->p[d]);
			r[d] = a->s[d] + u * (b->s[d] - a->s[d]);
		}
		double rl = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
		for (int d = 0; d < 3; d++)
			r[d] = rl > 1e-12 ? r[d] / rl : (u < 0.5 ? a->s[d] : b->s[d]);
		unsigned fl = a->flags & b->flags & (ON_WALLS | ON_SUB);
		todo[i].node = mesh_split(m, s, p, r, fl);
		rep->cuts++;
	}
	/* new nodes (index >= nn) are kept; the kept nodes of deleted
	 * triangles and the new nodes are where the sheets now end */
	size_t nf = m->nnode;
	unsigned char *fresh = xcalloc(nf + 1, 1);
	memset(fresh + nn, 1, nf - nn);
	for (size_t tt = 0; tt < m->ntri; tt++) {
		const struct triangle *tr = &m->tri[tt];
		if (!tr->alive)
			continue;
		int any = 0;
		for (int j = 0; j < 3; j++)
			any |= (size_t)tr->n[j] < nn && gone[tr->n[j]];
		if (any) {
			for (int j = 0; j < 3; j++)
				fresh[tr->n[j]] = 1;
			mesh_kill_triangle(m, (int)tt);
			rep->removed_tris++;
		}
	}
	if (first)
		rep->open_cut = deloop_open_length(m);
	unsigned char *welded = xcalloc(nf + 1, 1);
	if (join)
		rep->joined += deloop_zip(m, fresh, nf, welded, nf);
	/* the seam nodes, for merge_away */
	if (*nseam < nf) {
		*seam = xreallocarray(*seam, nf, 1);
		memset(*seam + *nseam, 0, nf - *nseam);
		*nseam = nf;
	}
	for (size_t i = 0; i < nf; i++)
		(*seam)[i] |= welded[i];
	/* the cut nodes left open: pulled back (DELOOP_PULLBACK) */
	for (size_t i = 0; i < ntodo; i++) {
		int c = todo[i].node, k = todo[i].kept;
		struct node *nc = &m->node[c];
		if (!nc->alive || welded[c] || !m->node[k].alive)
			continue;
		for (int d = 0; d < 3; d++)
			nc->p[d] -= DELOOP_PULLBACK * (nc->p[d] - m->node[k].p[d]);
	}
	free(welded);
	free(fresh);
	free(todo);
	free(gn);
}

/* The local passes' first resort at a seam: a node chosen to go, on or
 * next to a seam this run joined (seam, nseam) and barely past the other
 * sheet (DELOOP_MERGE_DEPTH), is merged onto its nearest neighbour not
 * chosen (mesh_merge, thesis 8.4.1.2, with all its checks) instead of
 * being deleted, so that the joined surface stays closed; the merge
 * moves the surface by less than a segment.  Returns the nodes merged;
 * none (every merge refused) leaves the deletion to cut_and_remove. */
static long merge_away(struct mesh *m, const struct deloop_pierce *pc, size_t np,
		       const unsigned char *gone, const unsigned char *seam, size_t nseam,
		       struct deloop_report *rep)
{
	long merged = 0;
	size_t nn = m->nnode;
	/* only nodes just past the other sheet: for every crossing on their
	 * segments, within DELOOP_MERGE_DEPTH segment lengths of the
	 * crossed triangle's plane */
	unsigned char *shallow = xcalloc(nn + 1, 1);
	for (size_t i = 0; i < np; i++)
		for (int e = 0; e < 2; e++) {
			int g = m->seg[pc[i].s].n[e];
			if (!gone[g] || shallow[g] == 2)
				continue;
			const struct triangle *tr = &m->tri[pc[i].t];
			const double *a = m->node[tr->n[0]].p, *b = m->node[tr->n[1]].p,
				*c = m->node[tr->n[2]].p;
			double u[3], v[3], n[3];
			vec3_sub(b, a, u);
			vec3_sub(c, a, v);
			vec3_cross(u, v, n);
			double nl = sqrt(vec3_dot(n, n));
			double depth = nl > 0 ? fabs(orient(a, b, c, m->node[g].p)) / nl : HUGE_VAL;
			shallow[g] = depth <= DELOOP_MERGE_DEPTH * mesh_seg_length(m, pc[i].s) ? 1 : 2;
		}
	for (size_t g = 0; g < nn; g++) {
		if (!gone[g] || !m->node[g].alive || shallow[g] != 1)
			continue;
		/* at a seam this run joined: the node or a neighbour on it */
		int near = g < nseam && seam[g];
		for (int k = 0; k < m->node[g].nseg && !near; k++) {
			const struct segment *sg = &m->seg[m->node[g].seg[k]];
			int o = sg->n[0] == (int)g ? sg->n[1] : sg->n[0];
			near = (size_t)o < nseam && seam[o];
		}
		if (!near)
			continue;
		/* the neighbours by distance, nearest first (ties by index) */
		const struct node *nd = &m->node[g];
		int best = -1;
		double bl = HUGE_VAL;
		for (int pick = 0; pick < nd->nseg && best < 0; pick++) {
			double lim = bl;
			int cand = -1;
			bl = HUGE_VAL;
			for (int k = 0; k < nd->nseg; k++) {
				int s = nd->seg[k];
				int o = m->seg[s].n[0] == (int)g ? m->seg[s].n[1] : m->seg[s].n[0];
				double l = mesh_seg_length(m, s);
				if ((size_t)o < nn && gone[o])
					continue;
				if (pick > 0 && !(l > lim))
					continue;
				if (l < bl) {
					bl = l;
					cand = s;
				}
			}
			if (cand < 0)
				break;
			if (mesh_can_merge(m, cand, (int)g))
				best = cand;
		}
		if (best < 0)
			continue;
		mesh_merge(m, best, (int)g);
		merged++;
	}
	free(shallow);
	rep->merged += merged;
	return merged;
}

static void deloop_passes(struct mesh *m, struct fmm *fm, const struct rfield *f, double t,
			  int join, struct deloop_report *rep)
{
	memset(rep, 0, sizeof *rep);
	unsigned char *seam = NULL;     /* nodes joined across a seam this run */
	size_t nseam = 0;
	struct deloop_snap sn = {0};
	struct box_cache bc = {0};
	for (int pass = 0; pass < DELOOP_PASSES; pass++) {
		struct deloop_pierce *pc;
		size_t np = pass == 0 ? dl_pierces_geo(m, &pc, &sn.geo, &bc)
			: dl_pierces_near_checked(m, &sn, &pc, &sn.geo, &bc);
		dl_snap_take(&sn, m, pc, np);
		if (pass == 0)
			rep->crossings = (long)np;
		rep->left = (long)np;
		if (np == 0)
			break;
		unsigned char *gone = pass == 0 ? classify_patches(m, pc, np, fm, f, t, rep)
			: classify_local(m, pc, np, fm, f, t, &rep->folds);
		/* the next pass recounts: cutting can leave a crossing that
		 * no pierce of this one showed */
		if (pass == 0 || pass > DELOOP_MERGE_PASSES ||
		    !merge_away(m, pc, np, gone, seam, nseam, rep))
			cut_and_remove(m, pc, np, gone, rep, pass == 0, join, &seam, &nseam);
		free(gone);
		free(pc);
		if (pass + 1 == DELOOP_PASSES) {
			/* the cap: report what the last pass left, not what it
			 * started from */
			rep->left = (long)dl_pierces_near_checked(m, &sn, &pc, &sn.geo, &bc);
			free(pc);
		}
	}
	dl_snap_free(&sn);
	free(bc.tb);
	free(bc.sb);
	free(bc.P);
	free(seam);
	rep->open_left = deloop_open_length(m);
}

/* The open border a loop-free run leaves is closed (deloop_close.c):
 * first every loop whose closing crosses nothing; the loops left (the
 * other sheet passes through where their closing must go) are closed
 * regardless and the passes run again on the crossings that makes, which
 * cut or delete the nodes past the other sheet and so open smaller loops,
 * closed in turn.  The rounds need not shrink the border every time, so
 * the mesh with the least border open is kept (a copy), and the rounds
 * stop when it is closed, after DELOOP_CLOSE_STALE rounds without
 * improving it, at a round that leaves crossings or an inconsistent
 * mesh, or at the cap. */
void deloop_close_open(struct mesh *m, struct fmm *fm, const struct rfield *f, double t,
		       struct deloop_report *rep)
{
	if (rep->left > 0 || !(rep->open_left > 0))
		return;
	deloop_close(m, 0);
	rep->open_left = deloop_open_length(m);
	struct mesh *best = NULL;
	struct deloop_report sum = *rep;
	int stale = 0;
	for (int round = 1; round < DELOOP_CLOSE_ROUNDS && rep->open_left > 0 &&
	     stale < DELOOP_CLOSE_STALE; round++) {
		if (!best)
			best = mesh_copy(m);
		deloop_close(m, 1);
		struct deloop_report r2;
		struct mesh *forced = mesh_copy(m);
		deloop_passes(m, fm, f, t, 1, &r2);
		if (r2.left > 0 || mesh_check(m)) {
			/* as deloop_run: redone without joining (the sheets end
			 * a pull-back apart, loops the next round closes; the
			 * round was given up instead, and the 1.0 um unbaked
			 * hole array delooped at 60 s kept 24.4 um of border
			 * open, 8.3 with this) */
			struct mesh joined = *m;
			*m = *forced;
			*forced = joined;
			deloop_passes(m, fm, f, t, 0, &r2);
		}
		mesh_free(forced);
		/* the passes on a forced closing can leave the mesh
		 * inconsistent (a segment doubled by a weld across a fold):
		 * such a round is undone like one that leaves crossings */
		if (r2.left > 0 || mesh_check(m))
			break;
		sum.loops += r2.loops;
		sum.removed_tris += r2.removed_tris;
		sum.cuts += r2.cuts;
		sum.joined += r2.joined;
		sum.merged += r2.merged;
		sum.folds += r2.folds;
		deloop_close(m, 0);
		sum.open_left = deloop_open_length(m);
		if (sum.open_left < rep->open_left - DELOOP_CLOSE_GAIN) {
			*rep = sum;
			mesh_free(best);
			best = NULL;
			stale = 0;
		} else {
			stale++;
		}
	}
	if (best) {
		/* back to the best mesh */
		struct mesh last = *m;
		*m = *best;
		*best = last;
		mesh_free(best);
	}
}

/* Joining the sheets along the intersection curve (deloop_zip.c) leaves,
 * on some meshes, crossings no later pass removes, or (on a mesh whose
 * open border was closed at an earlier deloop) a doubled segment (the unbaked contact at
 * 240 mJ/cm2 with 0.1 um segments: 4, however many passes).  A loop-free
 * mesh matters more than a closed seam, so the run is then redone from a
 * copy of the mesh without joining: the sheets end a pull-back apart. */
long deloop_run(struct mesh *m, struct fmm *fm, const struct rfield *f, double t,
		struct deloop_report *rep)
{
	struct mesh *before = mesh_copy(m);
	deloop_passes(m, fm, f, t, 1, rep);
	/* joining across a fold can also double a segment (two welds onto
	 * the same pair of nodes): redone without it as well */
	if (rep->left > 0 || mesh_check(m)) {
		struct mesh joined = *m;
		*m = *before;
		*before = joined;
		deloop_passes(m, fm, f, t, 0, rep);
		rep->unjoined = 1;
	}
	mesh_free(before);
	return rep->loops;
}

struct fmm *deloop_classifier(const struct ratefile *r, double seg,
			      const double *seeds, int nseeds)
{
	int refine[3];
	double h[3] = {
		r->nx > 1 ? (r->xmax - r->xmin) / (r->nx - 1) : 0,
		r->ny > 1 ? (r->ymax - r->ymin) / (r->ny - 1) : 0,
		r->nz > 1 ? (r->zmax - r->zmin) / (r->nz - 1) : 0,
	};
	int nz_auto = fmm_auto_refine(r);
	double nodes = 1;
	int n[3] = {r->nx, r->ny, r->nz};
	for (int d = 0; d < 3; d++) {
		/* a cell no wider than DELOOP_CELL_SEGS segments: a young
		 * loop is about a segment deep, and must be deeper than the
		 * margin */
		double k = seg > 0 && h[d] > DELOOP_CELL_SEGS * seg ?
			fmin(ceil(h[d] / (DELOOP_CELL_SEGS * seg)), DELOOP_MAX_REFINE) : 1;
		if (d == 2 && k < nz_auto)
			k = nz_auto;
		refine[d] = k > FMM_MAX_REFINE ? FMM_MAX_REFINE : (int)k;
	}
	for (;;) {
		nodes = 1;
		for (int d = 0; d < 3; d++)
			nodes *= (double)(n[d] > 1 ? (n[d] - 1) * refine[d] + 1 : 1);
		if (nodes <= DELOOP_MAX_FMM_NODES)
			break;
		int big = 0;
		for (int d = 1; d < 3; d++)
			if (refine[d] > refine[big])
				big = d;
		if (refine[big] == 1)
			break;
		refine[big]--;
	}
	return fmm_solve_lazy(r, refine, seeds, nseeds);
}
