/*
 * plot_common.h - what the four plot programs of the thesis' Appendix B
 * (pdraw, contour, drawplot, drawmask) share:
 *   - plot_common.c: the common command-line options (-o, -P, -s, -print,
 *     -ps, -noplot, labels, -svg, the X options), the common options-file
 *     keywords, and the output step (X11 preview, dataplot.ps, SVG, lpr);
 *   - plot_axes.c: round tick values, 2D axis frames (linear and log),
 *     tick labels.
 */
#ifndef S3D_PLOT_COMMON_H
#define S3D_PLOT_COMMON_H

#include "args.h"
#include "draw.h"
#include "draw_x11.h"
#include "fmt_labels.h"
#include "fmt_options.h"

/* Which of the common options a program takes. */
enum {
	PC_ZLABEL = 1,      /* -zl (pdraw) */
	PC_LANDSCAPE = 2,   /* -l is landscape (drawplot, drawmask) */
	PC_XDISPLAY = 4,    /* host:display, -d (contour, drawplot) */
	PC_BIG = 8          /* -big: read plot files beyond the estimate's limits */
};

/* The command line's common options. */
struct plot_cmd {
	const char *optfile;        /* -o */
	const char *printer;        /* -Pprinter */
	double scale;               /* -s, 0 if not given */
	int print, nops, noplot, landscape;
	const char *tl, *xl, *yl, *zl;
	const char *svg;            /* -svg FILE */
	const char *psfile;         /* -psfile FILE */
	struct draw_x11_opts x;
};

/* The resolved settings: defaults, then the options-file, then the
 * command line. */
struct plot_settings {
	const char *toplabel, *xlabel, *ylabel, *zlabel;
	int equalscale, postscript, printplot, noplot, landscape, grid;
	const char *printer;
	double scale;
	int xticks, yticks, zticks;
	int ticks_set;              /* xticks or yticks came from the file */
	int line, linechange, marker, markerchange;
	const char *svg;
	const char *psfile;         /* PLOT_PS_FILE unless -psfile */
};

void plot_cmd_init(struct plot_cmd *c);
/* If argv[a->i] is a common option, consumes it and returns 1. */
int plot_cmd_arg(struct args *a, struct plot_cmd *c, unsigned flags);
/* Usage lines of the common options (for the programs' usage texts). */
extern const char plot_usage_common[];
extern const char plot_usage_x[];

/* Entries of the options-file tables, shared so that every program spells
 * and bounds them alike (thesis Appendix B lists). */
#define PLOT_OPT_STR(k)     {k, OPT_STRING, 0, 0, NULL}
#define PLOT_OPT_ONOFF(k)   {k, OPT_ONOFF, 0, 0, NULL}
#define PLOT_OPT_SCALE      {"scale", OPT_NUM, 0.1, 1.0, NULL}
#define PLOT_OPT_TICKS(k)   {k, OPT_INT, 1, 20, NULL}
/* The keywords every plot program takes (read by plot_begin); a program's
 * table lists them first, then its own.  The order of a table does not
 * matter: entries are found by key. */
#define PLOT_OPT_COMMON \
	PLOT_OPT_STR("xlabel"), PLOT_OPT_STR("ylabel"), PLOT_OPT_STR("toplabel"), \
	PLOT_OPT_ONOFF("equalscale"), PLOT_OPT_ONOFF("noplot"), PLOT_OPT_ONOFF("postscript"), \
	PLOT_OPT_ONOFF("printplot"), PLOT_OPT_STR("printer"), PLOT_OPT_SCALE, \
	PLOT_OPT_TICKS("xticks"), PLOT_OPT_TICKS("yticks")
/* The line and marker keywords of the programs that draw plot curves. */
#define PLOT_OPT_LINES \
	PLOT_OPT_ONOFF("line"), PLOT_OPT_ONOFF("linechange"), PLOT_OPT_ONOFF("marker"), \
	PLOT_OPT_ONOFF("markerchange")

/* The value of key if the file set it, else NULL. */
const struct opt_value *plot_opt(const struct opt_spec *spec,
				 const struct opt_value *val, const char *key);
