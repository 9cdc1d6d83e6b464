/*
 * measure - CD metrology on a developed resist surface (a set of the
 * curves.plot that etch writes): the CD of a hole, space or line at given
 * heights, the sidewall angle, the resist loss and whether the feature
 * clears.  See man/man1/measure.1.
 */
#include "args.h"
#include "fmt_plot.h"
#include "measure.h"
#include "fmt_measure.h"
#include "rough.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
	"usage: measure [-s set] (-at z1,z2,... | -rel p1,p2,...)\n"
	"               (-hole X Y | -space X Y x|y | -line X Y x|y | -holes)\n"
	"               [-ler [-psd file]] [-lcdu] [-o file] [-plot file] [-force]\n"
	"               [-accuracy P|check -coarse table [-ratio r]\n"
	"                [-coarser table [-ratio2 q] [-coarser-fine table]]\n"
	"                [-order p] [-plus table]] surface.plot\n"
	"  -s set          the set (print time) to measure, from 1 in file order\n"
	"                  (default: the last)\n"
	"  -at z1,z2,...   heights, um (absolute, within the box's z range)\n"
	"  -rel p1,p2,...  heights at p percent of the resist thickness above\n"
	"                  the substrate: z = zmin + p/100 (zmax - zmin)\n"
	"  -hole X Y       the developed opening containing (X, Y): cd is the\n"
	"                  diameter of the circle of its area\n"
	"  -space X Y x|y  the width of the developed interval through (X, Y)\n"
	"                  along x (or y)\n"
	"  -line X Y x|y   the width of the resist interval through (X, Y)\n"
	"  -holes          every hole of the section (with -lcdu)\n"
	"  -ler            with -space or -line at one height: the roughness of\n"
	"                  its two edges along the whole box (LER, LWR,\n"
	"                  correlation length)\n"
	"  -psd file       with -ler: the edges' power spectral density as a 2D\n"
	"                  plot file (drawplot -xlog -ylog)\n"
	"  -lcdu           with -holes at one height: each hole's centroid and cd,\n"
	"                  and the local CD uniformity (3 sigma)\n"
	"  -o file         write the table to file (default: standard output)\n"
	"  -plot file      also write cd against z as a 2D plot file (drawplot)\n"
	"  -force          measure a surface that crosses itself (loops left by\n"
	"                  etch without -deloop), or a section through a gap of\n"
	"                  the surface (open border that -deloop left)\n"
	"  -accuracy P|check  add the column err, the discretisation error of cd\n"
	"                  estimated from the tables of the same measurement on\n"
	"                  coarser solves (Richardson; the order observed from\n"
	"                  three solves, 1 assumed from two); with P (percent),\n"
	"                  exit 3 when an err is over P %% of its cd or the\n"
	"                  solves are not in the asymptotic range\n"
	"  -coarse table   that table (measure's output on the coarser solve)\n"
	"  -ratio r        its grid spacing over this one's (default 2)\n"
	"  -coarser table  the table of a solve coarser still: the order is\n"
	"                  observed from the three\n"
	"  -ratio2 q       its grid spacing over -coarse's (default 2)\n"
	"  -coarser-fine table  the finer solve of the coarser change, when it\n"
	"                  is not -coarse's (refinement by axis: the change of\n"
	"                  one axis solved at another level of the others)\n"
	"  -order p        without -coarser, the order assumed (0.5 to 2,\n"
	"                  default 1)\n"
	"  -plus table     add that table's err (the estimate along the axes\n"
	"                  not refined here) to each err\n"
	"  -h, --help      this text\n";

