/*
 * string.c - the string algorithm (thesis 6.2, after SAMPLE): each node
 * moves by R dt along the average of the unit normals of its two segments
 * (Figure 6.1), R taken at the node; then the string is clipped at the
 * walls, its long segments cut by linear interpolation and its short ones
 * lose a node (6.2.3, S_max = 1.2, S_min = 0.1 S_ideal as Table 7.2), and
 * its loops are removed.  Direction comes from the surface alone, hence
 * the scissoring and rounding at corners of 6.2.3.1-2.
 *
 * From a seed the string starts as the wavelet of the first step: the half
 * circle of radius R(seed) t0 (t0 = the step, or more so that the radius
 * reaches S_ideal), the rate taken uniform inside it.
 */
#include "front.h"
#include "methods.h"

#include "util.h"

#include <math.h>
#include <stdlib.h>

/* segment lengths against S_ideal (thesis Table 7.2) */
#define SMAX 1.2
#define SMIN 0.1

/* Unit normal of the segment a -> b into the resist (on the right). */
static int normal(const double *a, const double *b, double nrm[2])
{
	double tx = b[0] - a[0], tz = b[1] - a[1], l = hypot(tx, tz);
	if (!(l > 0))
		return 0;
	nrm[0] = tz / l;
	nrm[1] = -tx / l;
	return 1;
}

void e2_run_string(struct e2 *e)
{
	double seg = front_seg(e), dt = front_dt(e), t = 0;
	struct front fr = {0};
	e2_check_steps(e, dt);
	if (e->o.seeded) {
		double r0 = e2_rate(e, e->o.seed[0], e->o.seed[1], NULL);
		double t0 = dt;
		if (r0 > 0 && r0 * t0 < seg)
			t0 = seg / r0;
		if (t0 > e->tp[0])
			t0 = e->tp[0];
		double rad = r0 * t0;
		long m = (long)ceil(M_PI * rad / seg);
		if (m < 8)
			m = 8;
		for (long k = 0; k <= m; k++) {
			double th = M_PI * (double)(m - k) / (double)m;
			double p[2] = {e->o.seed[0] + rad * cos(th), e->o.seed[1] - rad * sin(th)};
			if (k == 0 || k == m)
				p[1] = e->o.seed[1];
			front_push(&fr, p[0], p[1], 0, 0, 0);
		}
		front_clip(e, &fr);
		t = t0;
	} else if (e->sp) {
		/* the thesis' plain string: one node at each corner (6.2.3.1) */
		front_start_profile(e, &fr, seg, 0);
	} else {
		front_start(e, &fr, seg, 0);
	}
	double (*dir)[2] = NULL;
	size_t dcap = 0;
	int next = 0;
	while (next < e->ntp && t >= e->tp[next]) {
		e2_begin_set(e);
		front_emit(e, &fr);
		next++;
	}
	while (next < e->ntp) {
		double tp = e->tp[next], step = dt;
		int print = !(t + dt < tp - 1e-12 * tp);
		if (print)
			step = tp - t;
		front_ends(e, &fr);
		/* [I] directions from the string as it stands */
		xgrow(&dir, &dcap, fr.n, sizeof *dir);
		for (size_t i = 0; i < fr.n; i++) {
			double s[2] = {0, 0}, nrm[2];
			if (i > 0 && normal(fr.v[i - 1].p, fr.v[i].p, nrm))
				s[0] += nrm[0], s[1] += nrm[1];
			if (i + 1 < fr.n && normal(fr.v[i].p, fr.v[i + 1].p, nrm))
				s[0] += nrm[0], s[1] += nrm[1];
			if (!front_flatten(e, fr.v[i].flags, s))
				s[0] = s[1] = 0;
			dir[i][0] = s[0], dir[i][1] = s[1];
		}
		/* [II] every node by R dt along its direction */
		for (size_t i = 0; i < fr.n; i++) {
			struct fnode *n = &fr.v[i];
			double d = e2_rate(e, n->p[0], n->p[1], NULL) * step;
			n->p[0] += d * dir[i][0];
			n->p[1] += d * dir[i][1];
			n->flags = (n->flags & END) | front_walls(e, n->p);
		}
		/* [III] keep the string in the box, its density even, loop-free */
		front_clip(e, &fr);
		front_remesh(e, &fr, SMAX * seg, SMIN * seg, 0);
		e->st.loops += front_deloop(e, &fr);
		e->st.steps++;
		if ((long)fr.n > e->st.items)
			e->st.items = (long)fr.n;
		if (fr.cap * sizeof *fr.v > e->st.bytes)
			e->st.bytes = fr.cap * sizeof *fr.v + dcap * sizeof *dir;
		t = print ? tp : t + step;
		if (print) {
			e2_begin_set(e);
			front_emit(e, &fr);
			next++;
		}
	}
	free(dir);
	front_free(&fr);
}
