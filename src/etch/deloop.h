/*
 * deloop.h - removing the loops of the ray-string mesh (thesis 7.5.3,
 * 8.4.3, 8.5 and the future-research list of 10.2).
 *
 * Where etch fronts converge the mesh passes through itself and the part
 * behind the other front (already developed resist) forms a loop.  A run
 * works in four stages, in these files: stage 1 in deloop_grid.c (the
 * first search) and deloop_near.c (the searches of later passes, and the
 * reference search), stages 2 to 4 in deloop.c, the joining of stage 3
 * in deloop_zip.c:
 *
 *  1. find every segment that crosses the interior of a triangle it does
 *     not touch ("pierces"), through a hashed grid of the triangles (cells
 *     about two edges long, only the occupied ones stored, in Morton
 *     order), searched by the threads (par.h) in ranges of segments, each
 *     pair in the lowest cell both boxes touch: O(N) work for N
 *     triangles of similar size instead of the thesis' O(N^2) pair
 *     test; the passes after the first search only near what the
 *     previous one changed.  Two triangles intersect exactly when an edge of
 *     one pierces the other (barring exact degeneracies), so the pierces
 *     are the self-intersections;
 *  2. the pierced segments are the ones the intersection curves cross
 *     (thesis Figure 8.11), so the nodes joined by unpierced segments fall
 *     into patches bounded by those curves.  Each patch is classified as a
 *     whole by a volumetric test: the median, over its nodes, of the signed
 *     distance (T(p) - t) R(p) to the developed surface, T the arrival time
 *     of the independent fast-marching engine (fmm.h).  A patch whose median
 *     lies inside developed resist by more than a margin (a few times the
 *     engines' typical disagreement on this mesh) is a loop.  One
 *     verdict per patch, from every node of it, so pinwheeling triangles or
 *     three triangles meeting at a point (where the thesis' motion test
 *     failed) cannot flip it;
 *  3. every pierced segment from a kept node to a loop node is cut where it
 *     crosses the other sheet, and every triangle with a loop node is
 *     deleted.  The kept sheets then end on the intersection curve, and
 *     are joined there (deloop_zip.c, thesis Figure 8.11): the two border
 *     chains become one chain of shared nodes and segments.  Stretches
 *     that cannot be joined are left open, their cut nodes pulled back a
 *     little towards the kept nodes (DELOOP_PULLBACK) so that the sheets
 *     do not touch, and closed at the end of the run (deloop_close.c);
 *  4. the crossings are searched again; any left (folds shallower than the
 *     margin, where both sides pass for front) go node by node, the node of
 *     a crossing segment deeper in developed resist first, until none is
 *     left or DELOOP_PASSES passes have run.  A node barely past the
 *     other sheet (a fold at a joined seam) is merged onto a neighbour
 *     rather than deleted, so that the joined surface stays closed.
 *
 * For the surface written at a print time (deloop_close_open, on a copy
 * of the mesh) each loop of open border left is triangulated
 * (deloop_close.c) unless its triangles would cross the surface; those
 * that would are closed regardless and the stages run again on the
 * crossings, in rounds, until no border is open.  The set written at a
 * print time is delooped on a copy (ray_run.c), and the front that goes
 * on advancing keeps its loops; only -deloop n deloops it in place, and
 * it then keeps its seams open: closed in place, the closing's triangles
 * folded into later deloops and steps, and a merge doubled a segment
 * (car-arf-contact with -pt 10, found by -check).
 */
#ifndef ETCH_DELOOP_H
#define ETCH_DELOOP_H

#include "mesh.h"

#include <stddef.h>

struct fmm;
struct rfield;
struct ratefile;

/* Segment s crosses triangle t at x, a fraction u of the way from its
 * node n[0] to its node n[1]. */
struct deloop_pierce {
	int s, t;
	double u;
	double x[3];
};

/* Every pierce of m (alive segments and triangles sharing no node),
 * sorted by segment then triangle.  *out is malloc'd (free it; NULL when
 * there are none).  Returns the count. */
size_t deloop_pierces(const struct mesh *m, struct deloop_pierce **out);

/* The same list found without the grid (every pair whose x ranges meet,
 * O(N^2) at worst): the grid's reference, for the tests. */
size_t deloop_pierces_all(const struct mesh *m, struct deloop_pierce **out);

/* What one pass did. */
struct deloop_report {
	long crossings;         /* pierces found */
	long loops;             /* patches removed */
	long folds;             /* local passes needed after the patch pass */
	double margin;          /* the patch verdict's margin, um */
	long removed_tris;      /* triangles deleted (after the cuts) */
	long cuts;              /* segments cut on the intersection curves */
	long left;              /* pierces between two kept patches (0 if clean) */
	long joined;            /* seam segments joined (deloop_zip) */
	long merged;            /* fold nodes merged away (local passes) */
	double open_cut;        /* open border (um) the first pass's cuts left, before joining */
	double open_left;       /* open border (um) at the end of the run */
	int unjoined;            /* joining left crossings: redone without it */
};

/* -check: compare every search near a pass's changes with a full search
 * (etch dies on a difference). */
void deloop_set_check(int on);
/* Deloops m at time t (s), classifying with the arrival times fm and the
 * rates f.  Returns the number of loops removed.  The mesh stays
 * consistent (mesh_check); call mesh_compact afterwards. */
long deloop_run(struct mesh *m, struct fmm *fm, const struct rfield *f, double t,
		struct deloop_report *rep);

/* Joins the open borders left by the cuts (deloop_zip.c): only open
 * segments between nodes marked in fresh (nodes from nfresh on count as
 * marked) take part.  welded[i] (i < nwelded) is set for every node that
 * took the other sheet's node.  Returns the segments joined. */
long deloop_zip(struct mesh *m, const unsigned char *fresh, size_t nfresh,
		unsigned char *welded, size_t nwelded);

/* Whether segment s is open border: one triangle, and not lying on a
 * face of the box. */
int deloop_border_open(const struct mesh *m, int s);

/* Closes the open border loops the joining left (deloop_close.c): each
 * loop triangulated, and opened again if its triangles cross the
 * surface (unless force: then the crossings are left for deloop's
 * passes).  Returns the loops closed. */
long deloop_close(struct mesh *m, int force);

/* Closes the open border of m, delooped at time t (deloop_run, whose
 * report rep is updated): the loops deloop_close closes cleanly, then
 * rounds of forced closing and deloop passes, keeping the mesh with the
 * least border open.  For the surface written at a print time, on a copy
 * (ray_run.c): the front that goes on advancing keeps its seams open. */
void deloop_close_open(struct mesh *m, struct fmm *fm, const struct rfield *f, double t,
		       struct deloop_report *rep);

/* Total length (um) of the open border of m: segments with one triangle
 * not lying on a face of the box. */
double deloop_open_length(const struct mesh *m);

/* The classifier for a simulation: the fast-marching solution from the
 * resist top (nseeds = 0) or from the seed points (x y z triples), its
 * grid refined so that a cell is no larger than about seg (um) across and
 * the standing waves are resolved (fmm_auto_refine).  The solve is lazy
 * (fmm_solve_lazy): it marches only as far as the deloops' queries need
 * (the fronts at the print times), with the full solve's T wherever it
 * is read; fm is therefore not const in the calls above. */
struct fmm *deloop_classifier(const struct ratefile *r, double seg,
			      const double *seeds, int nseeds);

#endif
