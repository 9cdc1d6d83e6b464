/*
 * plotdiff - compare two plot files (or any of the suite's numeric text
 * files: contour-files, ASCII rate files) number by number, within a
 * tolerance, for users whose machines differ in the last digits.
 *
 * Both files are read as token streams through the library's reader: a
 * token that is a number in both files is compared numerically, any other
 * token must match exactly.  The first difference is reported with both
 * files' line numbers.  Exit status as cmp(1) and diff(1): 0 the same within
 * the tolerance, 1 different, 2 trouble (usage, unreadable file).
 */
#include "args.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
	"usage: plotdiff [-tol abs] [-rtol rel] [-q] file1 file2\n"
	"  -tol abs    numbers may differ by abs (default 0)\n"
	"  -rtol rel   ... or by rel times the larger magnitude (default 0)\n"
	"  -q          no message, only the exit status\n";

struct options {
	double tol, rtol;
	int quiet;
	const char *a, *b;
};

static void parse_options(int argc, char **argv, struct options *o)
{
	struct args a;
	args_init(&a, argc, argv);
	args_usage(&a, usage, NULL, NULL);
	memset(o, 0, sizeof *o);
	while (a.i < argc) {
		args_help_exit(&a, 1);
		if (args_num(&a, "-tol", 0, INFINITY, &o->tol) ||
		    args_num(&a, "-rtol", 0, INFINITY, &o->rtol))
			;
		else if (args_flag(&a, "-q"))
			o->quiet = 1;
		else
			args_operand(&a, (const char **[]){&o->a, &o->b}, 2, "file");
	}
	if (!o->b)
		args_error(&a, "two files are needed");
	args_done(&a, NULL);
}

int main(int argc, char **argv)
{
	struct options o;
	parse_options(argc, argv, &o);
	util_set_die_status(2); /* 1 means "different" */
	struct lex *la = lex_open(o.a), *lb = lex_open(o.b);
	long count = 0;
	double worst = 0;
	int status = 0;
	for (;;) {
		const char *ta = lex_token(la);
		char *sa = ta ? xstrdup(ta) : NULL;
		const char *tb = lex_token(lb);
		if (!sa && !tb)
			break;
		count++;
		if (!sa || !tb) {
			if (!o.quiet)
				printf("plotdiff: %s ends at token %ld, %s:%ld goes on\n",
				       sa ? o.b : o.a, count, sa ? o.a : o.b,
				       sa ? lex_lineno(la) : lex_lineno(lb));
			free(sa);
			status = 1;
			break;
		}
		double x, y;
		int differ;
		double d = 0;
		if (num_parse(sa, &x) && num_parse(tb, &y)) {
			d = fabs(x - y);
			double allow = fmax(o.tol, o.rtol * fmax(fabs(x), fabs(y)));
			differ = !(d <= allow);
			if (d > worst)
				worst = d;
		} else {
			differ = strcmp(sa, tb) != 0;
		}
		if (differ) {
			if (!o.quiet)
				printf("plotdiff: %s:%ld: %s differs from %s:%ld: %s (token %ld, |difference| %g)\n",
				       o.a, lex_lineno(la), sa, o.b, lex_lineno(lb), tb, count, d);
			free(sa);
			status = 1;
			break;
		}
		free(sa);
	}
	if (status == 0 && !o.quiet)
		printf("plotdiff: %ld numbers agree (largest difference %g)\n", count, worst);
	lex_close(la);
	lex_close(lb);
	fshut(stdout, "stdout");
	return status;
}