/* A comma-separated list of finite numbers. */
static int parse_list(const char *s, double **v, int *n)
{
	char *copy = xstrdup(s), *save = NULL;
	size_t cap = 0;
	int ok = 1;
	*n = 0;
	free(*v);
	*v = NULL;
	if (!*s || s[strlen(s) - 1] == ',' || *s == ',' || strstr(s, ",,"))
		ok = 0;
	for (char *t = strtok_r(copy, ",", &save); ok && t; t = strtok_r(NULL, ",", &save)) {
		double x;
		if (!num_parse(t, &x)) {
			ok = 0;
			break;
		}
		xgrow(v, &cap, (size_t)*n + 1, sizeof **v);
		(*v)[(*n)++] = x;
	}
	free(copy);
	return ok && *n > 0;
}

/* -hole X Y, -space X Y x|y, -line X Y x|y */
static int parse_feature(struct args *a, struct options *o)
{
	static const char *names[] = {"-hole", "-space", "-line"};
	const char *w = a->argv[a->i];
	int k;
	for (k = 0; k < 3; k++)
		if (strcmp(w, names[k]) == 0)
			break;
	if (k == 3)
		return 0;
	int need = k == HOLE ? 2 : 3;
	if (o->have_kind)
		args_error(a, "give one of -hole, -space and -line, once");
	o->have_kind = 1;
	o->kind = (enum kind)k;
	a->i++;
	char **v = a->argv + a->i;
	int left = a->argc - a->i;
	if (left < need || !num_parse(v[0], &o->x) || !num_parse(v[1], &o->y) ||
	    (need == 3 && strcmp(v[2], "x") != 0 && strcmp(v[2], "y") != 0)) {
		args_error(a, need == 2 ? "option %s needs two numbers X Y"
					: "option %s needs X Y and x or y", names[k]);
		/* skip what looks like its values */
		for (int j = 0; j < need && a->i < a->argc; j++) {
			double t;
			const char *s = a->argv[a->i];
			if (s[0] == '-' && !num_parse(s, &t))
				break;
			a->i++;
		}
		return 1;
	}
	if (need == 3)
		o->axis = v[2][0] == 'y';
	a->i += need;
	return 1;
}

/* -ler, -lcdu, -holes: figures of a whole feature (rough.h) */
static int parse_whole(struct args *a, struct options *o)
{
	if (args_flag(a, "-ler"))
		o->ler = 1;
	else if (args_flag(a, "-lcdu"))
		o->lcdu = 1;
	else if (args_flag(a, "-holes"))
		o->holes = 1;
	else
		return 0;
	return 1;
}

static void check_whole(struct args *a, const struct options *o)
{
	if (o->ler && (!o->have_kind || o->kind == HOLE))
		args_error(a, "option -ler needs -space X Y x|y or -line X Y x|y");
	if (o->psd && !o->ler)
		args_error(a, "option -psd needs -ler");
	if (o->lcdu && !o->holes)
		args_error(a, "option -lcdu needs -holes");
	if (o->holes && !o->lcdu)
		args_error(a, "option -holes needs -lcdu");
	if (o->holes && o->plot)
		args_error(a, "option -plot needs -hole, -space or -line");
	if ((o->ler || o->lcdu) && o->nh > 1)
		args_error(a, "option %s measures at one height: give one value to -at or -rel",
			   o->ler ? "-ler" : "-lcdu");
}

/* -ratio's range: a coarse grid must be coarser; a hundred times is
 * beyond any use of the estimate (which assumes both solves are close to
 * converged). */
static const double RATIO_MIN = 1.01, RATIO_MAX = 100;

/* -accuracy P|check and -coarse go together; P is a percentage. */
static void parse_accuracy(struct args *a, struct options *o, const char *acc)
{
	if (!acc) {
		if (o->coarse || o->coarser || o->coarser_fine || o->plus)
			args_error(a, "%s goes with -accuracy",
				   o->coarse ? "-coarse" : o->coarser ? "-coarser" :
				   o->coarser_fine ? "-coarser-fine" : "-plus");
		return;
	}
	o->have_accuracy = 1;
	if (strcmp(acc, "check") != 0 &&
	    (!num_parse(acc, &o->accuracy) || !(o->accuracy > 0 && o->accuracy < 100)))
		args_error(a, "option -accuracy: expected a percentage between 0 and 100, or "
			   "check, found \"%.40s\"", acc);
	if (!o->coarse)
		args_error(a, "-accuracy needs -coarse (the table of the coarser solve)");
	if (o->coarser_fine && !o->coarser)
		args_error(a, "-coarser-fine needs -coarser (the coarse solve of that change)");
}

