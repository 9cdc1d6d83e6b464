/*
 * cell_methods.c - the two cell methods in 3D (thesis 3.6 and 4.3-4.5.1,
 * Figure 4.3), so that the thesis' verdict on them can be checked in 3D:
 * -method cell (Dill's cell removal) and -method huygens (the modified,
 * Huygens cell method).  The box is tiled by cubes of side -seg (the
 * last of each row shorter if the box does not divide); the rate is the
 * library's interpolant at a cell's centre.
 *
 * cell: a boundary cell (unetched, a face on an etched cell or, from the
 * top, on the developer above) loses its remaining fraction through its
 * exposed faces: a whole cell of side a goes in a/R with one face,
 * a/(sqrt 2 R) with two adjacent, a/(sqrt 3 R) with three meeting at a
 * corner, a/(2R) when two exposed faces are opposite (and with four or
 * more), as etch2d's 2D rule extended.  Each step removes the cells that
 * empty first and advances the others by that time.
 * huygens: every constant step dt each boundary cell (etched, with an
 * unetched face neighbour) etches the cells whose centres lie within
 * R dt of its centre; from the top the developer is a layer of etched
 * cells above the box.  Default dt: 10 cells at the largest rate.
 *
 * Output: at each print time the faces between etched and unetched cells
 * (and, from the top, the top faces of unetched top cells), each a closed
 * 5-point curve in curves.plot and its x-y projection in curves.plot.2D,
 * as the other engines lay out their triangles.
 */
#include "etch.h"

#include "fmt_plot.h"
#include "ptimes.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Most cells of a run: Dill's method keeps 42 bytes a cell (flags, rate,
 * remaining fraction, speed, two index lists), about 180 MB at this. */
#define CELLS_MAX 4194304.0
#define F_TINY 1e-9
#define HUYGENS_CELLS_PER_STEP 10
/* Most steps of a huygens run: beyond, it takes hours (-dt tiny). */
#define HUYGENS_MAX_STEPS 1e6
/* Most print times a run may ask for (-pt tiny against -et). */
#define CELLS_MAX_PRINTS 100000

struct cgrid {
	int n[3];
	double lo[3], h[3], top;
	unsigned char *et;
	int open_top;
};

static size_t cidx(const struct cgrid *g, int i, int j, int k)
{
	return ((size_t)k * g->n[1] + (size_t)j) * g->n[0] + (size_t)i;
}

static int etched_at(const struct cgrid *g, int i, int j, int k)
{
	if (i < 0 || j < 0 || k < 0 || i >= g->n[0] || j >= g->n[1])
		return 0;
	if (k >= g->n[2])
		return g->open_top;
	return g->et[cidx(g, i, j, k)];
}

static double cx(const struct cgrid *g, int d, int i)
{
	double x = g->lo[d] + (i + 0.5) * g->h[d];
	return x;
}

