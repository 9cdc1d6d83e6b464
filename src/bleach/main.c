/*
 * bleach - 3D exposure of a photoresist (thesis 2.1, 8.6, Appendix B):
 * reads splat's aerial image (a contour-file) and a resist/process
 * description (bleach.5), computes the PAC concentration M(x, y, z) with
 * Dill bleaching under standing waves, the post-exposure bake, and the
 * development rate, and writes the rate array for etch (rval.3D.binary,
 * or rval.3D with -ascii), carrying M as a second array.  -solid also
 * writes mxyz.solid.3D, the surface M = level (Figure 8.15).
 *
 * main.c reads the command line; run.c is the pipeline.
 */
#include "args.h"
#include "budget.h"
#include "bleach.h"
#include "cutline.h"
#include "num.h"
#include "par.h"
#include "util.h"

#include <stdlib.h>
#include <string.h>

static const char usage[] =
	"usage: bleach [-ascii] [-solid] [-m level] [-o rate-file] [-q] [-dose D] [-seed S] [-nz N]\n"
	"              [-big] [-threads n] contour-file bleach-inputfile\n"
	"       bleach -cutline [-ascii] [-o rate-file] [-q] cutline-plot bleach-inputfile\n"
	"       bleach -check bleach-inputfile\n"
	"  -check         read and check the bleach input file only (its first problem,\n"
	"                 or nothing and exit 0), as sample3D does before any stage runs\n"
	"  -cutline       the first file is a cutline of splat (a 2D plot file): write the\n"
	"                 2D rate array (ny = 1) over (distance along the cut, z) for etch2d\n"
	"  -ascii         write the rate array as ASCII rval.3D (default binary rval.3D.binary)\n"
	"  -solid         also write mxyz.solid.3D, the surface M = level, for pdraw\n"
	"  -m level       M of that surface (default 0.8)\n"
	"  -o rate-file   name of the rate array file\n"
	"  -q             no progress lines on stderr\n"
	"  -dose D        exposure dose in mJ/cm2, replacing the input's dose statement\n"
	"  -seed S        the shot noise's seed, replacing the stochastic statement's\n"
	"  -nz N          points through the resist, replacing the input's grid nz\n"
	"  -big           run work estimated beyond the limits (an hour, the\n"
	"                 machine's memory; also SAMPLE3D_BIG=1)\n"
	"  -threads n     threads to use (default $SAMPLE3D_THREADS, else every core)\n";

/* Largest -dose, mJ/cm2: bleach(5)'s bound on the dose statement. */
static const double DOSE_MAX = 1e6;

struct options {
	int ascii, solid, quiet, cutline, check;
	long threads;
	long nz;                /* -nz, 0 when not given */
	double level;
	const char *output;
	const char *dose;       /* -dose value, checked after parsing */
	long seed;              /* -seed value, -1 if not given */
	const char *contour;
	const char *input;
};

static void parse_options(int argc, char **argv, struct options *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage, NULL, NULL);
	memset(o, 0, sizeof *o);
	o->level = 0.8;
	o->seed = -1;
	while (a.i < argc) {
		args_help_exit(&a, 1);
		if (args_flag(&a, "-ascii"))
			o->ascii = 1;
		else if (args_flag(&a, "-solid"))
			o->solid = 1;
		else if (args_flag(&a, "-cutline"))
			o->cutline = 1;
		else if (args_flag(&a, "-check"))
			o->check = 1;
		else if (args_flag(&a, "-q"))
			o->quiet = 1;
		else if (args_flag(&a, "-big"))
			budget_allow_big();
		else if (args_int(&a, "-threads", 1, PAR_MAX_THREADS, &o->threads))
			;
		else if (args_int(&a, "-nz", 2, BLEACH_MAX_NZ, &o->nz))
			;
		else if (args_num(&a, "-m", 0, 1, &o->level))
			;
		else if (args_str(&a, "-o", &o->output))
			;
		else if (args_str(&a, "-dose", &o->dose))
			;
		else if (args_int(&a, "-seed", 0, BLEACH_MAX_SEED, &o->seed))
			;
		else
			args_operand(&a, (const char **[]){&o->contour, &o->input}, 2, "file");
	}
	if (o->cutline && o->solid)
		args_error(&a, "-solid draws a 3D array: not with -cutline");
	if (o->cutline && o->nz)
		args_error(&a, "-nz sets the 3D array's grid: not with -cutline");
	if (o->check) {
		/* the one operand is the input file */
		if (!o->contour)
			args_error(&a, "-check: no bleach-inputfile");
		else if (o->input)
			args_error(&a, "-check takes the bleach-inputfile alone");
		o->input = o->contour;
		o->contour = NULL;
	} else if (!o->contour)
		args_error(&a, "no contour-file");
	else if (!o->input)
		args_error(&a, "no bleach-inputfile");
	args_done(&a, NULL);
}

int main(int argc, char **argv)
{
	util_setprog(argv[0]);
	struct options o;
	parse_options(argc, argv, &o);
	par_set_threads((int)o.threads);
	if (o.check) {
		struct bleach_input in;
		fmt_bleach_read(o.input, &in);
		return 0;
	}
	if (o.cutline) {
		cutline_bleach(o.contour, o.input, o.output ? o.output : o.ascii ? "rval.2D" :
			       "rval.2D.binary", o.ascii, o.quiet);
		return 0;
	}

	/* -dose D: the range of bleach(5)'s dose statement; a bad value is a
	 * one-line usage error (sweep scripts read it in a log) */
	struct bleach_opts b = {o.contour, o.input, o.output, o.ascii, o.solid, o.quiet,
				o.level, o.dose != NULL, 0, o.seed, (int)o.nz};
	/* dose 0 exposes nothing: refused, as fem refuses it */
	if (o.dose && (!num_parse(o.dose, &b.dose) || !(b.dose > 0 && b.dose <= DOSE_MAX)))
		die_status(EXIT_USAGE, "option -dose: expected a number above 0 up to %g, found \"%.40s\"",
			   DOSE_MAX, o.dose);
	bleach_run(&b);
	return 0;
}
