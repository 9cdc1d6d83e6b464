/*
 * stitch - layouts beyond one window: cuts a splat input into tiles
 * with halos (-cut), and joins the tiles' results, their developed
 * surfaces (plot3d(5)) or their aerial images (-image, contour(5)), into
 * one, each tile taken only in its core.  The drivers' -tile (sample3D)
 * runs it; see stitch(1) for the design and its accuracy.
 */
#include "args.h"
#include "num.h"
#include "stitch.h"
#include "surf_stitch.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
	"usage: stitch -cut W [-halo H] [-d DIR] splat-inputfile\n"
	"       stitch [-image] [-o FILE] [-q] [-window XMIN XMAX YMIN YMAX]\n"
	"              -t FILE DX DY XMIN XMAX YMIN YMAX ...\n"
	"  -cut W      cut the splat input into tiles whose cores are W um wide,\n"
	"              rounded to its grid; writes DIR/tNNNN.in per tile and prints\n"
	"              one line per tile: tNNNN.in DX DY XMIN XMAX YMIN YMAX\n"
	"  -halo H     the margin around each core (um, rounded up to the grid;\n"
	"              default 3 lambda/NA)\n"
	"  -d DIR      where -cut writes the tiles (default tiles)\n"
	"  -t FILE DX DY XMIN XMAX YMIN YMAX  one tile: its result, the shift from\n"
	"              its coordinates to the output's, its core (output's, um)\n"
	"  -image      the tiles are contour-files (aerial images); without it\n"
	"              plot3d surfaces, cut to their cores and welded at the seams\n"
	"  -window XMIN XMAX YMIN YMAX  join only this part of the cores (um)\n"
	"  -o FILE     the output (default stitched.plot, with -image stitched.cont)\n"
	"  -q          quiet: no line about open seams\n"
	"  -h, --help  this text\n";

struct options {
	double cut, halo;
	int have_cut, image, quiet, have_window;
	double window[4];
	const char *dir, *out, *input;
	struct tile *t;
	int nt;
};

/* -window XMIN XMAX YMIN YMAX */
static void window_arg(struct args *a, struct options *o)
{
	char **v = a->argv + a->i;
	if (a->i + 4 >= a->argc) {
		args_error(a, "-window needs XMIN XMAX YMIN YMAX");
		a->i = a->argc;
		return;
	}
	for (int k = 0; k < 4; k++)
		if (!num_parse(v[1 + k], &o->window[k]) || !isfinite(o->window[k]))
			args_error(a, "-window: %s is not a number", v[1 + k]);
	if (!(o->window[0] < o->window[1] && o->window[2] < o->window[3]))
		args_error(a, "-window must have XMIN < XMAX and YMIN < YMAX");
	o->have_window = 1;
	a->i += 5;
}

/* The cores cut to the window; tiles left without a core dropped. */
static void apply_window(struct options *o)
{
	int m = 0;
	for (int k = 0; k < o->nt; k++) {
		double *c = o->t[k].core;
		c[0] = fmax(c[0], o->window[0]), c[1] = fmin(c[1], o->window[1]);
		c[2] = fmax(c[2], o->window[2]), c[3] = fmin(c[3], o->window[3]);
		if (c[0] < c[1] && c[2] < c[3])
			o->t[m++] = o->t[k];
	}
	o->nt = m;
	if (m == 0)
		die("-window %g %g %g %g: no core meets it", o->window[0], o->window[1],
		    o->window[2], o->window[3]);
}

/* -t FILE DX DY XMIN XMAX YMIN YMAX */
static void tile_arg(struct args *a, struct options *o, size_t *cap)
{
	char **v = a->argv + a->i;
	if (a->i + 7 >= a->argc) {
		args_error(a, "-t needs a file, a shift DX DY and a core XMIN XMAX YMIN YMAX");
		a->i = a->argc;
		return;
	}
	struct tile t = {.file = v[1]};
	double *x[6] = {&t.dx, &t.dy, &t.core[0], &t.core[1], &t.core[2], &t.core[3]};
	for (int k = 0; k < 6; k++)
		if (!num_parse(v[2 + k], x[k]) || !isfinite(*x[k]))
			args_error(a, "-t %s: %s is not a number", v[1], v[2 + k]);
	if (!(t.core[0] < t.core[1] && t.core[2] < t.core[3]))
		args_error(a, "-t %s: the core must have XMIN < XMAX and YMIN < YMAX", v[1]);
	xgrow(&o->t, cap, (size_t)o->nt + 1, sizeof *o->t);
	o->t[o->nt++] = t;
	a->i += 8;
}

static void parse_options(int argc, char **argv, struct options *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage, NULL, NULL);
	memset(o, 0, sizeof *o);
	o->halo = -1;
	size_t cap = 0;
	int have_halo = 0;
	while (a.i < argc) {
		args_help_exit(&a, 1);
		if (strcmp(argv[a.i], "-t") == 0)
			tile_arg(&a, o, &cap);
		else if (strcmp(argv[a.i], "-window") == 0)
			window_arg(&a, o);
		else if (args_num(&a, "-cut", 0, INFINITY, &o->cut))
			o->have_cut = 1;
		else if (args_num(&a, "-halo", 0, INFINITY, &o->halo))
			have_halo = 1;
		else if (args_flag(&a, "-image"))
			o->image = 1;
		else if (args_flag(&a, "-q"))
			o->quiet = 1;
		else if (args_str(&a, "-d", &o->dir) || args_str(&a, "-o", &o->out))
			;
		else
			args_operand(&a, (const char **[]){&o->input}, 1, "splat input file");
	}
	if (o->have_cut) {
		if (!(o->cut > 0))
			args_error(&a, "-cut: the tile must be wider than 0 um");
		if (!o->input)
			args_error(&a, "-cut needs the splat input file");
		if (o->nt || o->image || o->out || o->have_window)
			args_error(&a, "-cut writes tiles: -t, -image, -window and -o belong to the join");
	} else {
		if (have_halo || o->dir)
			args_error(&a, "-halo and -d belong to -cut");
		if (o->input)
			args_error(&a, "%s: the join takes its tiles with -t", o->input);
		else if (o->nt == 0)
			args_error(&a, "nothing to do: give -cut W and a splat input, or tiles with -t");
	}
	args_done(&a, NULL);
}

int main(int argc, char **argv)
{
	util_setprog(argv[0]);
	struct options o;
	parse_options(argc, argv, &o);
	if (o.have_window)
		apply_window(&o);
	if (o.have_cut) {
		stitch_cut(o.input, o.cut, o.halo, o.dir ? o.dir : "tiles");
	} else if (o.image) {
		stitch_images(o.t, o.nt, o.out ? o.out : "stitched.cont");
	} else {
		const char *out = o.out ? o.out : "stitched.plot";
		long open = stitch_surfaces(o.t, o.nt, out);
		if (open && !o.quiet)
			warn("%s: %ld seam curves or corners left open (the tiles disagree there "
			     "by more than %g um)", out, open, STITCH_MATCH_UM);
	}
	free(o.t);
	fshut(stdout, "stdout");
	return 0;
}
