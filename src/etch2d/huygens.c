/*
 * huygens.c - the modified cell method (thesis chapter 4, 4.3): cells
 * are etched or not, nothing in between.  Every constant step dt, each
 * boundary cell (an etched cell with an unetched neighbour) etches every
 * cell whose centre lies within R dt of its own centre, R taken at that
 * centre: the front after the step is the envelope of those Huygens
 * wavelets.  The boundary is then found again by a scan of all cells, as
 * the thesis did (4.4).  A cell whose R dt is below a cell width etches
 * nothing, ever: the discretisation error of 4.5.2-4.5.3, kept on purpose.
 *
 * From the resist top the developer is a row of etched cells above the
 * box, its rates those of the top row's centres' x at the top (z = zmax).
 * A print time cuts the step before it short.  Default dt: 10 cells of
 * the smaller side at the largest rate (Figure 4.2a).
 */
#include "methods.h"

#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* cells per step at the largest rate when -dt is not given */
#define CELLS_PER_STEP 10

struct bcell { int i, k; double r; };

void e2_run_huygens(struct e2 *e)
{
	int nx, nz;
	e2_cells(e, &nx, &nz);
	size_t n = (size_t)nx * nz;
	double dx = (e->x1 - e->x0) / nx, dz = (e->z1 - e->z0) / nz;
	double dt = e->o.dt;
	if (!(dt > 0))
		dt = e->f->rmax > 0 ? CELLS_PER_STEP * fmin(dx, dz) / e->f->rmax : e->o.et;
	if (dt < e->o.et)
		e2_check_steps(e, dt);
	unsigned char *et = xcalloc(n, 1);
	struct bcell *b = xreallocarray(NULL, n + (size_t)nx, sizeof *b);
	e->st.bytes = n + (n + (size_t)nx) * sizeof *b;
	e->st.total = (long)n;
	if (e->o.seeded) {
		int i = (int)floor((e->o.seed[0] - e->x0) / dx);
		int k = (int)floor((e->o.seed[1] - e->z0) / dz);
		i = i < 0 ? 0 : i >= nx ? nx - 1 : i;
		k = k < 0 ? 0 : k >= nz ? nz - 1 : k;
		et[(size_t)k * nx + i] = 1;
	} else if (e->sp) {
		/* the cells whose centres lie above the start profile */
		for (size_t c = 0; c < n; c++)
			et[c] = (unsigned char)e2_start_etched(e, e->x0 + ((double)(c % nx) + 0.5) * dx,
								 e->z0 + ((double)(c / nx) + 0.5) * dz);
	}
	double t = 0;
	int next = 0;
	while (next < e->ntp) {
		double tp = e->tp[next], step = dt;
		int print = !(t + dt < tp - 1e-12 * tp);
		if (print)
			step = tp - t;
		/* [II] the boundary cells (with the developer row from the top) */
		size_t nb = 0;
		for (int k = 0; k < nz; k++)
			for (int i = 0; i < nx; i++) {
				size_t c = (size_t)k * nx + i;
				if (!et[c])
					continue;
				if ((i > 0 && !et[c - 1]) || (i + 1 < nx && !et[c + 1]) ||
				    (k > 0 && !et[c - nx]) || (k + 1 < nz && !et[c + nx]))
					b[nb++] = (struct bcell){i, k, 0};
			}
		if (!e->o.seeded)
			for (int i = 0; i < nx; i++)
				if (!et[(size_t)(nz - 1) * nx + i])
					b[nb++] = (struct bcell){i, nz, 0};
		if ((long)nb > e->st.items)
			e->st.items = (long)nb;
		/* [I] radii from the rates at the start of the step, then etch */
		for (size_t q = 0; q < nb; q++) {
			double x = e->x0 + (b[q].i + 0.5) * dx;
			double z = b[q].k == nz ? e->z1 : e->z0 + (b[q].k + 0.5) * dz;
			b[q].r = e2_rate(e, x, z, NULL) * step;
		}
		for (size_t q = 0; q < nb; q++) {
			double r = b[q].r;
			if (!(r > 0))
				continue;
			int ri = (int)floor(r / dx), rk = (int)floor(r / dz);
			int i0 = b[q].i - ri, i1 = b[q].i + ri, k0 = b[q].k - rk, k1 = b[q].k + rk;
			if (i0 < 0) i0 = 0;
			if (i1 > nx - 1) i1 = nx - 1;
			if (k0 < 0) k0 = 0;
			if (k1 > nz - 1) k1 = nz - 1;
			for (int k = k0; k <= k1; k++) {
				double ddz = (k - b[q].k) * dz;
				for (int i = i0; i <= i1; i++) {
					double ddx = (i - b[q].i) * dx;
					if (ddx * ddx + ddz * ddz <= r * r)
						et[(size_t)k * nx + i] = 1;
				}
			}
		}
		e->st.steps++;
		t = print ? tp : t + step;
		if (print) {
			e2_begin_set(e);
			cells_emit(e, et, nx, nz, !e->o.seeded);
			next++;
		}
	}
	free(et);
	free(b);
}
