/*
 * ray.c - the ray algorithm (thesis 6.3): independent rays, each moved
 * by the ray equation (the library's step, with recursive vector checking
 * and flattening at the walls as in the ray-string), no mesh at all.  The
 * surface is reconstructed at each print time by joining the rays' ends in
 * the order the rays started, keeping those inside the box: so the
 * ray-scarce regions and loops of 6.3.3 show as they are.
 *
 * From the resist top the rays start S_ideal apart pointing down; from a
 * seed they fan out over the half circle, the first and last along the
 * top, as many as put them S_ideal apart at the largest rate's reach
 * R_max et.
 */
#include "front.h"
#include "methods.h"

#include "util.h"

#include <math.h>
#include <stdlib.h>

/* most rays from a seed */
#define MAX_SEED_RAYS 1000000L

void e2_run_ray(struct e2 *e)
{
	double seg = front_seg(e), dt = front_dt(e), t = 0;
	struct front fr = {0};
	e2_check_steps(e, dt);
	long nseed = 0;
	if (e->o.seeded || e->sp) {
		double m = ceil(M_PI * e->f->rmax * e->o.et / seg) + 1;
		if (m > MAX_SEED_RAYS)
			die("-seg %g asks for %.0f rays from the seed (at most %ld)", seg, m, MAX_SEED_RAYS);
		nseed = m < 9 ? 9 : (long)m;
	}
	front_start(e, &fr, seg, nseed);
	e->st.items = (long)fr.n;
	e->st.bytes = fr.cap * sizeof *fr.v;
	int next = 0;
	while (next < e->ntp) {
		double tp = e->tp[next], step = dt;
		int print = !(t + dt < tp - 1e-12 * tp);
		if (print)
			step = tp - t;
		front_ends(e, &fr);
		for (size_t i = 0; i < fr.n; i++)
			front_advance_ray(e, &fr.v[i], step, 0);
		e->st.steps++;
		t = print ? tp : t + step;
		if (print) {
			e2_begin_set(e);
			/* the rays' ends joined in order (front_emit: a ray out of
			 * the box breaks the curve) */
			front_emit(e, &fr);
			next++;
		}
	}
	front_free(&fr);
}
