/*
 * surface.c - the tiles' developed surfaces (plot3d(5), one set per print
 * time) joined into one (stitch, the default job).  Each tile's
 * triangles are moved to the output's coordinates, cut to the tile's
 * core and kept in a scratch file, one per set, with the seams
 * (surf_stitch.h); when every tile is read the seams are welded and the
 * sets written in order, each triangle as a closed curve of 4 points as
 * etch writes them.  Only one tile is held (a tile repeated in a row is
 * read once), and the scratch files hold the output in binary.
 */
#include "fmt_plot.h"
#include "stitch.h"
#include "surf_stitch.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Triangles formatted per call of fmt_plot_curves. */
enum { CHUNK = 1 << 18 };

/* The z bounds of the tiles agree to this (um). */
#define Z_EPS 1e-9

struct sink {
	FILE *f;
	size_t n;
};

static void emit(void *ctx, const double *t9)
{
	struct sink *s = ctx;
	if (fwrite(t9, sizeof *t9, 9, s->f) != 9)
		die("a scratch file: cannot write:");
	s->n++;
}

static void get(void *ctx, size_t i, double *p)
{
	const double *t = (const double *)ctx + 9 * i;
	memcpy(p, t, 9 * sizeof *p);
	memcpy(p + 9, t, 3 * sizeof *p);
}

static void write_sets(const char *out, struct stitch *st, struct sink *sk, int nsets,
		       const struct plot_labels *labels)
{
	struct plot_writer *w = fmt_plot_open(out, 3);
	fmt_plot_labels(w, labels);
	double *buf = xreallocarray(NULL, 9 * (size_t)CHUNK, sizeof *buf);
	for (int s = 0; s < nsets; s++) {
		fmt_plot_begin_set(w, st[s].box, (long)sk[s].n);
		if (fflush(sk[s].f) != 0 || fseek(sk[s].f, 0, SEEK_SET) != 0)
			die("a scratch file: cannot read back:");
		for (size_t done = 0; done < sk[s].n;) {
			size_t m = sk[s].n - done < CHUNK ? sk[s].n - done : CHUNK;
			if (fread(buf, 9 * sizeof *buf, m, sk[s].f) != m)
				die("a scratch file: cannot read back:");
			fmt_plot_curves(w, m, 4, get, buf);
			done += m;
		}
		fclose(sk[s].f);
	}
	free(buf);
	fmt_plot_close(w);
}

/* Cuts set s of tile k (pf) into sk, keeping its seams in st. */
static void cut_set(const struct tile *t, int k, const struct plot_set *set, struct stitch *st,
		    struct sink *sk)
{
	if (fabs(set->bounds[4] - st->box[4]) > Z_EPS || fabs(set->bounds[5] - st->box[5]) > Z_EPS)
		die("%s: z from %g to %g, not the first tile's %g to %g", t[k].file, set->bounds[4],
		    set->bounds[5], st->box[4], st->box[5]);
	for (int c = 0; c < set->ncurves; c++) {
		const struct plot_curve *cv = &set->curves[c];
		if (cv->npts != 4 || memcmp(cv->p, cv->p + 9, 3 * sizeof *cv->p) != 0)
			die("%s: curve %d of a set is not a triangle (a closed curve of 4 points)",
			    t[k].file, c + 1);
		double tri[9];
		for (int v = 0; v < 3; v++) {
			tri[3 * v] = cv->p[3 * v] + t[k].dx;
			tri[3 * v + 1] = cv->p[3 * v + 1] + t[k].dy;
			tri[3 * v + 2] = cv->p[3 * v + 2];
		}
		stitch_clip(st, k, t[k].core, tri, emit, sk);
	}
}

long stitch_surfaces(const struct tile *t, int n, const char *out)
{
	double box[6] = {INFINITY, -INFINITY, INFINITY, -INFINITY, 0, 0};
	for (int k = 0; k < n; k++) {
		box[0] = fmin(box[0], t[k].core[0]), box[1] = fmax(box[1], t[k].core[1]);
		box[2] = fmin(box[2], t[k].core[2]), box[3] = fmax(box[3], t[k].core[3]);
	}
	struct plot_file *pf = NULL;
	struct stitch *st = NULL;
	struct sink *sk = NULL;
	struct plot_labels labels;
	int nsets = 0;
	const char *cur = NULL;
	for (int k = 0; k < n; k++) {
		if (!cur || strcmp(cur, t[k].file) != 0) {
			fmt_plot_free(pf);
			pf = fmt_plot_read(t[k].file, 3);
			cur = t[k].file;
		}
		if (k == 0) {
			nsets = pf->nsets;
			if (nsets < 1)
				die("%s: no surface", cur);
			labels = pf->labels;
			st = xcalloc((size_t)nsets, sizeof *st);
			sk = xcalloc((size_t)nsets, sizeof *sk);
			for (int s = 0; s < nsets; s++) {
				box[4] = pf->sets[s].bounds[4], box[5] = pf->sets[s].bounds[5];
				stitch_init(&st[s], box);
				if (!(sk[s].f = tmpfile()))
					die("cannot open a scratch file:");
			}
		}
		if (pf->nsets != nsets)
			die("%s: %d sets (print times), not the first tile's %d", cur, pf->nsets, nsets);
		for (int s = 0; s < nsets; s++)
			cut_set(t, k, &pf->sets[s], &st[s], &sk[s]);
	}
	fmt_plot_free(pf);
	long open = 0;
	for (int s = 0; s < nsets; s++) {
		stitch_weld(&st[s], emit, &sk[s]);
		open += (long)(st[s].unmatched + st[s].corners_open);
	}
	write_sets(out, st, sk, nsets, &labels);
	for (int s = 0; s < nsets; s++)
		stitch_free(&st[s]);
	free(st);
	free(sk);
	return open;
}
