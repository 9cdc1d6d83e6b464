/* args.c - see args.h. */
#include "args.h"
#include "num.h"
#include "util.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void args_init(struct args *a, int argc, char **argv)
{
	a->argc = argc;
	a->argv = argv;
	a->i = 1;
	a->bad = 0;
	util_setprog(argv[0]);
}

void args_error(struct args *a, const char *fmt, ...)
{
	va_list ap;
	fprintf(stderr, "%s: ", util_prog());
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
	a->bad++;
}

int args_flag(struct args *a, const char *opt)
{
	if (a->i < a->argc && strcmp(a->argv[a->i], opt) == 0) {
		a->i++;
		return 1;
	}
	return 0;
}

int args_help(struct args *a)
{
	return args_flag(a, "-h") || args_flag(a, "--help");
}

int args_str(struct args *a, const char *opt, const char **val)
{
	if (a->i >= a->argc || strcmp(a->argv[a->i], opt) != 0)
		return 0;
	if (a->i + 1 >= a->argc) {
		args_error(a, "option %s needs a value", opt);
		a->i++;
		return 1;
	}
	*val = a->argv[a->i + 1];
	a->i += 2;
	return 1;
}

int args_num(struct args *a, const char *opt, double min, double max, double *val)
{
	const char *s = NULL;
	if (!args_str(a, opt, &s))
		return 0;
	double v;
	if (s && (!num_parse(s, &v) || v < min || v > max))
		args_error(a, "option %s: expected a number from %g to %g, found \"%.40s\"",
			   opt, min, max, s);
	else if (s)
		*val = v;
	return 1;
}

int args_int(struct args *a, const char *opt, long min, long max, long *val)
{
	const char *s = NULL;
	if (!args_str(a, opt, &s))
		return 0;
	long v;
	if (s && !num_parse_count(s, min, max, &v))
		args_error(a, "option %s: expected a whole number from %ld to %ld, found \"%.40s\"",
			   opt, min, max, s);
	else if (s)
		*val = v;
	return 1;
}

void args_unknown(struct args *a)
{
	args_error(a, "unknown option %.60s", a->argv[a->i]);
	a->i++;
}

void args_done(struct args *a, const char *usage)
{
	if (a->bad) {
		fprintf(stderr, "%s", usage);
		exit(EXIT_USAGE);
	}
}
