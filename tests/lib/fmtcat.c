/*
 * fmtcat - test tool: reads a file with one of the library's readers and
 * writes it back with the matching writer, so that shell tests can check
 * round trips (write -> read -> write is byte-identical) and feed every
 * reader a corpus of malformed files from the command line.
 *
 *   fmtcat contour|contour-old|stack|plot2|plot3|options|rate|rate-ascii IN OUT
 *
 * "options" uses a table with one keyword of every type: label (string),
 * grid (on/off), scale (number in [0.1, 1]), xticks (whole number in
 * [1, 20]), joinlevel (high|low).  "stack" reads an image stack or a
 * contour-file (fmt_stack_read) and writes it back as it came.
 */
#include "fmt_contour.h"
#include "fmt_options.h"
#include "fmt_plot.h"
#include "fmt_rate.h"
#include "fmt_stack.h"
#include "util.h"

#include <stdio.h>
#include <string.h>

static const struct opt_spec spec[] = {
	{"label", OPT_STRING, 0, 0, NULL},
	{"grid", OPT_ONOFF, 0, 0, NULL},
	{"scale", OPT_NUM, 0.1, 1.0, NULL},
	{"xticks", OPT_INT, 1, 20, NULL},
	{"joinlevel", OPT_WORD, 0, 0, "high|low"},
	{NULL, OPT_NUM, 0, 0, NULL},
};

int main(int argc, char **argv)
{
	util_setprog(argv[0]);
	if (argc != 4) {
		fputs("usage: fmtcat contour|contour-old|stack|plot2|plot3|options|rate|rate-ascii IN OUT\n", stderr);
		return EXIT_USAGE;
	}
	const char *t = argv[1], *in = argv[2], *out = argv[3];
	if (!strcmp(t, "contour") || !strcmp(t, "contour-old")) {
		int old = !strcmp(t, "contour-old");
		struct contour *c = fmt_contour_read(in, old);
		if (old)
			fmt_contour_write_old(out, c);
		else
			fmt_contour_write(out, c);
		fmt_contour_free(c);
	} else if (!strcmp(t, "stack")) {
		struct image_stack *st = fmt_stack_read(in);
		fmt_stack_write(out, st);
		fmt_stack_free(st);
	} else if (!strcmp(t, "plot2") || !strcmp(t, "plot3")) {
		struct plot_file *pf = fmt_plot_read(in, t[4] - '0');
		fmt_plot_write(out, pf);
		fmt_plot_free(pf);
	} else if (!strcmp(t, "options")) {
		struct opt_value val[sizeof spec / sizeof spec[0]];
		memset(val, 0, sizeof val);
		fmt_options_read(in, spec, val);
		fmt_options_write(out, spec, val);
		fmt_options_free(spec, val);
	} else if (!strcmp(t, "rate") || !strcmp(t, "rate-ascii")) {
		struct ratefile *r = fmt_rate_read(in);
		fmt_rate_write(out, r, !strcmp(t, "rate-ascii"));
		fmt_rate_free(r);
	} else {
		die("unknown format \"%s\"", t);
	}
	return 0;
}