/* The start every plot program shares: val (one entry per entry of spec,
 * its terminator included) cleared and filled from the options-file of
 * -o if given, then s set from defaults, the options-file values of the
 * common keywords, and the command line. */
void plot_begin(struct plot_settings *s, const struct plot_settings *defaults,
		const struct opt_spec *spec, struct opt_value *val, const struct plot_cmd *c);

/* The labels an input file carries (fmt_labels.h) replace the built-in
 * defaults: a label the options-file or the command line sets wins, an
 * empty one in l changes nothing.  Call after plot_begin; l
 * must outlive s. */
void plot_settings_labels(struct plot_settings *s, const struct plot_labels *l,
			  const struct opt_spec *spec, const struct opt_value *val,
			  const struct plot_cmd *c);

/* Before reading plot files: their memory and time estimated from their
 * size (fmt_plot_size) - the text of the largest file, or per number
 * read the bytes and seconds of all files - checked against the limits
 * (budget.h); beyond them the program stops with one line naming the
 * estimate and -big.  bytes_per_number and seconds_per_number are the
 * program's measured costs (beside its call). */
void plot_budget(int nfiles, char *const *files, double bytes_per_number,
		 double seconds_per_number);

/* Builds the picture; called again after a key changes the view. */
typedef struct draw *(*plot_render)(void *ctx);

/* The output step common to all: the X11 preview (unless noplot; without
 * X11 or a display a one-line note and no preview), then dataplot.ps
 * (unless -ps or POSTSCRIPT=OFF), the SVG if asked, and printing (-print,
 * or a yes to the question asked only when stdin is a terminal). */
void plot_output(const struct plot_settings *s, const struct plot_cmd *c,
		 plot_render render, draw_x11_key key, void *ctx);

/* The name of the PostScript output (thesis: "temporary POSTSCRIPT file"). */
#define PLOT_PS_FILE "dataplot.ps"

/* ---- plot_axes.c ---- */

enum { PLOT_MAXTICKS = 64 };

/* An axis: data range [lo, hi] (log10 of it for a log axis) and its tick
 * values with labels. */
struct plot_axis {
	double lo, hi;              /* mapped range (log10 units if log) */
	int log;
	int nticks;
	double tick[PLOT_MAXTICKS]; /* in mapped units */
	char label[PLOT_MAXTICKS][24];
	int nminor;
	double minor[PLOT_MAXTICKS * 9];
};

/* A round step near (hi - lo) / ndiv: 1, 2 or 5 times a power of ten. */
double plot_nice_step(double lo, double hi, int ndiv);
/* Linear axis.  autorange: widen [lo, hi] to multiples of a round step of
 * about ndiv divisions; otherwise exactly ndiv divisions of [lo, hi]. */
void plot_axis_linear(struct plot_axis *ax, double lo, double hi, int ndiv, int autorange);
/* Log axis over [lo, hi] (> 0): ticks at the decades, minor ticks at
 * 2..9; autorange widens to whole decades.  Returns 0 if lo or hi <= 0. */
int plot_axis_log(struct plot_axis *ax, double lo, double hi, int autorange);
/* Formats tick labels so that they are distinct and read back close to
 * the tick values (shortest %g precision that does). */
void plot_axis_labels(struct plot_axis *ax);

/* A 2D frame: a box on the page and the axes mapped onto it. */
struct plot_frame {
	double x0, y0, x1, y1;      /* box, points */
	struct plot_axis *xa, *ya;
};
/* Places the box on the page, leaving room for labels; with equal, one
 * data unit is the same length in x and y. */
void plot_frame_place(struct plot_frame *f, const struct draw *d, int equal);
/* Page position of a data point; 0 if it cannot be shown (log of <= 0). */
int plot_frame_map(const struct plot_frame *f, double x, double y, double *px, double *py);
/* Box, ticks, tick labels, grid (dotted) and the three labels. */
void plot_frame_draw(struct draw *d, const struct plot_frame *f, int grid,
		     const char *top, const char *xl, const char *yl);
/* The page of a picture: portrait 612x792 or landscape 792x612 points. */
struct draw *plot_new_page(int landscape);
/* The comma-separated list of -times as numbers in *times (allocated);
 * returns their count, or dies (usage) on a word that is not a number. */
int plot_parse_times(const char *list, double **times);

#endif
