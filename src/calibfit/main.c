/*
 * calibfit - the numerics of calib(1), one job per call, no state kept:
 * the free numbers of a resist file (read, write), the probe points of
 * the finite-difference Jacobian, the sum of squared CD residuals, the
 * Levenberg-Marquardt trial point, and the report (calib.dat, pictures).
 * calib runs the simulations (fem) between the calls.
 */
#include "args.h"
#include "calibfit.h"
#include "calibfit_report.h"
#include "fmt_bleach.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

static const char usage[] =
	"usage: calibfit -bf resist.in -free \"STATEMENT K LO:HI\" [-free ...] JOB\n"
	"  jobs:\n"
	"  -start                 print the file's values of the free numbers\n"
	"  -write V -o file       the resist file with the free numbers set to V\n"
	"  -probes V              the Jacobian's probe points at V, one a line\n"
	"  -points -data m.dat    the measured (focus, dose) points as fem -points takes them\n"
	"  -ssr -data m.dat -sim fem.dat\n"
	"                         print the sum of squared residuals (um2), the number\n"
	"                         of points and of points that did not clear\n"
	"  -step V -lambda L [-scale S] -data m.dat -sim fem.dat -jac f1.dat,f2.dat,...\n"
	"                         print the Levenberg-Marquardt trial point (S times\n"
	"                         the step, default 1), or\n"
	"                         \"converged\" when the step is negligible\n"
	"  -report V -data m.dat -sim fem.dat -jac f1.dat,... [-iter N]\n"
	"          [-vdata v.dat -vsim vfem.dat] -d DIR\n"
	"                         write DIR/calib.dat and the pictures' plot files\n"
	"  V is the free numbers' values, comma-separated, in -free order;\n"
	"  fem.dat the simulation at V, fK.dat the one at the K-th probe point.\n";

enum job { J_NONE, J_START, J_WRITE, J_PROBES, J_POINTS, J_SSR, J_STEP, J_REPORT };

struct options {
	enum job job;
	const char *bf, *values, *out, *data, *sim, *jac, *vdata, *vsim, *dir;
	double lambda, scale;
	long iter;
	int have_lambda;
	int nfree;
	struct calib_free free[CALIB_MAX_FREE];
};

/* "STATEMENT K LO:HI" */
static int parse_free(const char *spec, struct calib_free *f)
{
	char st[64], kk[64], range[128], extra[2];
	if (sscanf(spec, "%63s %63s %127s %1s", st, kk, range, extra) != 3 || strlen(st) >= sizeof f->stmt)
		return 0;
	char *colon = strchr(range, ':');
	long k;
	if (!colon || !num_parse_count(kk, 1, 1000, &k))
		return 0;
	*colon = '\0';
	if (!num_parse(range, &f->lo) || !num_parse(colon + 1, &f->hi) || !(f->lo < f->hi))
		return 0;
	strcpy(f->stmt, st);
	f->k = (int)k;
	f->spec = spec;
	return 1;
}

/* 1 if f names a number an earlier -free already frees. */
static int freed_before(const struct options *o, const struct calib_free *f)
{
	for (int j = 0; j < o->nfree; j++)
		if (o->free[j].k == f->k && strcasecmp(o->free[j].stmt, f->stmt) == 0)
			return 1;
	return 0;
}

static void set_job(struct args *a, struct options *o, enum job j, const char *opt)
{
	if (o->job != J_NONE)
		args_error(a, "%s: one job at a time", opt);
	o->job = j;
}

static void check_job(struct args *a, const struct options *o)
{
	int needv = o->job == J_WRITE || o->job == J_PROBES || o->job == J_STEP || o->job == J_REPORT;
	int needsim = o->job == J_SSR || o->job == J_STEP || o->job == J_REPORT;
	if (o->job == J_NONE)
		args_error(a, "nothing to do: give a job (-start, -write, -probes, -points, -ssr, -step, -report)");
	if (o->job != J_POINTS && o->job != J_SSR && o->job != J_NONE) {
		if (!o->bf)
			args_error(a, "-bf (the resist file) is required");
		if (o->nfree == 0)
			args_error(a, "give at least one -free \"STATEMENT K LO:HI\"");
	}
	if (needv && !o->values)
		args_error(a, "this job needs the values V");
	if ((needsim || o->job == J_POINTS) && !o->data)
		args_error(a, "this job needs -data (the measured CDs)");
	if (needsim && !o->sim)
		args_error(a, "this job needs -sim (the simulation's fem.dat)");
	if ((o->job == J_STEP || o->job == J_REPORT) && !o->jac)
		args_error(a, "this job needs -jac (the probes' fem.dat files)");
	if (o->job == J_STEP && !o->have_lambda)
		args_error(a, "-step needs -lambda");
	if (o->job == J_WRITE && !o->out)
		args_error(a, "-write needs -o");
	if (o->job == J_REPORT && !o->dir)
		args_error(a, "-report needs -d DIR");
	if (!o->vdata != !o->vsim)
		args_error(a, "-vdata and -vsim go together");
}

