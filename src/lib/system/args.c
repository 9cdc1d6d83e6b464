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
	a->usage[0] = a->usage[1] = a->usage[2] = NULL;
	util_setprog(argv[0]);
}

void args_usage(struct args *a, const char *part1, const char *part2, const char *part3)
{
	a->usage[0] = part1;
	a->usage[1] = part2;
	a->usage[2] = part3;
}

static void print_usage(const struct args *a, FILE *f)
{
	for (int k = 0; k < 3; k++)
		if (a->usage[k])
			fputs(a->usage[k], f);
}

void args_help_exit(struct args *a, int short_h)
{
	if ((short_h && args_flag(a, "-h")) || args_flag(a, "--help")) {
		print_usage(a, stdout);
		fshut(stdout, "stdout");
		exit(0);
	}
}

void args_operand(struct args *a, const char **slots[], int n, const char *name)
{
	const char *s = a->argv[a->i];
	if (s[0] == '-' && s[1] != '\0') {
		args_unknown(a);
		return;
	}
	a->i++;
	for (int k = 0; k < n; k++)
		if (!*slots[k]) {
			*slots[k] = s;
			return;
		}
	args_error(a, "%.60s: one %s too many", s, name);
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
	/* an output named by nothing is found now, not after the run, in
	 * one line (a usage error, without the usage: nothing is unknown) */
	if (!**val && (!strcmp(opt, "-o") || !strcmp(opt, "-plot") || !strcmp(opt, "-svg")))
		die_status(EXIT_USAGE, "option %s: an empty file name", opt);
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
		if (usage)
			fputs(usage, stderr);
		else
			print_usage(a, stderr);
		exit(EXIT_USAGE);
	}
}
