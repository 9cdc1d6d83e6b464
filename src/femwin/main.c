/*
 * femwin - the tables of a focus-exposure matrix, for fem(1) and by hand:
 * collects the points' measure tables into fem.dat with the Bossung plot
 * (-collect), computes the process window of a fem.dat (-target, -tol),
 * writes the probe surface fem checks measure's arguments on (-probe),
 * or prints the grids the drivers' -accuracy refines (-resolution).
 */
#include "args.h"
#include "femwin.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
	"usage: femwin -target CD -tol PCT [-o window.dat] [-plot window.2D]\n"
	"              [-region region.2D [-region-template file]] fem.dat\n"
	"       femwin -collect [-o fem.dat] [-bossung bossung.2D] [-template file]\n"
	"              [-stochastic stoch.dat] -p focus dose measure-table ...\n"
	"       femwin -probe mask.in resist.in [-o probe.plot]\n"
	"       femwin -resolution mask.in resist.in\n"
	"  -target CD       the CD in spec (um)\n"
	"  -tol PCT         in spec when |cd - CD| <= PCT % of CD (and cleared)\n"
	"  -o file          output: window.dat, fem.dat or the probe surface\n"
	"                   (defaults window.dat, fem.dat, probe.plot)\n"
	"  -plot file       the EL/DOF curve as a 2D plot file for drawplot\n"
	"  -region file     the in-spec region in (focus, dose) and the 5 % and\n"
	"                   10 % EL rectangles, as a 2D plot file\n"
	"  -region-template file  drawplot template labelling those curves\n"
	"  -collect         make fem.dat from the points' measure tables\n"
	"  -p f d table     one point: focus (um), dose (mJ/cm2), measure's table\n"
	"  -bossung file    cd against focus, one curve per dose (2D plot file)\n"
	"  -template file   drawplot template labelling the Bossung curves by dose\n"
	"  -stochastic file a point given more than once holds seeds: fem.dat gets\n"
	"                   their mean cd, file the mean, 3 sigma and failures\n"
	"  -probe m r       the undeveloped resist of splat input m and bleach\n"
	"                   input r as a surface, to try measure's arguments on\n"
	"  -resolution m r  print the image grid of m and the points through the\n"
	"                   resist of r: nx ny nz (what the drivers' -accuracy refines)\n";

enum mode { M_NONE, M_WINDOW, M_COLLECT, M_PROBE, M_RESOLUTION };

struct options {
	enum mode mode;
	double target, tol;
	int have_target, have_tol;
	const char *out, *plot, *bossung, *template, *fem, *region, *region_tpl, *stoch;
	const char *probe_mask, *probe_resist;
	struct femwin_input *pts;
	int npts;
};

static void set_mode(struct args *a, struct options *o, enum mode m, const char *opt)
{
	if (o->mode != M_NONE && o->mode != m)
		args_error(a, "%s: -collect, -probe, -resolution and -target/-tol are different "
			   "jobs", opt);
	o->mode = m;
}