static void parse_options(int argc, char **argv, struct options *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage, NULL, NULL);
	memset(o, 0, sizeof *o);
	o->scale = 1;
	while (a.i < argc) {
		args_help_exit(&a, 1);
		const char *spec;
		if (args_str(&a, "-free", &spec)) {
			if (o->nfree == CALIB_MAX_FREE)
				args_error(&a, "at most %d -free", CALIB_MAX_FREE);
			else if (!parse_free(spec, &o->free[o->nfree]))
				args_error(&a, "-free \"%s\": expected \"STATEMENT K LO:HI\" (K from 1, LO < HI)", spec);
			else if (freed_before(o, &o->free[o->nfree]))
				args_error(&a, "-free \"%s\": that number is already free", spec);
			else
				o->nfree++;
		} else if (args_flag(&a, "-start")) {
			set_job(&a, o, J_START, "-start");
		} else if (args_flag(&a, "-points")) {
			set_job(&a, o, J_POINTS, "-points");
		} else if (args_flag(&a, "-ssr")) {
			set_job(&a, o, J_SSR, "-ssr");
		} else if (args_str(&a, "-write", &o->values)) {
			set_job(&a, o, J_WRITE, "-write");
		} else if (args_str(&a, "-probes", &o->values)) {
			set_job(&a, o, J_PROBES, "-probes");
		} else if (args_str(&a, "-step", &o->values)) {
			set_job(&a, o, J_STEP, "-step");
		} else if (args_str(&a, "-report", &o->values)) {
			set_job(&a, o, J_REPORT, "-report");
		} else if (args_num(&a, "-scale", 1e-6, 1, &o->scale)) {
			;
		} else if (args_num(&a, "-lambda", 0, 1e300, &o->lambda)) {
			o->have_lambda = 1;
		} else if (args_int(&a, "-iter", 0, 1000000, &o->iter) ||
			   args_str(&a, "-bf", &o->bf) || args_str(&a, "-o", &o->out) ||
			   args_str(&a, "-data", &o->data) || args_str(&a, "-sim", &o->sim) ||
			   args_str(&a, "-jac", &o->jac) || args_str(&a, "-vdata", &o->vdata) ||
			   args_str(&a, "-vsim", &o->vsim) || args_str(&a, "-d", &o->dir)) {
			;
		} else {
			args_unknown(&a);
		}
	}
	check_job(&a, o);
	args_done(&a, NULL);
}

