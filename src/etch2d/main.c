/*
 * etch2d - 2D development of a resist cross-section (a rate array with
 * ny = 1) by any of the thesis' etching algorithms (chapters 3-7) or a
 * fast-marching reference.  See man/man1/etch2d.1 and etch2d.h.
 */
#include "args.h"
#include "etch2d.h"
#include "fmt_rate.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

static const char usage[] =
	"usage: etch2d -et etchtime [-pt printtime]\n"
	"              [-method raystring|string|ray|cell|huygens|fmm] [-seed x z]\n"
	"              [-cells nx nz] [-seg length] [-dt timestep] [-rl length]\n"
	"              [-start profile.plot]\n"
	"              [-o profile.plot] [-stats] rate-file\n"
	"  -et etchtime     total development time, s (required)\n"
	"  -pt printtime    print interval, s (default: only the end)\n"
	"  -method M        raystring (default, thesis ch. 7), string (6.2), ray (6.3),\n"
	"                   cell (Dill, ch. 3), huygens (ch. 4), fmm (fast marching)\n"
	"  -seed x z        develop from this point on the resist top only (the top\n"
	"                   is then a wall); default: from the whole top\n"
	"  -cells nx nz     cells tiling the box (cell, huygens, fmm; default 200\n"
	"                   along the longer side, square cells)\n"
	"  -seg length      node or ray spacing S_ideal, um (default width / 50)\n"
	"  -dt timestep     time step, s (default 0.1; huygens: 10 cells at max R)\n"
	"  -rl length       recursive length of vector checking (default 0.1)\n"
	"  -start profile.plot  develop from this profile (plot2d(5): the last set's\n"
	"                   one polyline, wall to wall; etched above it)\n"
	"  -o profile.plot  output, a 2D plot file, one set per print time\n"
	"                   (default profile.plot)\n"
	"  -stats           print CPU time, memory, nodes or cells and steps\n";

/* Largest cell or node grid: 2^24, about 0.5 GB for fast marching. */
#define E2_MAX_CELLS 16777216.0
/* A seed this close (relative to the depth) to the top is on it. */
#define SEED_TOP_TOL 1e-9

static const char *method_names[] = {"raystring", "string", "ray", "cell", "huygens", "fmm"};

static void parse_options(int argc, char **argv, struct e2opts *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage, NULL, NULL);
	memset(o, 0, sizeof *o);
	o->et = -1;
	o->rl = 0.1;
	o->out = "profile.plot";
	const char *method = "raystring";
	while (a.i < argc) {
		args_help_exit(&a, 1);
		if (args_num(&a, "-et", 0, 1e12, &o->et) ||
		    args_num(&a, "-pt", 0, 1e12, &o->pt) ||
		    args_num(&a, "-seg", 0, 1e12, &o->seg) ||
		    args_num(&a, "-dt", 0, 1e12, &o->dt) ||
		    args_num(&a, "-rl", 0, 2, &o->rl) ||
		    args_str(&a, "-o", &o->out) ||
		    args_str(&a, "-start", &o->startfile) ||
		    args_str(&a, "-method", &method))
			;
		else if (args_flag(&a, "-stats"))
			o->stats = 1;
		else if (strcmp(argv[a.i], "-seed") == 0 || strcmp(argv[a.i], "-cells") == 0) {
			int seed = argv[a.i][1] == 's';
			a.i++;
			for (int k = 0; k < 2; k++, a.i++) {
				const char *v = a.i < argc ? argv[a.i] : NULL;
				if (seed ? !(v && num_parse(v, &o->seed[k]))
					 : !(v && num_parse_count(v, 1, 1L << 24, &o->cells[k]))) {
					args_error(&a, seed ? "option -seed needs two numbers, x and z"
							    : "option -cells needs two whole numbers from 1 to 16777216");
					break;
				}
			}
			o->seeded |= seed;
		} else
			args_operand(&a, (const char **[]){&o->input}, 1, "rate-file");
	}
	o->method = -1;
	for (int m = 0; m < 6; m++)
		if (strcmp(method, method_names[m]) == 0)
			o->method = m;
	if (o->method < 0)
		args_error(&a, "unknown -method %s (raystring, string, ray, cell, huygens or fmm)", method);
	if (!(o->et > 0))
		args_error(&a, "-et etchtime is required (a time above 0 s)");
	if (!o->input)
		args_error(&a, "no rate-file");
	if (o->startfile && o->seeded)
		args_error(&a, "-start and -seed exclude each other (a start profile or a seed)");
	args_done(&a, NULL);
}

