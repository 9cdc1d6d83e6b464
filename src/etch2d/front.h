/*
 * front.h - the string of nodes the surface methods (string, ray,
 * ray-string) move: front.c advances, clips, remeshes and deloops it,
 * front_start.c makes the first one.  It sits on e2.h and under the
 * methods.
 */
#ifndef ETCH2D_FRONT_H
#define ETCH2D_FRONT_H

#include "e2.h"

#include <stddef.h>

/* Most nodes a string may grow to before the run is refused. */
#define FRONT_MAX_NODES 4000000L

enum { ON_LEFT = 1, ON_RIGHT = 2, ON_TOP = 4, END = 16 };
struct fnode {
	double p[2], s[2];      /* position; unit direction (rays) */
	unsigned flags;
};
struct front {
	size_t n, cap;
	struct fnode *v;        /* in order, left end to right end; the
				 * material on the right of the walk */
};
void front_push(struct front *fr, double x, double z, double sx, double sz, unsigned flags);
/* Wall flags of a node from its position. */
unsigned front_walls(const struct e2 *e, const double p[2]);
/* Boundary flattening (7.5.2.2): a node on a side wall whose direction
 * points into the resist loses the normal component; an end of the string
 * on the top (from a seed) keeps only its component along the top.  0 if
 * nothing is left. */
int front_flatten(const struct e2 *e, unsigned flags, double s[2]);
/* Advances one node by dt along its ray (ray equation, recursive vector
 * checking with length rl, flattening at the walls).  The substrate is a
 * wall too, handled as the bottom face's rate continued below it (R(x,
 * zmin), dR/dz = 0: any path below has its projection onto the substrate
 * as fast), so nodes go on below it and front_emit draws the cleared
 * substrate where the string runs under it. */
void front_advance_ray(struct e2 *e, struct fnode *n, double dt, int depth);
/* Cuts the string where it leaves the box through a side wall (and the top
 * when seeded), 7.5.2.1. */
void front_clip(struct e2 *e, struct front *fr);
/* Cuts segments longer than smax (arc: on the arc the end directions
 * define, 7.5.1.1; else linear) and merges those shorter than smin. */
void front_remesh(struct e2 *e, struct front *fr, double smax, double smin, int arc);
/* 2D delooping (7.5.3.3): removes the loops of the string; returns how
 * many. */
long front_deloop(struct e2 *e, struct front *fr);
void front_emit(struct e2 *e, const struct front *fr);
/* Marks the first and last nodes END (and no other). */
void front_ends(struct e2 *e, struct front *fr);
/* The start: from the resist top, nodes spaced at most seg along it
 * pointing down; from a seed (on the top), nseed nodes at the seed with
 * directions spread evenly over the half circle below the top, the
 * first and last along the top; from a -start profile,
 * front_start_profile with fans of rays pi / (nseed - 1) apart. */
void front_start(struct e2 *e, struct front *fr, double seg, long nseed);
/* Default node spacing (width / 50, the thesis' 50 segments) and step. */
/* The start from a -start profile: a node at each vertex and at most seg
 * apart between, pointing along the normal into the resist (the bisector
 * at a vertex); at a diverging corner (the profile turning away from the
 * resist) with fan > 0 a fan of nodes at the vertex whose directions turn
 * from the one face's normal to the other's at most fan radians apart. */
void front_start_profile(struct e2 *e, struct front *fr, double seg, double fan);
double front_seg(const struct e2 *e);
double front_dt(const struct e2 *e);
void front_free(struct front *fr);

#endif
