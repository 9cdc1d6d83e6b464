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
	a->nknown = 0;
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
	/* only the first problem is printed: the later ones are often its
	 * echo (a misspelled option's value taken for one operand too many) */
	if (a->bad++)
		return;
	va_list ap;
	fprintf(stderr, "%s: ", util_prog());
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
}

/* Remembers opt as an option the program knows (for "did you mean"). */
static void know(struct args *a, const char *opt)
{
	for (int k = 0; k < a->nknown; k++)
		if (a->known[k] == opt || strcmp(a->known[k], opt) == 0)
			return;
	if (a->nknown < ARGS_KNOWN_MAX)
		a->known[a->nknown++] = opt;
}

int args_flag(struct args *a, const char *opt)
{
	know(a, opt);
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
	know(a, opt);
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

/* Longest option name compared by args_nearest; longer words are no
 * option of ours and are not suggested for. */
enum { NEAR_LEN = 40 };

/* Edit distance of a and b (Damerau's: insertion, deletion, substitution
 * and the swap of two neighbours cost 1 each), both at most NEAR_LEN. */
static int edit_distance(const char *a, const char *b)
{
	int la = (int)strlen(a), lb = (int)strlen(b);
	int d[NEAR_LEN + 1][NEAR_LEN + 1];
	for (int i = 0; i <= la; i++)
		d[i][0] = i;
	for (int j = 0; j <= lb; j++)
		d[0][j] = j;
	for (int i = 1; i <= la; i++)
		for (int j = 1; j <= lb; j++) {
			int c = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
			if (d[i - 1][j] + 1 < c)
				c = d[i - 1][j] + 1;
			if (d[i][j - 1] + 1 < c)
				c = d[i][j - 1] + 1;
			if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
			    d[i - 2][j - 2] + 1 < c)
				c = d[i - 2][j - 2] + 1;
			d[i][j] = c;
		}
	return d[la][lb];
}

const char *args_nearest(const char *word, const char *const cand[], int n)
{
	size_t lw = strlen(word);
	if (lw > NEAR_LEN)
		return NULL;
	/* a slip: one edit in a short name, two in one of 6 letters or more
	 * (-delop, -deloopp, -mehtod); more would suggest unrelated words */
	int limit = lw >= 6 ? 2 : 1;
	const char *best = NULL;
	int bestd = limit + 1, ties = 0;
	for (int k = 0; k < n; k++) {
		if (strlen(cand[k]) > NEAR_LEN || strcmp(cand[k], word) == 0)
			continue;
		int dk = edit_distance(word, cand[k]);
		if (dk < bestd) {
			bestd = dk;
			best = cand[k];
			ties = 0;
		} else if (dk == bestd && best && strcmp(cand[k], best) != 0) {
			ties++;
		}
	}
	return best && !ties ? best : NULL;
}

/* Adds the options the usage text names (words "-x..." after a blank or
 * '[') to the known ones: options a program tests by hand count too. */
static void know_usage(struct args *a, char names[][NEAR_LEN + 1], int max)
{
	int n = 0;
	for (int k = 0; k < 3; k++)
		for (const char *s = a->usage[k]; s && *s; s++) {
			if (s[0] != '-' || !(s[1] >= 'a' && s[1] <= 'z'))
				continue;
			if (s != a->usage[k] && s[-1] != ' ' && s[-1] != '[' && s[-1] != '|' &&
			    s[-1] != '\t' && s[-1] != '(')
				continue;
			size_t len = 1;
			while (len < NEAR_LEN && (s[len] == '-' || (s[len] >= 'a' && s[len] <= 'z') ||
						  (s[len] >= '0' && s[len] <= '9')))
				len++;
			if (n < max) {
				memcpy(names[n], s, len);
				names[n][len] = '\0';
				know(a, names[n++]);
			}
			s += len - 1;
		}
}

void args_unknown(struct args *a)
{
	const char *word = a->argv[a->i];
	if (!a->bad) {
		static char names[ARGS_KNOWN_MAX][NEAR_LEN + 1];
		know_usage(a, names, ARGS_KNOWN_MAX);
		const char *near = args_nearest(word, a->known, a->nknown);
		if (near)
			args_error(a, "unknown option %.60s; did you mean %s?", word, near);
		else
			args_error(a, "unknown option %.60s", word);
	} else {
		a->bad++;
	}
	a->i++;
}

void args_done(struct args *a, const char *usage)
{
	if (!a->bad)
		return;
	if (a->argc <= 1) {
		/* nothing was asked: the usage is what is wanted */
		if (usage)
			fputs(usage, stderr);
		else
			print_usage(a, stderr);
	} else {
		args_hint();
	}
	exit(EXIT_USAGE);
}

void args_hint(void)
{
	fprintf(stderr, "%s: %s --help prints the usage\n", util_prog(), util_prog());
}