static void parse_options(int argc, char **argv, struct options *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage, NULL, NULL);
	memset(o, 0, sizeof *o);
	size_t cap = 0;
	while (a.i < argc) {
		args_help_exit(&a, 1);
		const char *w = argv[a.i];
		if (strcmp(w, "-p") == 0) {
			set_mode(&a, o, M_COLLECT, w);
			if (a.i + 3 >= argc) {
				args_error(&a, "-p needs a focus, a dose and a measure table");
				a.i = argc;
				break;
			}
			struct femwin_input in;
			int ok = num_parse(argv[a.i + 1], &in.focus) && num_parse(argv[a.i + 2], &in.dose);
			if (!ok || !(in.dose > 0))
				args_error(&a, "-p %s %s: expected a focus (um) and a positive dose",
					   argv[a.i + 1], argv[a.i + 2]);
			in.table = argv[a.i + 3];
			xgrow(&o->pts, &cap, (size_t)o->npts + 1, sizeof *o->pts);
			o->pts[o->npts++] = in;
			a.i += 4;
		} else if (strcmp(w, "-probe") == 0 || strcmp(w, "-resolution") == 0) {
			set_mode(&a, o, w[1] == 'p' ? M_PROBE : M_RESOLUTION, w);
			if (a.i + 2 >= argc) {
				args_error(&a, "%s needs a splat and a bleach input file", w);
				a.i = argc;
				break;
			}
			o->probe_mask = argv[a.i + 1];
			o->probe_resist = argv[a.i + 2];
			a.i += 3;
		} else if (args_flag(&a, "-collect")) {
			set_mode(&a, o, M_COLLECT, "-collect");
		} else if (args_num(&a, "-target", 0, INFINITY, &o->target)) {
			set_mode(&a, o, M_WINDOW, "-target");
			o->have_target = 1;
		} else if (args_num(&a, "-tol", 0, 100, &o->tol)) {
			set_mode(&a, o, M_WINDOW, "-tol");
			o->have_tol = 1;
		} else if (args_str(&a, "-o", &o->out) || args_str(&a, "-plot", &o->plot) ||
			   args_str(&a, "-region", &o->region) ||
			   args_str(&a, "-region-template", &o->region_tpl) ||
			   args_str(&a, "-bossung", &o->bossung) ||
			   args_str(&a, "-template", &o->template) ||
			   args_str(&a, "-stochastic", &o->stoch)) {
			;
		} else {
			args_operand(&a, (const char **[]){&o->fem}, 1, "fem.dat");
		}
	}
	switch (o->mode) {
	case M_NONE:
		args_error(&a, "nothing to do: give -target and -tol, -collect, -probe or "
			   "-resolution");
		break;
	case M_WINDOW:
		if (!o->have_target || !o->have_tol)
			args_error(&a, "the process window needs both -target and -tol");
		else if (!(o->target > 0) || !(o->tol > 0))
			args_error(&a, "-target and -tol must be positive");
		if (!o->fem)
			args_error(&a, "which fem.dat?");
		if (o->bossung || o->template || o->stoch)
			args_error(&a, "-bossung, -template and -stochastic belong to -collect");
		if (o->region_tpl && !o->region)
			args_error(&a, "-region-template goes with -region");
		break;
	case M_COLLECT:
		if (o->npts == 0)
			args_error(&a, "-collect needs at least one point (-p focus dose table)");
		if (o->fem)
			args_error(&a, "-collect takes its points with -p, not %s", o->fem);
		if (o->plot || o->region || o->region_tpl)
			args_error(&a, "-plot and -region belong to the process window");
		break;
	case M_PROBE:
		if (o->fem || o->plot || o->bossung || o->template || o->region || o->region_tpl ||
		    o->stoch)
			args_error(&a, "-probe takes only -o");
		break;
	case M_RESOLUTION:
		if (o->fem || o->out || o->plot || o->bossung || o->template || o->region ||
		    o->region_tpl)
			args_error(&a, "-resolution takes no other option");
		break;
	}
	args_done(&a, NULL);
}

int main(int argc, char **argv)
{
	util_setprog(argv[0]);
	struct options o;
	parse_options(argc, argv, &o);
	int status = 0;
	switch (o.mode) {
	case M_WINDOW: {
		struct fem_table *t = fmt_fem_read(o.fem);
		struct femwin_spec s = {o.target, o.tol};
		femwin_window(t, &s, o.fem, o.out ? o.out : "window.dat", o.plot, o.region,
			      o.region_tpl);
		fmt_fem_free(t);
		break;
	}
	case M_COLLECT:
		status = femwin_collect(o.pts, o.npts, o.out ? o.out : "fem.dat", o.bossung,
					o.template, o.stoch) ? EXIT_RUNTIME : 0;
		break;
	case M_PROBE:
		femwin_probe(o.probe_mask, o.probe_resist, o.out ? o.out : "probe.plot");
		break;
	case M_RESOLUTION:
		femwin_resolution(o.probe_mask, o.probe_resist);
		break;
	case M_NONE:
		break;
	}
	free(o.pts);
	fshut(stdout, "stdout");
	return status;
}