/* Writes the faces between etched and unetched cells. */
static void faces(const struct cgrid *g, struct plot_writer *w3, struct plot_writer *w2,
		  const double bounds[6])
{
	for (int pass = 0; pass < 2; pass++) {
		long count = 0;
		for (int k = 0; k < g->n[2]; k++)
			for (int j = 0; j < g->n[1]; j++)
				for (int i = 0; i < g->n[0]; i++) {
					if (g->et[cidx(g, i, j, k)])
						continue;
					int nb[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
							{i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
					for (int q = 0; q < 6; q++) {
						if (!etched_at(g, nb[q][0], nb[q][1], nb[q][2]))
							continue;
						count++;
						if (pass == 0)
							continue;
						int d = q / 2, side = q % 2;
						int c[3] = {i, j, k};
						double lo[3], hi[3];
						for (int e = 0; e < 3; e++) {
							lo[e] = g->lo[e] + c[e] * g->h[e];
							hi[e] = c[e] + 1 == g->n[e] ? bounds[2 * e + 1] : lo[e] + g->h[e];
						}
						double pl = side ? hi[d] : lo[d];
						int a = (d + 1) % 3, b = (d + 2) % 3;
						double uv[5][2] = {{lo[a], lo[b]}, {hi[a], lo[b]}, {hi[a], hi[b]},
								   {lo[a], hi[b]}, {lo[a], lo[b]}};
						double p3[15], p2[10];
						for (int v = 0; v < 5; v++) {
							p3[3 * v + d] = pl;
							p3[3 * v + a] = uv[v][0];
							p3[3 * v + b] = uv[v][1];
							p2[2 * v] = p3[3 * v];
							p2[2 * v + 1] = p3[3 * v + 1];
						}
						if (w3) fmt_plot_curve(w3, 5, p3);
						if (w2) fmt_plot_curve(w2, 5, p2);
					}
				}
		if (pass == 0) {
			if (count > PLOT_MAX_COUNT)
				die("%ld cell faces, more than a plot file holds", count);
			if (w3) fmt_plot_begin_set(w3, bounds, count);
			if (w2) fmt_plot_begin_set(w2, bounds, count);
		}
	}
}

/* Removal speed (fraction per second) of boundary cell (i, j, k). */
static double dill_speed(const struct cgrid *g, const double *rate, int i, int j, int k)
{
	int ex[6] = {etched_at(g, i - 1, j, k), etched_at(g, i + 1, j, k),
		     etched_at(g, i, j - 1, k), etched_at(g, i, j + 1, k),
		     etched_at(g, i, j, k - 1), etched_at(g, i, j, k + 1)};
	int nface = 0, axes = 0, opposite = 0;
	for (int d = 0; d < 3; d++) {
		nface += ex[2 * d] + ex[2 * d + 1];
		axes += ex[2 * d] || ex[2 * d + 1];
		opposite |= ex[2 * d] && ex[2 * d + 1];
	}
	double R = rate[cidx(g, i, j, k)];
	if (nface == 0 || !(R > 0))
		return 0;
	double a = (g->h[0] + g->h[1] + g->h[2]) / 3;
	if (nface == 1) {
		for (int d = 0; d < 3; d++)
			if (ex[2 * d] || ex[2 * d + 1])
				a = g->h[d];
		return R / a;
	}
	if (opposite || nface >= 4)
		return 2 * R / a;
	return sqrt((double)axes) * R / a;   /* 2 adjacent: sqrt 2; 3 at a corner: sqrt 3 */
}

/* The state of Dill's cell removal (thesis 3.2): the fraction left of
 * every cell, and the boundary cells with their speeds. */
struct dill {
	struct cgrid *g;
	const double *rate;
	double *fr, *v;                 /* per cell; per boundary cell */
	size_t *list, *gone, nlist;     /* the boundary; the cells emptied */
	unsigned char *inlist;
	long maxb;                      /* the largest boundary */
};

static void dill_init(struct dill *dl, struct cgrid *g, const double *rate, size_t n)
{
	memset(dl, 0, sizeof *dl);
	dl->g = g;
	dl->rate = rate;
	dl->fr = xreallocarray(NULL, n, sizeof *dl->fr);
	dl->v = xreallocarray(NULL, n, sizeof *dl->v);
	dl->list = xreallocarray(NULL, n, sizeof *dl->list);
	dl->gone = xreallocarray(NULL, n, sizeof *dl->gone);
	dl->inlist = xcalloc(n, 1);
	for (size_t c = 0; c < n; c++)
		dl->fr[c] = 1;
	/* the first boundary: every unetched cell with an exposed face */
	for (int k = 0; k < g->n[2]; k++)
		for (int j = 0; j < g->n[1]; j++)
			for (int i = 0; i < g->n[0]; i++) {
				size_t c = cidx(g, i, j, k);
				if (!g->et[c] && dill_speed(g, rate, i, j, k) > 0) {
					dl->list[dl->nlist++] = c;
					dl->inlist[c] = 1;
				}
			}
}

static void dill_free(struct dill *dl)
{
	free(dl->fr);
	free(dl->v);
	free(dl->list);
	free(dl->gone);
	free(dl->inlist);
}

/* One step of Dill's removal from t, up to the next cell emptied or tp;
 * returns the new time. */
static double dill_step(struct dill *dl, double t, double tp)
{
	struct cgrid *g = dl->g;
	if ((long)dl->nlist > dl->maxb)
		dl->maxb = (long)dl->nlist;
	double step = INFINITY;
	for (size_t l = 0; l < dl->nlist; l++) {
		size_t c = dl->list[l];
		int i = (int)(c % (size_t)g->n[0]), j = (int)(c / (size_t)g->n[0] % (size_t)g->n[1]);
		int k = (int)(c / ((size_t)g->n[0] * g->n[1]));
		dl->v[l] = dill_speed(g, dl->rate, i, j, k);
		if (dl->v[l] > 0 && dl->fr[c] / dl->v[l] < step)
			step = dl->fr[c] / dl->v[l];
	}
	int cap = !(t + step < tp);
	if (cap)
		step = tp - t;
	/* advance every boundary cell; the emptied ones go and their unetched
	 * neighbours join the boundary */
	size_t keep = 0, nl = dl->nlist, ngone = 0;
	for (size_t l = 0; l < nl; l++) {
		size_t c = dl->list[l];
		dl->fr[c] -= dl->v[l] * step;
		if (dl->fr[c] <= F_TINY) {
			g->et[c] = 1;
			dl->inlist[c] = 0;
			dl->gone[ngone++] = c;
		} else {
			dl->list[keep++] = c;
		}
	}
	dl->nlist = keep;
	for (size_t l = 0; l < ngone; l++) {
		size_t c = dl->gone[l];
		int i = (int)(c % (size_t)g->n[0]), j = (int)(c / (size_t)g->n[0] % (size_t)g->n[1]);
		int k = (int)(c / ((size_t)g->n[0] * g->n[1]));
		int nb[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
				{i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
		for (int e = 0; e < 6; e++) {
			int a0 = nb[e][0], a1 = nb[e][1], a2 = nb[e][2];
			if (a0 < 0 || a1 < 0 || a2 < 0 || a0 >= g->n[0] || a1 >= g->n[1] || a2 >= g->n[2])
				continue;
			size_t c2 = cidx(g, a0, a1, a2);
			if (!g->et[c2] && !dl->inlist[c2]) {
				dl->inlist[c2] = 1;
				dl->list[dl->nlist++] = c2;
			}
		}
	}
	return cap ? tp : t + step;
}

/* One step of the Huygens cell method (thesis 4.3) from t, dt or up to
 * tp: every etched cell on the boundary etches a ball of radius R dt
 * around it.  Returns the new time; *maxb the largest boundary. */
static double huygens_step(struct cgrid *g, const struct rfield *f, double dt, double t,
			   double tp, long *maxb)
{
	double step = dt;
	int cap = !(t + dt < tp - 1e-12 * tp);
	if (cap)
		step = tp - t;
	size_t bcap = 0, nb = 0;
	struct bc { int c[3]; double r; } *b = NULL;
	for (int k = 0; k <= g->n[2]; k++)
		for (int j = 0; j < g->n[1]; j++)
			for (int i = 0; i < g->n[0]; i++) {
				if (!etched_at(g, i, j, k))
					continue;
				if ((i > 0 && !etched_at(g, i - 1, j, k)) ||
				    (i + 1 < g->n[0] && !etched_at(g, i + 1, j, k)) ||
				    (j > 0 && !etched_at(g, i, j - 1, k)) ||
				    (j + 1 < g->n[1] && !etched_at(g, i, j + 1, k)) ||
				    (k > 0 && !etched_at(g, i, j, k - 1)) ||
				    (k + 1 < g->n[2] && !etched_at(g, i, j, k + 1))) {
					double p[3] = {cx(g, 0, i), cx(g, 1, j),
						       k == g->n[2] ? f->hi[2] : cx(g, 2, k)};
					xgrow(&b, &bcap, nb + 1, sizeof *b);
					b[nb].c[0] = i, b[nb].c[1] = j, b[nb].c[2] = k;
					b[nb++].r = rfield_eval(f, p, NULL) * step;
				}
			}
	if ((long)nb > *maxb)
		*maxb = (long)nb;
	for (size_t l = 0; l < nb; l++) {
		double r = b[l].r;
		if (!(r > 0))
			continue;
		int lo[3], hi[3];
		for (int d = 0; d < 3; d++) {
			int rr = (int)floor(r / g->h[d]);
			lo[d] = b[l].c[d] - rr < 0 ? 0 : b[l].c[d] - rr;
			hi[d] = b[l].c[d] + rr > g->n[d] - 1 ? g->n[d] - 1 : b[l].c[d] + rr;
		}
		for (int k = lo[2]; k <= hi[2]; k++)
			for (int j = lo[1]; j <= hi[1]; j++)
				for (int i = lo[0]; i <= hi[0]; i++) {
					double dx = (i - b[l].c[0]) * g->h[0];
					double dy = (j - b[l].c[1]) * g->h[1];
					double dz = (k - b[l].c[2]) * g->h[2];
					if (dx * dx + dy * dy + dz * dz <= r * r)
						g->et[cidx(g, i, j, k)] = 1;
				}
	}
	free(b);
	return cap ? tp : t + step;
}

/* The grid of cells of side about seg over the box of f (dies beyond
 * CELLS_MAX cells), the rate at every cell's centre in *rate, and the
 * start: the open top, or the cells of the seed points etched. */
static size_t cells_setup(struct cgrid *g, const struct rfield *f, const struct etch_opts *o,
			  double seg, double **rate)
{
	memset(g, 0, sizeof *g);
	double total = 1;
	for (int d = 0; d < 3; d++) {
		g->n[d] = (int)fmax(1, ceil((f->hi[d] - f->lo[d]) / seg - 1e-9));
		g->lo[d] = f->lo[d];
		g->h[d] = (f->hi[d] - f->lo[d]) / g->n[d];
		total *= g->n[d];
	}
	if (total > CELLS_MAX)
		die("-seg %g: %.0f cells is more than the %.0f allowed (a larger -seg)", seg, total,
		    CELLS_MAX);
	size_t n = (size_t)total;
	g->et = xcalloc(n, 1);
	double *r = *rate = xreallocarray(NULL, n, sizeof *r);
	for (int k = 0; k < g->n[2]; k++)
		for (int j = 0; j < g->n[1]; j++)
			for (int i = 0; i < g->n[0]; i++) {
				double p[3] = {cx(g, 0, i), cx(g, 1, j), cx(g, 2, k)};
				r[cidx(g, i, j, k)] = rfield_eval(f, p, NULL);
			}
	g->open_top = o->seed == 0;
	for (int s = 0; s < o->seed; s++) {
		int c[3];
		for (int d = 0; d < 3; d++) {
			c[d] = (int)floor((o->seedp[s][d] - g->lo[d]) / g->h[d]);
			c[d] = c[d] < 0 ? 0 : c[d] >= g->n[d] ? g->n[d] - 1 : c[d];
		}
		g->et[cidx(g, c[0], c[1], c[2])] = 1;
	}
	return n;
}

void etch_run_cells(const struct rfield *f, const struct etch_opts *o)
{
	struct cgrid g;
	double seg = o->seg > 0 ? o->seg : fmax(fmax(f->hi[0] - f->lo[0], f->hi[1] - f->lo[1]),
						 f->hi[2] - f->lo[2]) / 30;
	double *rate;
	size_t n = cells_setup(&g, f, o, seg, &rate);
	double dt = o->dt;
	if (o->method == METHOD_HUYGENS && !(dt > 0))
		dt = f->rmax > 0 ? HUYGENS_CELLS_PER_STEP * fmin(fmin(g.h[0], g.h[1]), g.h[2]) / f->rmax
				 : o->et;
	if (o->method == METHOD_HUYGENS && !(o->et / dt <= HUYGENS_MAX_STEPS))
		die("%.3g time steps of %g s to -et %g is more than the %.0f allowed (a larger -dt)",
		    o->et / dt, dt, o->et, HUYGENS_MAX_STEPS);
	double bounds[6] = {f->lo[0], f->hi[0], f->lo[1], f->hi[1], f->lo[2], f->hi[2]};
	struct plot_writer *w3 = o->out3d ? fmt_plot_open(o->out3d, 3) : NULL;
	struct plot_writer *w2 = o->out2d ? fmt_plot_open(o->out2d, 2) : NULL;
	fmt_plot_labels(w3, fmt_labels_std(LABELS_SURFACE));
	fmt_plot_labels(w2, fmt_labels_std(LABELS_TOPVIEW));
	/* the print times (ptimes.h), at most CELLS_MAX_PRINTS */
	if (ptimes_count(o->et, o->pt) > CELLS_MAX_PRINTS)
		die("-pt %g against -et %g: too many print times", o->pt, o->et);
	int ntp;
	double *tps = ptimes_make(o->et, o->pt, &ntp), t = 0;
	long steps = 0, maxb = 0;
	struct dill dl;
	if (o->method == METHOD_CELL)
		dill_init(&dl, &g, rate, n);
	for (int q = 0; q < ntp; q++) {
		double tp = tps[q];
		while (t < tp) {
			if (o->method == METHOD_CELL)
				t = dill_step(&dl, t, tp);
			else
				t = huygens_step(&g, f, dt, t, tp, &maxb);
			steps++;
		}
		faces(&g, w3, w2, bounds);
	}
	free(tps);
	if (o->method == METHOD_CELL) {
		maxb = dl.maxb;
		dill_free(&dl);
	}
	if (!o->quiet)
		fprintf(stderr, "%s: %s: %d x %d x %d cells of %g um, %ld steps, largest boundary %ld cells\n",
			util_prog(), o->method == METHOD_CELL ? "cell" : "huygens", g.n[0], g.n[1], g.n[2],
			seg, steps, maxb);
	if (w3)
		fmt_plot_close(w3);
	if (w2)
		fmt_plot_close(w2);
	free(g.et);
	free(rate);
}
