/*
 * raystring.c - the 2D ray-string algorithm (thesis chapter 7): nodes
 * joined into a string, each node moving along its own ray by the ray
 * equation with recursive vector checking (7.3, 7.4.2; the library's ray
 * step, the same as etch's in 3D), then the mesh operations of 7.5:
 * clipping at the side walls, boundary flattening (inside the advance),
 * cutting of segments longer than S_max with arc interpolation, merging
 * of those shorter than S_min (1.2 and 0.1 S_ideal, Table 7.2), and 2D
 * delooping after every step.
 *
 * From a seed the string starts as nine nodes at the seed whose rays
 * span the half circle below the top (Figure 7.7's start, widened to the
 * half plane); the first step spreads them and arc interpolation fills
 * the circle between.
 */
#include "front.h"
#include "methods.h"

#include <math.h>

#define SMAX 1.2
#define SMIN 0.1
#define SEED_RAYS 9

void e2_run_raystring(struct e2 *e)
{
	double seg = front_seg(e), dt = front_dt(e), t = 0;
	struct front fr = {0};
	e2_check_steps(e, dt);
	front_start(e, &fr, seg, SEED_RAYS);
	int next = 0;
	while (next < e->ntp) {
		double tp = e->tp[next], step = dt;
		int print = !(t + dt < tp - 1e-12 * tp);
		if (print)
			step = tp - t;
		front_ends(e, &fr);
		for (size_t i = 0; i < fr.n; i++)
			front_advance_ray(e, &fr.v[i], step, 0);
		front_clip(e, &fr);
		front_remesh(e, &fr, SMAX * seg, SMIN * seg, 1);
		e->st.loops += front_deloop(e, &fr);
		e->st.steps++;
		if ((long)fr.n > e->st.items)
			e->st.items = (long)fr.n;
		if (fr.cap * sizeof *fr.v > e->st.bytes)
			e->st.bytes = fr.cap * sizeof *fr.v;
		t = print ? tp : t + step;
		if (print) {
			e2_begin_set(e);
			front_emit(e, &fr);
			next++;
		}
	}
	front_free(&fr);
}