/* "a,b,c" -> exactly want numbers (what says what they are). */
static void list(const char *s, int want, double *v, const char *what)
{
	char *copy = xstrdup(s), *save = NULL;
	int n = 0;
	for (char *t = strtok_r(copy, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
		if (n == want || !num_parse(t, &v[n]))
			die_status(EXIT_USAGE, "%s \"%s\": expected %d comma-separated numbers", what, s, want);
		n++;
	}
	if (n != want)
		die_status(EXIT_USAGE, "%s \"%s\": expected %d comma-separated numbers", what, s, want);
	free(copy);
}

static void print_values(int p, const double *v)
{
	char x[NUM_BUFSZ];
	for (int j = 0; j < p; j++)
		printf("%s%s", j ? "," : "", num_fmt(x, v[j]));
	putchar('\n');
}

/* The resist file with the values v (checked by the bleach reader). */
static void write_resist(const struct options *o, const double *v)
{
	size_t len;
	char *text = lex_slurp(o->bf, &len);
	text[len] = '\0';
	if (strlen(text) != len)
		die("%s: not a text file (NUL byte)", o->bf);
	for (int j = 0; j < o->nfree; j++) {
		char *t = fmt_bleach_set_number(o->bf, text, o->free[j].stmt, o->free[j].k, v[j]);
		free(text);
		text = t;
	}
	struct bleach_input in;
	fmt_bleach_parse(o->out, text, &in);
	struct aout *a = aout_open(o->out);
	fputs(text, a->f);
	aout_commit(a);
	free(text);
}

/* The file's values, each checked against its range. */
static void start_values(const struct options *o, double *v)
{
	struct bleach_input in;
	fmt_bleach_read(o->bf, &in);
	size_t len, off, nl;
	long line;
	char *text = lex_slurp(o->bf, &len);
	text[len] = '\0';
	for (int j = 0; j < o->nfree; j++) {
		const struct calib_free *f = &o->free[j];
		v[j] = fmt_bleach_number(o->bf, text, f->stmt, f->k, &off, &nl, &line);
		if (!(v[j] >= f->lo && v[j] <= f->hi))
			die_status(EXIT_USAGE, "%s:%ld: -free \"%s\": the file's value %.*s is outside the range",
				   o->bf, line, f->spec, (int)nl, text + off);
	}
	free(text);
}

/* The simulations named by -jac, matched to the measured points, and J. */
static double *jacobian(const struct options *o, const double *v, const struct fem_table *meas,
			const struct calib_points *base)
{
	struct calib_points probe[CALIB_MAX_FREE];
	double vp[CALIB_MAX_FREE];
	char *copy = xstrdup(o->jac), *save = NULL;
	int n = 0;
	for (char *t = strtok_r(copy, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
		if (n == o->nfree)
			die_status(EXIT_USAGE, "-jac: more files than -free");
		vp[n] = calib_probe_value(&o->free[n], v[n]);
		calib_match(meas, t, &probe[n++]);
	}
	if (n != o->nfree)
		die_status(EXIT_USAGE, "-jac: expected %d files, one per -free, found %d", o->nfree, n);
	double *J = xreallocarray(NULL, (size_t)meas->n * (size_t)n, sizeof *J);
	calib_jacobian(n, v, vp, base, probe, J);
	for (int j = 0; j < n; j++)
		calib_points_free(&probe[j]);
	free(copy);
	return J;
}

static void step(const struct options *o, const double *v, const struct fem_table *meas)
{
	struct calib_points base;
	calib_match(meas, o->sim, &base);
	double *J = jacobian(o, v, meas, &base);
	double *r = xreallocarray(NULL, (size_t)meas->n, sizeof *r);
	for (int i = 0; i < meas->n; i++)
		r[i] = base.cd[i] - meas->p[i].cd;
	double w[CALIB_MAX_FREE];
	if (calib_step(o->nfree, o->free, v, meas->n, J, r, o->lambda, o->scale, w))
		print_values(o->nfree, w);
	else
		puts("converged");
	free(r);
	free(J);
	calib_points_free(&base);
}

static void report(const struct options *o, const double *v, const struct fem_table *meas)
{
	if (meas->n <= o->nfree)
		die("%s: %d points for %d free parameters: the errors need more points than parameters",
		    o->data, meas->n, o->nfree);
	struct calib_points base, val;
	struct fem_table *vmeas = NULL;
	calib_match(meas, o->sim, &base);
	double *J = jacobian(o, v, meas, &base);
	if (o->vdata) {
		vmeas = fmt_fem_read_cds(o->vdata);
		calib_match(vmeas, o->vsim, &val);
	}
	struct calib_report_in in = {o->nfree, o->free, v, &base, J, vmeas ? &val : NULL,
				     (int)o->iter, o->dir};
	calib_report(&in);
	if (vmeas) {
		calib_points_free(&val);
		fmt_fem_free(vmeas);
	}
	free(J);
	calib_points_free(&base);
}

int main(int argc, char **argv)
{
	util_setprog(argv[0]);
	struct options o;
	parse_options(argc, argv, &o);
	double v[CALIB_MAX_FREE];
	if (o.values)
		list(o.values, o.nfree, v, "the values");
	struct fem_table *meas = o.data ? fmt_fem_read_cds(o.data) : NULL;
	char x[NUM_BUFSZ];
	switch (o.job) {
	case J_START:
		start_values(&o, v);
		print_values(o.nfree, v);
		break;
	case J_WRITE:
		write_resist(&o, v);
		break;
	case J_PROBES:
		for (int j = 0; j < o.nfree; j++) {
			double w[CALIB_MAX_FREE];
			memcpy(w, v, sizeof w);
			w[j] = calib_probe_value(&o.free[j], v[j]);
			print_values(o.nfree, w);
		}
		break;
	case J_POINTS:
		for (int i = 0; i < meas->n; i++) {
			printf("%s%s:", i ? "," : "", num_fmt(x, meas->p[i].focus));
			printf("%s", num_fmt(x, meas->p[i].dose));
		}
		putchar('\n');
		break;
	case J_SSR: {
		struct calib_points s;
		calib_match(meas, o.sim, &s);
		printf("%s %d %d\n", num_fmt(x, calib_ssr(&s)), s.n, s.uncleared);
		calib_points_free(&s);
		break;
	}
	case J_STEP:
		step(&o, v, meas);
		break;
	case J_REPORT:
		report(&o, v, meas);
		break;
	case J_NONE:
		break;
	}
	fmt_fem_free(meas);
	fshut(stdout, "stdout");
	return 0;
}
