/*
 * deloop.c - mesh delooping (thesis 7.5.3, 8.4.3): not implemented yet;
 * it has its own issue.  The ray-string simulation runs correctly with
 * loops present (thesis 8.5): the rays are independent of the local
 * surface, so a loop never corrupts the correct part of the front, and
 * nothing here relies on the mesh being free of self-intersections.
 *
 * The mesh (mesh.h) is shaped for the pass to come: it can walk the
 * triangles and test pairs for intersection, cut the crossing segments
 * with mesh_split (which keeps every link two-way), and remove the loop's
 * triangles with mesh_kill_triangle, which deletes orphaned segments and
 * nodes.
 */
#include "etch.h"

long deloop_mesh(struct mesh *m)
{
	(void)m;
	return 0;
}
