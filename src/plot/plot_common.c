/*
 * plot_common.c - the common options and the output step of the plot
 * programs (thesis Appendix B: pdraw(L), contour(L), drawplot(L),
 * drawmask(L) share -o, -P, -s, -noplot, -print, -ps, the labels, the
 * X options and most options-file keywords).  The guides let the program
 * prompt before printing; we ask only when stdin is a terminal, so that
 * scripts never block.
 */
#include "plot_common.h"
#include "budget.h"
#include "fmt_plot.h"
#include "num.h"
#include "util.h"

#include <ctype.h>
#include <math.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/wait.h>
#include <unistd.h>

const char plot_usage_common[] =
	"  -o options-file  plotting options (keyword value per line)\n"
	"  -Pprinter        printer for -print (default $PRINTER)\n"
	"  -s scale         scale of the PostScript plot (0.1 to 1)\n"
	"  -noplot          no X11 preview (also -noplots)\n"
	"  -print           send the PostScript plot to lpr\n"
	"  -ps              no PostScript file (also POSTSCRIPT=OFF)\n"
	"  -psfile file     the PostScript file (default dataplot.ps)\n"
	"  -svg file        also write the picture as SVG\n"
	"  -tl/-xl/-yl text top, x and y labels\n";
const char plot_usage_x[] =
	"  X options: host:display, -d host:display, =geom, -rv, -bw width,\n"
	"             -bd color, -fg color, -bg color, -fn font\n";

void plot_cmd_init(struct plot_cmd *c)
{
	memset(c, 0, sizeof *c);
	c->x.border_width = -1;
}

/* "host:0" or ":0.1" - the thesis' bare host:display argument. */
static int is_display(const char *s)
{
	const char *colon = strrchr(s, ':');
	if (!colon || s[0] == '-' || !isdigit((unsigned char)colon[1]))
		return 0;
	for (const char *p = s; p < colon; p++)
		if (!isalnum((unsigned char)*p) && *p != '.' && *p != '-' && *p != '_')
			return 0;
	for (const char *p = colon + 1; *p; p++)
		if (!isdigit((unsigned char)*p) && *p != '.')
			return 0;
	return 1;
}

int plot_cmd_arg(struct args *a, struct plot_cmd *c, unsigned flags)
{
	const char *s = a->argv[a->i];
	long bw;
	if (args_str(a, "-o", &c->optfile))
		return 1;
	if (strncmp(s, "-P", 2) == 0) {
		if (s[2])
			c->printer = s + 2, a->i++;
		else
			args_str(a, "-P", &c->printer);
		return 1;
	}
	if (args_num(a, "-s", 0.1, 1.0, &c->scale))
		return 1;
	if (args_flag(a, "-noplot") || args_flag(a, "-noplots")) {
		c->noplot = 1;
		return 1;
	}
	if (args_flag(a, "-print")) {
		c->print = 1;
		return 1;
	}
	if (args_flag(a, "-ps")) {
		c->nops = 1;
		return 1;
	}
	if (args_str(a, "-psfile", &c->psfile)) {
		if (!*c->psfile)
			args_error(a, "-psfile needs a file name");
		return 1;
	}
	if (args_str(a, "-svg", &c->svg) || args_str(a, "-tl", &c->tl) ||
	    args_str(a, "-xl", &c->xl) || args_str(a, "-yl", &c->yl))
		return 1;
	if ((flags & PC_BIG) && args_flag(a, "-big")) {
		budget_allow_big();
		return 1;
	}
	if ((flags & PC_ZLABEL) && args_str(a, "-zl", &c->zl))
		return 1;
	if ((flags & PC_LANDSCAPE) && args_flag(a, "-l")) {
		c->landscape = 1;
		return 1;
	}
	/* X options (all four programs accept them: the guides list them
	 * for pdraw, contour and drawplot; drawmask opens a window too) */
	if (args_str(a, "-d", &c->x.display) || args_str(a, "-bd", &c->x.border) ||
	    args_str(a, "-fg", &c->x.fg) || args_str(a, "-bg", &c->x.bg) ||
	    args_str(a, "-fn", &c->x.font))
		return 1;
	if (args_flag(a, "-rv")) {
		c->x.reverse = 1;
		return 1;
	}
	if (args_int(a, "-bw", 0, 100, &bw)) {
		c->x.border_width = (int)bw;
		return 1;
	}
	if (s[0] == '=' && s[1]) {
		c->x.geometry = s;
		a->i++;
		return 1;
	}
	if (is_display(s)) {
		c->x.display = s;
		a->i++;
		return 1;
	}
	return 0;
}