static void parse_options(int argc, char **argv, struct options *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage, NULL, NULL);
	memset(o, 0, sizeof *o);
	o->out = "-";
	const char *at = NULL, *rel = NULL, *acc = NULL;
	const char **slots[] = {&o->input};
	o->ratio = 2;
	o->ratio2 = 2;
	o->order = 1;
	while (a.i < argc) {
		args_help_exit(&a, 1);
		if (a.i >= argc)
			break;
		if (args_int(&a, "-s", 1, PLOT_MAX_COUNT, &o->set) ||
		    args_str(&a, "-at", &at) || args_str(&a, "-rel", &rel) ||
		    args_str(&a, "-o", &o->out) || args_str(&a, "-plot", &o->plot) ||
		    args_str(&a, "-accuracy", &acc) || args_str(&a, "-coarse", &o->coarse) ||
		    args_num(&a, "-ratio", RATIO_MIN, RATIO_MAX, &o->ratio) ||
		    args_str(&a, "-coarser", &o->coarser) ||
		    args_str(&a, "-coarser-fine", &o->coarser_fine) ||
		    args_str(&a, "-plus", &o->plus) ||
		    args_num(&a, "-ratio2", RATIO_MIN, RATIO_MAX, &o->ratio2) ||
		    args_num(&a, "-order", ACCURACY_ORDER_MIN, ACCURACY_ORDER_MAX, &o->order) ||
		    parse_feature(&a, o))
			continue;
		if (args_flag(&a, "-force")) {
			o->force = 1;
			continue;
		}
		if (args_str(&a, "-psd", &o->psd) || parse_whole(&a, o))
			continue;
		args_operand(&a, slots, 1, "surface file");
	}
	if (at && rel)
		args_error(&a, "give -at or -rel, not both");
	else if (!at && !rel)
		args_error(&a, "give the heights: -at z1,z2,... or -rel p1,p2,...");
	else if (!parse_list(at ? at : rel, &o->h, &o->nh))
		args_error(&a, "option %s: expected numbers separated by commas, found \"%.40s\"",
			   at ? "-at" : "-rel", at ? at : rel);
	o->rel = rel != NULL;
	if (rel)
		for (int i = 0; i < o->nh; i++)
			if (o->h[i] < 0 || o->h[i] > 100) {
				args_error(&a, "option -rel: %g is not a percentage from 0 to 100",
					   o->h[i]);
				break;
			}
	parse_accuracy(&a, o, acc);
	/* the specific problems first: only the first problem is printed */
	check_whole(&a, o);
	if (o->holes && o->have_kind)
		args_error(&a, "give -holes or one of -hole, -space and -line, not both");
	else if (!o->have_kind && !o->holes)
		args_error(&a, "give the feature: -hole X Y, -space X Y x|y or -line X Y x|y");
	if (!o->input)
		args_error(&a, "give the surface file (curves.plot of etch)");
	args_done(&a, NULL);
}

/* measure -accuracy P: a table whose estimate is over P % (the drivers
 * refine on it); 1 is an error, 2 a usage error. */
enum { EXIT_INACCURATE = 3 };

/* Too many crossings to be worth counting further. */
enum { CROSS_REPORT_MAX = 1000 };

/* The set to measure, as a surface; dies (having freed what it holds,
 * so that runs under the leak checker stay clean on errors) if there is
 * no such set or it is not triangles in a box. */
