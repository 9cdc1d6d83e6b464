/*
 * args.h - the small command-line helper every program uses.  The thesis'
 * programs take single-dash words (-et 30, -noplot), so getopt does not
 * fit.  The first bad option is reported in one line (an unknown option
 * with the nearest known one, "did you mean -deloop?"), then one line
 * saying where the usage is, and the program exits with status 2; later
 * problems, often only the echo of the first (the value of a misspelled
 * option taken for an operand), are not printed.  With no arguments at
 * all, the usage itself is printed.
 */
#ifndef S3D_ARGS_H
#define S3D_ARGS_H

enum { ARGS_KNOWN_MAX = 192 };

struct args {
	int argc;
	char **argv;
	int i;          /* index of the option being looked at */
	int bad;        /* errors reported so far */
	const char *usage[3];   /* the usage text, in parts (args_usage) */
	/* the options the program's loop has asked about (args_flag,
	 * args_str, ...), the candidates of "did you mean" */
	const char *known[ARGS_KNOWN_MAX];
	int nknown;
};

void args_init(struct args *a, int argc, char **argv);
/* Sets the usage text, printed by args_help_exit and args_done: up to
 * three parts printed one after another (a program's own lines, then
 * lines shared by several programs); unused parts NULL. */
void args_usage(struct args *a, const char *part1, const char *part2, const char *part3);
/* If argv[i] is --help, or -h when short_h is non-zero (pdraw's -h means
 * hidden lines): prints the usage on stdout and exits 0. */
void args_help_exit(struct args *a, int short_h);
/* The last branch of an option loop: a word starting with '-' (other than
 * "-" alone, standard input) is reported as an unknown option; any other
 * is the next operand, stored in the first of *slots[0..n-1] still NULL,
 * or reported as one too many (name says what the operands are). */
void args_operand(struct args *a, const char **slots[], int n, const char *name);
/* 1 if argv[i] is exactly opt (then consumes it). */
int args_flag(struct args *a, const char *opt);
/* If argv[i] is opt: consumes it and its value, returned in *val; a
 * missing value is reported.  Returns 1 if opt matched. */
int args_str(struct args *a, const char *opt, const char **val);
/* The same with a finite number in [min, max]. */
int args_num(struct args *a, const char *opt, double min, double max, double *val);
/* The same with a whole number in [min, max]. */
int args_int(struct args *a, const char *opt, long min, long max, long *val);
/* Reports "prog: unknown option X" for argv[i] and skips it, with
 * "; did you mean -Y?" when one known option (asked about by the loop or
 * named in the usage text) is within a small edit distance of X. */
void args_unknown(struct args *a);
/* Reports a usage problem (counts as bad). */
void args_error(struct args *a, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* If any error was reported: prints one line naming --help (or, when the
 * command line was empty, the usage itself: usage, or if NULL the text of
 * args_usage) to stderr and exits 2. */
void args_done(struct args *a, const char *usage);
/* Prints "prog: prog --help prints the usage" on stderr: the second line
 * of a usage error (args_done prints it too). */
void args_hint(void);
/* 1 if argv[i] is -h or --help (consumed). */
int args_help(struct args *a);
/* The option among the n names in cand[] nearest to word by edit
 * distance (insertions, deletions, substitutions, swaps of neighbours),
 * if it is near enough to be a slip of the keyboard (see args.c), else
 * NULL. */
const char *args_nearest(const char *word, const char *const cand[], int n);

#endif