const struct opt_value *plot_opt(const struct opt_spec *spec,
				 const struct opt_value *val, const char *key)
{
	int i = fmt_options_find(spec, key);
	return i >= 0 && val[i].set ? &val[i] : NULL;
}

static void take_str(const struct opt_spec *sp, const struct opt_value *v,
		     const char *key, const char **dst)
{
	const struct opt_value *o = plot_opt(sp, v, key);
	if (o)
		*dst = o->str;
}

static void take_int(const struct opt_spec *sp, const struct opt_value *v,
		     const char *key, int *dst)
{
	const struct opt_value *o = plot_opt(sp, v, key);
	if (o)
		*dst = (int)o->num;
}

static void settings_resolve(struct plot_settings *s, const struct opt_spec *spec,
			     const struct opt_value *val, const struct plot_cmd *c)
{
	const struct opt_value *o;
	if (spec && val) {
		take_str(spec, val, "toplabel", &s->toplabel);
		take_str(spec, val, "xlabel", &s->xlabel);
		take_str(spec, val, "ylabel", &s->ylabel);
		take_str(spec, val, "zlabel", &s->zlabel);
		take_str(spec, val, "printer", &s->printer);
		take_int(spec, val, "equalscale", &s->equalscale);
		take_int(spec, val, "postscript", &s->postscript);
		take_int(spec, val, "printplot", &s->printplot);
		take_int(spec, val, "noplot", &s->noplot);
		take_int(spec, val, "landscape", &s->landscape);
		take_int(spec, val, "grid", &s->grid);
		take_int(spec, val, "line", &s->line);
		take_int(spec, val, "linechange", &s->linechange);
		take_int(spec, val, "marker", &s->marker);
		take_int(spec, val, "markerchange", &s->markerchange);
		take_int(spec, val, "zticks", &s->zticks);
		if ((o = plot_opt(spec, val, "xticks")))
			s->xticks = (int)o->num, s->ticks_set = 1;
		if ((o = plot_opt(spec, val, "yticks")))
			s->yticks = (int)o->num, s->ticks_set = 1;
		if ((o = plot_opt(spec, val, "scale")))
			s->scale = o->num;
	}
	if (c->tl) s->toplabel = c->tl;
	if (c->xl) s->xlabel = c->xl;
	if (c->yl) s->ylabel = c->yl;
	if (c->zl) s->zlabel = c->zl;
	if (c->printer) s->printer = c->printer;
	if (c->scale > 0) s->scale = c->scale;
	if (c->print) s->printplot = 1;
	if (c->nops) s->postscript = 0;
	if (c->noplot) s->noplot = 1;
	if (c->landscape) s->landscape = 1;
	const char *env = getenv("POSTSCRIPT");
	if (env && strcasecmp(env, "off") == 0)
		s->postscript = 0;
	s->svg = c->svg;
	s->psfile = c->psfile ? c->psfile : PLOT_PS_FILE;
}

void plot_begin(struct plot_settings *s, const struct plot_settings *defaults,
		const struct opt_spec *spec, struct opt_value *val, const struct plot_cmd *c)
{
	size_t n = 0;
	while (spec[n].key)
		n++;
	memset(val, 0, (n + 1) * sizeof *val);
	if (c->optfile)
		fmt_options_read(c->optfile, spec, val);
	*s = *defaults;
	settings_resolve(s, spec, val, c);
}

/* lpr -Pprinter dataplot.ps; a missing lpr is an error, not a crash. */
static void print_ps(const char *printer, const char *psfile)
{
	if (!printer || !*printer)
		printer = getenv("PRINTER");
	char parg[256];
	char *argv[4];
	int n = 0;
	argv[n++] = "lpr";
	if (printer && *printer) {
		snprintf(parg, sizeof parg, "-P%s", printer);
		argv[n++] = parg;
	}
	argv[n++] = (char *)psfile;
	argv[n] = NULL;
	fflush(NULL);
	pid_t pid = fork();
	if (pid < 0)
		die("lpr: cannot start:");
	if (pid == 0) {
		execvp("lpr", argv);
		fprintf(stderr, "%s: lpr: cannot run: %s\n", util_prog(), strerror(errno));
		_exit(127);
	}
	int st;
	while (waitpid(pid, &st, 0) < 0)
		if (errno != EINTR)
			die("lpr: wait:");
	if (WIFEXITED(st) && WEXITSTATUS(st) == 127)
		exit(EXIT_RUNTIME);     /* the child said why */
	if (!WIFEXITED(st) || WEXITSTATUS(st) != 0)
		die("lpr failed on %s (status %d)", psfile,
		    WIFEXITED(st) ? WEXITSTATUS(st) : -1);
}