static struct surf *load(struct options *o, long *setno)
{
	struct plot_file *pf = fmt_plot_read(o->input, 3);
	if (strcmp(pf->labels.title, fmt_labels_std(LABELS_PAC)->title) == 0) {
		/* bleach -solid's surface of constant PAC closes the box: its
		 * "CD" would be 0, a number that means nothing */
		fmt_plot_free(pf);
		free(o->h);
		die("%s:1: this is bleach -solid's surface of constant PAC, not a developed "
		    "surface: measure etch's curves.plot", o->input);
	}
	*setno = o->set ? o->set : pf->nsets;
	if (*setno > pf->nsets) {
		int n = pf->nsets;
		fmt_plot_free(pf);
		free(o->h);
		die("%s: no set %ld: the file has %d", o->input, *setno, n);
	}
	char err[200];
	struct surf *s = surf_from_plot_set(&pf->sets[*setno - 1], err, sizeof err);
	fmt_plot_free(pf);
	if (!s) {
		free(o->h);
		die("%s: set %ld: %s", o->input, *setno, err);
	}
	return s;
}

/* The heights in um into z; checks them, the point and (unless -force)
 * the surface: what is wrong goes into err (empty if nothing). */
static void check(const struct options *o, const struct surf *s, long setno, double *z,
		  char *err, size_t errsz)
{
	const double *box = s->box;
	err[0] = '\0';
	if (!o->holes && (o->x < box[0] || o->x > box[1] || o->y < box[2] || o->y > box[3])) {
		snprintf(err, errsz, "the point (%g, %g) is outside the box x %g..%g, y %g..%g",
			 o->x, o->y, box[0], box[1], box[2], box[3]);
		return;
	}
	for (int i = 0; i < o->nh; i++) {
		z[i] = o->rel ? box[4] + o->h[i] / 100 * (box[5] - box[4]) : o->h[i];
		if (!o->rel && (z[i] < box[4] || z[i] > box[5])) {
			snprintf(err, errsz, "height z = %g is outside the resist (z from %g to %g)",
				 z[i], box[4], box[5]);
			return;
		}
	}
	if (o->force)
		return;
	long n = surf_crossings(s, CROSS_REPORT_MAX);
	if (n > 0) {
		snprintf(err, errsz, "set %ld: the surface crosses itself (%s%ld crossing%s: "
			 "loops left where etch fronts met); rerun etch with -deloop, "
			 "or give measure -force", setno,
			 n >= CROSS_REPORT_MAX ? "at least " : "", n, n == 1 ? "" : "s");
		return;
	}
}

/* A gap is near a section when it (surf.h: a chord between free ends of
 * the section, or an open edge above the plane seen from above) passes
 * within this many median triangle edges of the rectangle of the section
 * that decided cd.  A gap in a wall lies on the true contour, which the
 * rectangle's side may miss by about a triangle (the section stops at the
 * triangles beside the gap; a hole's area lines are 1/400 of it apart);
 * 3 edges covers that and stays well below a feature's size (ray-string
 * edges of 0.05 um: 0.15 um). */
#define NEAR_EDGES 3.0

static const char *kind_name(enum kind k)
{
	return k == HOLE ? "hole" : k == SPACE ? "space" : "line";
}

/* Whether the section of a row passes through a gap of the surface near
 * the feature: if so the message goes into err and 1 is returned.  With
 * -force the message is a warning instead, and 0 is returned.  Gaps away
 * from every section only give the length of the open border. */
