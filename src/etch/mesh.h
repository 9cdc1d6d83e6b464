/*
 * mesh.h - the surface mesh of the ray-string algorithm (thesis 8.2.2,
 * Figure 8.1): nodes, segments and triangles with two-way links.
 *
 * A node holds its position, its unit ray vector and the list of its
 * segments; a segment its two nodes and its (at most two) triangles; a
 * triangle its three nodes, in order, and its three segments, segment i
 * joining node i to node i+1.  Triangles are oriented so that
 * (n1 - n0) x (n2 - n0) points the way the front advances (into the
 * resist), and two triangles sharing a segment traverse it in opposite
 * directions.  A segment with one triangle is a border of the mesh (on a
 * wall of the box after clipping).
 *
 * The objects live in growable arrays and refer to each other by index,
 * not by pointer, so that the arrays can grow without invalidating links
 * and so that mesh_compact can renumber them in order (deterministic
 * output, cache-friendly sweeps).  A deleted object is marked dead and
 * left in place until the next compaction.  This is also the shape a
 * delooping pass (thesis 8.4.3) needs: it can walk triangles, find the
 * segments to cut through the same split primitive as mesh modification,
 * and delete triangles with mesh_kill_triangle, which cleans up orphaned
 * segments and nodes.
 */
#ifndef ETCH_MESH_H
#define ETCH_MESH_H

#include <stddef.h>

/* Node flags: which face of the rate box a node is pinned to. */
enum {
	ON_X0 = 1, ON_X1 = 2, ON_Y0 = 4, ON_Y1 = 8,
	ON_TOP = 16,            /* clipped at z = zmax */
	ON_SUB = 32,            /* reached the substrate z = zmin: stopped */
	ON_SIDES = ON_X0 | ON_X1 | ON_Y0 | ON_Y1,
	ON_WALLS = ON_SIDES | ON_TOP        /* never deleted (thesis 8.4.1.2) */
};

struct node {
	double p[3];            /* position, um */
	double s[3];            /* unit ray vector */
	int *seg;               /* segments attached */
	int nseg, capseg;
	unsigned flags;
	int alive;
};

struct segment {
	int n[2];               /* nodes */
	int t[2];               /* triangles; t[1] (or both) -1 if none */
	int alive;
};

struct triangle {
	int n[3];               /* nodes, oriented */
	int s[3];               /* s[i] joins n[i] and n[(i+1)%3] */
	int alive;
};

struct mesh {
	struct node *node;
	struct segment *seg;
	struct triangle *tri;
	size_t nnode, nseg, ntri;           /* slots used (alive or dead) */
	size_t capnode, capseg, captri;
	size_t live_node, live_seg, live_tri;
};

struct mesh *mesh_new(void);
void mesh_free(struct mesh *m);
/* A deep copy (to try an operation and fall back). */
struct mesh *mesh_copy(const struct mesh *m);

int mesh_add_node(struct mesh *m, const double p[3], const double s[3], unsigned flags);
/* The segment joining a and b, or -1. */
int mesh_find_segment(const struct mesh *m, int a, int b);
/* Adds triangle (a, b, c), creating its segments as needed. */
int mesh_add_triangle(struct mesh *m, int a, int b, int c);

/* Splits segment s at a new node (position p, ray r, flags); both
 * triangles on s are split in two through the new node (thesis Figure
 * 8.2).  Returns the new node. */
int mesh_split(struct mesh *m, int s, const double p[3], const double r[3],
	       unsigned flags);

/* Whether segment s may be merged by deleting node del onto the other
 * node (thesis 8.4.1.2): del not on a wall nor on a mesh border, the
 * result still a surface (the nodes' common neighbours are exactly the
 * apexes of the triangles on s), no 3-triangle pyramid flattened (Figure
 * 8.8) and no triangle turned over.  Returns 1 if allowed. */
int mesh_can_merge(const struct mesh *m, int s, int del);
/* Merges segment s: node del is deleted, its segments and triangles are
 * given to the other node (Figure 8.4).  Call mesh_can_merge first. */
void mesh_merge(struct mesh *m, int s, int del);

/* Whether nodes keep and del, both on mesh borders and at (nearly) the
 * same place, may be welded into one (delooping, thesis 8.4.3 and Figure
 * 8.11: the two sheets cut along their intersection curve meet there):
 * not joined by a segment, and every segment (del, x) either new to keep
 * or, with its twin (keep, x), two border segments whose triangles
 * traverse them in opposite directions and have different third nodes
 * (the twins become one segment with two triangles).  Returns 1 if
 * allowed. */
int mesh_can_weld(const struct mesh *m, int keep, int del);
/* Welds node del onto keep (call mesh_can_weld first): del's segments
 * and triangles go to keep, twin border segments become one; keep keeps
 * its position, ray and flags.  Returns the number of segments joined. */
int mesh_weld(struct mesh *m, int keep, int del);

/* Deletes triangle t; segments left without a triangle and nodes left
 * without a segment are deleted too. */
void mesh_kill_triangle(struct mesh *m, int t);

/* Drops dead objects and renumbers the rest in order (at once when
 * nothing is dead). */
void mesh_compact(struct mesh *m);

/* The largest share of dead slots among the node, segment and triangle
 * arrays (0 after mesh_compact). */
double mesh_dead_share(const struct mesh *m);
/* etch compacts when the share passes this (and at print times). */
#define MESH_DEAD_SHARE 0.125

/* Length of segment s. */
double mesh_seg_length(const struct mesh *m, int s);

/* Consistency check (every link two-way, every triangle closed by its
 * segments, orientation consistent, no duplicate segment, no dangling
 * reference, unit rays, finite coordinates).  Returns NULL if clean,
 * else a description of the first fault (static storage). */
const char *mesh_check(const struct mesh *m);

#endif