/* The guide's "send it to the printer?" - only at a terminal. */
static int ask_print(void)
{
	if (!isatty(0))
		return 0;
	fprintf(stderr, "Send the PostScript plot to the printer? [n] ");
	fflush(stderr);
	char buf[64];
	if (!fgets(buf, sizeof buf, stdin))
		return 0;
	return buf[0] == 'y' || buf[0] == 'Y';
}

void plot_output(const struct plot_settings *s, const struct plot_cmd *c,
		 plot_render render, draw_x11_key key, void *ctx)
{
	if (!s->noplot) {
		const char *why = NULL;
		struct draw_x11_opts xo = c->x;
		if (!xo.title)
			xo.title = util_prog();
		if (!draw_x11_built())
			why = "built without X11";
		else if (!xo.display && !getenv("DISPLAY"))
			why = "no DISPLAY";
		if (why || draw_x11_show(&xo, render, key, ctx, &why) != 0)
			fprintf(stderr, "%s: no X11 preview (%s); as with -noplot\n",
				util_prog(), why);
	}
	if (!s->postscript && !s->svg) {
		if (s->printplot)
			die("-print needs the PostScript plot, which -ps or POSTSCRIPT=OFF turned off");
		return;
	}
	struct draw *d = render(ctx);
	/* the PostScript and the SVG are committed together (util.h): a
	 * failing -svg must not leave dataplot.ps replaced */
	aout_defer();
	if (s->postscript) {
		struct draw_ps_opts po = {s->scale, d->w > d->h, s->toplabel};
		draw_write_ps(d, s->psfile, &po);
	}
	if (s->svg)
		draw_write_svg(d, s->svg);
	aout_finish();
	draw_free(d);
	if (s->postscript && (s->printplot || ask_print()))
		print_ps(s->printer, s->psfile);
	else if (s->printplot)
		die("-print needs the PostScript plot, which -ps or POSTSCRIPT=OFF turned off");
}

/* Reading holds a file's text and its numbers (8 bytes each, up to
 * twice that while the block grows) at once; the text is freed before
 * drawing. */
#define READ_BYTES_PER_NUMBER 16.0

void plot_budget(int nfiles, char *const *files, double bytes_per_number,
		 double seconds_per_number)
{
	double text_max = 0, text_sum = 0, numbers = 0;
	const char *largest = NULL;
	for (int i = 0; i < nfiles; i++) {
		double t, n;
		if (!fmt_plot_size(files[i], &t, &n))
			continue;
		if (!largest || t > text_max)
			largest = files[i], text_max = t;
		text_sum += t;
		numbers += n;
	}
	if (!largest)
		return;
	double bytes = fmax(text_max + numbers * READ_BYTES_PER_NUMBER,
			    numbers * bytes_per_number);
	char what[96], b[16];
	snprintf(what, sizeof what, "%s%.2g plot numbers (%s of text)",
		 nfiles > 1 ? "with the other files, " : "", numbers,
		 budget_bytes(b, text_sum));
	budget_check(largest, what, numbers * seconds_per_number, bytes);
}

/* One label: the file's if neither the options-file nor the command line
 * gave one. */
static void file_label(const char **dst, const char *text, const struct opt_spec *spec,
		       const struct opt_value *val, const char *key, const char *cmd)
{
	if (!text[0] || cmd || (spec && val && plot_opt(spec, val, key)))
		return;
	*dst = text;
}

void plot_settings_labels(struct plot_settings *s, const struct plot_labels *l,
			  const struct opt_spec *spec, const struct opt_value *val,
			  const struct plot_cmd *c)
{
	file_label(&s->toplabel, l->title, spec, val, "toplabel", c->tl);
	file_label(&s->xlabel, l->axis[0], spec, val, "xlabel", c->xl);
	file_label(&s->ylabel, l->axis[1], spec, val, "ylabel", c->yl);
	file_label(&s->zlabel, l->axis[2], spec, val, "zlabel", c->zl);
}

int plot_parse_times(const char *list, double **times)
{
	char *copy = xstrdup(list), *save = NULL;
	int n = 0;
	*times = NULL;
	for (char *t = strtok_r(copy, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
		*times = xreallocarray(*times, (size_t)n + 1, sizeof **times);
		if (!num_parse(t, &(*times)[n]))
			die_status(EXIT_USAGE, "-times: \"%.40s\" is not a number", t);
		n++;
	}
	free(copy);
	return n;
}