static int gaps(const struct options *o, const struct surf *s, long setno,
		const struct result *r, char *err, size_t errsz)
{
	struct surf_border b;
	surf_border_find(s, &b);
	double tol = NEAR_EDGES * b.median_edge;
	int crossed = 0;
	err[0] = '\0';
	for (int i = 0; i < r->nrows && b.n > 0; i++) {
		const struct row *w = &r->rows[i];
		double rect[4] = {w->rect[0] - tol, w->rect[1] + tol, w->rect[2] - tol, w->rect[3] + tol};
		struct surf_gap g;
		if (!surf_border_at(&b, w->zsec, rect, o->x, o->y, &g))
			continue;
		double len = hypot(g.b[0] - g.a[0], g.b[1] - g.a[1]);
		snprintf(err, errsz, "set %ld: the section of the %s at z = %g passes through a gap "
			 "of the surface %.3g um wide from (%.4g, %.4g) to (%.4g, %.4g)%s: its cd "
			 "is decided by the ray test alone%s", setno, kind_name(o->kind), w->z, len,
			 g.a[0], g.a[1], g.b[0], g.b[1], g.n > 1 ? " and others" : "",
			 o->force ? " (measured anyway: -force)" :
			 "; rerun etch with -method fmm, measure at another height, or give "
			 "measure -force");
		crossed = 1;
		if (!o->force)
			break;
		warn("%s: %s", o->input, err);
		err[0] = '\0';
	}
	if (!crossed && b.length > 0)
		warn("%s: set %ld: the surface has %.3g um of open border inside the box "
		     "(gaps, as delooping can leave), none through the sections measured",
		     o->input, setno, b.length);
	surf_border_free(&b);
	return err[0] != '\0';
}

/* -lcdu -holes: the table of every hole instead of one feature's. */
static int holes_main(struct options *o, struct surf *s, double *z)
{
	struct lcdu l;
	lcdu_measure(s, z[0], &l);
	fmt_measure_write_holes(o->out, l.holes, l.n, l.lcdu >= 0 ? l.lcdu : NAN);
	lcdu_free(&l);
	free(z);
	free(o->h);
	surf_free(s);
	return 0;
}

int main(int argc, char **argv)
{
	struct options o;
	parse_options(argc, argv, &o);
	long setno;
	struct surf *s = load(&o, &setno);
	double *z = xreallocarray(NULL, (size_t)o.nh, sizeof *z);
	char err[600];
	check(&o, s, setno, z, err, sizeof err);
	if (err[0]) {
		surf_free(s);
		free(z);
		free(o.h);
		die("%s: %s", o.input, err);
	}
	surf_index(s);
	if (o.holes)
		return holes_main(&o, s, z);

	struct result r = {0};
	measure_feature(s, &o, z, &r);
	if (gaps(&o, s, setno, &r, err, sizeof err)) {
		free(r.rows);
		surf_free(s);
		free(z);
		free(o.h);
		die("%s: %s", o.input, err);
	}
	struct roughness rough;
	r.rough = NULL;
	if (o.ler) {
		if (roughness_measure(s, &o, z[0], &r.rows[0], &rough, err, sizeof err)) {
			free(r.rows);
			surf_free(s);
			free(z);
			free(o.h);
			die("%s: %s", o.input, err);
		}
		r.rough = &rough;
	}
	for (int i = 0; i < r.nrows; i++)
		if (r.rows[i].edge) {
			warn("%s: at z = %g the %s reaches the box edge: its cd is cut there",
			     o.input, r.rows[i].z,
			     o.kind == HOLE ? "hole" : o.kind == SPACE ? "space" : "line");
			break;
		}
	int over = o.have_accuracy ? accuracy_estimate(&o, &r) : 0;
	if (o.psd || o.plot)
		aout_defer();
	report_table(&o, &r);
	if (o.plot)
		report_plot(&o, s, &r);
	if (o.psd)
		roughness_psd(o.psd, &rough);
	if (o.psd || o.plot)
		aout_finish();
	if (o.ler)
		roughness_free(&rough);
	if (over)
		fprintf(stderr, "measure: %s: the estimated error of %d cd%s is over %g %%\n",
			o.input, over, over == 1 ? "" : "s", o.accuracy);
	free(r.rows);
	free(z);
	free(o.h);
	surf_free(s);
	return over ? EXIT_INACCURATE : 0;
}