/* What main holds while it may still die: reachable from a global (not
 * static: a write-only static may be optimised away) so that a fatal
 * error is not reported as a leak by the sanitizers. */
struct etch2d_held { struct ratefile *r; struct plot_file *start; struct e2 e; } etch2d_held;

int main(int argc, char **argv)
{
	util_setprog(argv[0]);
	struct e2opts o;
	parse_options(argc, argv, &o);
	struct ratefile *r = etch2d_held.r = fmt_rate_read(o.input);
	if (r->ny != 1)
		die("%s:1: a 3D rate array (ny = %d): etch2d develops a 2D one (ny = 1); use etch",
		    o.input, r->ny);
	struct rfield f;
	fmt_rate_field(&f, r, o.input);
	if (o.seeded) {
		if (o.seed[0] < f.lo[0] || o.seed[0] > f.hi[0] || o.seed[1] < f.lo[2] || o.seed[1] > f.hi[2])
			die("-seed %g %g: outside the rate array's box x %g..%g, z %g..%g",
			    o.seed[0], o.seed[1], f.lo[0], f.hi[0], f.lo[2], f.hi[2]);
		int surface = o.method == M_RAYSTRING || o.method == M_STRING || o.method == M_RAY;
		if (surface && fabs(o.seed[1] - f.hi[2]) > SEED_TOP_TOL * (f.hi[2] - f.lo[2]))
			die("-seed %g %g: with -method %s the seed must be on the resist top (z = %g)",
			    o.seed[0], o.seed[1], method_names[o.method], f.hi[2]);
		if (surface)
			o.seed[1] = f.hi[2];
	}
	if (o.startfile) {
		/* the last set's single polyline: an etch2d profile's last time
		 * serves as well as a drawn one */
		struct plot_file *sp = etch2d_held.start = fmt_plot_read(o.startfile, 2);
		const struct plot_set *s = sp->nsets ? &sp->sets[sp->nsets - 1] : NULL;
		if (!s || s->ncurves != 1)
			die("%s:1: -start needs one polyline in the last set (it has %d)",
			    o.startfile, s ? s->ncurves : 0);
		o.start = s->curves[0].p;
		o.nstart = s->curves[0].npts;
	}
	struct e2 *ep = &etch2d_held.e;
	e2_init(ep, &f, &o);
	if (o.method == M_CELL || o.method == M_HUYGENS || o.method == M_FMM) {
		int nx, nz;
		e2_cells(ep, &nx, &nz);
		double cells = (double)(nx + 1) * (nz + 1);
		if (cells > E2_MAX_CELLS)
			die("-cells %d %d: %.0f cells is more than the %.0f allowed", nx, nz, cells,
			    E2_MAX_CELLS);
	}
	e2_run(ep);
	const struct e2 *e = ep;
	fmt_plot_write(o.out, e->pf);
	if (o.stats) {
		struct rusage ru;
		getrusage(RUSAGE_SELF, &ru);
		const char *what = o.method == M_CELL || o.method == M_HUYGENS ? "boundary cells"
				   : o.method == M_FMM ? "trial nodes" : o.method == M_RAY ? "rays" : "nodes";
		fprintf(stderr, "%s: method %s: cpu %.3f s, memory %zu bytes (peak RSS %ld kB), "
			"%s %ld", util_prog(), method_names[o.method], e->st.cpu, e->st.bytes,
			(long)ru.ru_maxrss, what, e->st.items);
		if (e->st.total)
			fprintf(stderr, " of %ld cells", e->st.total);
		fprintf(stderr, ", steps %ld", e->st.steps);
		if (o.method == M_STRING || o.method == M_RAYSTRING)
			fprintf(stderr, ", loops removed %ld", e->st.loops);
		fputc('\n', stderr);
	}
	e2_free(ep);
	if (etch2d_held.start)
		fmt_plot_free(etch2d_held.start);
	fmt_rate_free(r);
	return 0;
}
