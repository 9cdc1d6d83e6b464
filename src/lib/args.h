/*
 * args.h - the small command-line helper every program uses.  The thesis'
 * programs take single-dash words (-et 30, -noplot), so getopt does not
 * fit.  Every bad option is reported, not only the first; then usage is
 * printed and the program exits with status 2.
 */
#ifndef S3D_ARGS_H
#define S3D_ARGS_H

struct args {
	int argc;
	char **argv;
	int i;          /* index of the option being looked at */
	int bad;        /* errors reported so far */
};

void args_init(struct args *a, int argc, char **argv);
/* 1 if argv[i] is exactly opt (then consumes it). */
int args_flag(struct args *a, const char *opt);
/* If argv[i] is opt: consumes it and its value, returned in *val; a
 * missing value is reported.  Returns 1 if opt matched. */
int args_str(struct args *a, const char *opt, const char **val);
/* The same with a finite number in [min, max]. */
int args_num(struct args *a, const char *opt, double min, double max, double *val);
/* The same with a whole number in [min, max]. */
int args_int(struct args *a, const char *opt, long min, long max, long *val);
/* Reports "prog: unknown option X" for argv[i] and skips it. */
void args_unknown(struct args *a);
/* Reports a usage problem (counts as bad). */
void args_error(struct args *a, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* If any error was reported: prints usage to stderr and exits 2. */
void args_done(struct args *a, const char *usage);
/* 1 if argv[i] is -h or --help (consumed). */
int args_help(struct args *a);

#endif
