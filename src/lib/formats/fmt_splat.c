/*
 * fmt_splat.c - reader and writer of the splat input file (see
 * fmt_splat.h and man/man5/splat.5).
 *
 * The file is read line by line through lex_line; every statement is
 * checked as it is read, and the checks that need the whole file (a rect
 * outside a window given later, a missing window) are made at the end,
 * still naming the offending line.  SPLAT's own manual is lost (thesis
 * 2.2.1), so the statements are ours; they keep the thesis' words
 * ("coma 0.4 lambda at field (1,0)", thesis 9.3.3).
 */
#include "fmt_splat.h"
#include "fmt_gds.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* Largest cutline count: far beyond any use (SPLAT_MAX_GRID, the grid's
 * bound, is in fmt_splat.h for splat -grid). */
enum { SPLAT_MAX_CUTPTS = 1000000 };
/* Highest fringe Zernike term implemented (the usual 37-term set). */
enum { SPLAT_MAX_ZERNIKE = 37 };
/* What a lithography user can mean (man/man5/splat.5): wavelengths from
 * EUV (0.0135 um) to the near infrared, defocus within tens of
 * micrometres, aberrations within tens of waves.  A value a thousand
 * times too large is most likely in nanometres: the message says so. */
static const double WAVE_MIN = 0.01, WAVE_MAX = 2, DEFOCUS_MAX = 50, ABERR_MAX = 100;

/* Dies "kw V is outside [lo, hi] UNIT" with a "nanometres?" hint when
 * v / 1000 would have been in range. */
static void in_range(struct lex *lx, const char *kw, double v, double lo, double hi,
		     const char *unit)
{
	if (v >= lo && v <= hi)
		return;
	if (fabs(v) / 1000 >= lo && fabs(v) / 1000 <= hi)
		lex_error(lx, "%s %g is outside [%g, %g] %s: nanometres? (%g nm is %g um)",
			  kw, v, lo, hi, unit, v, v / 1000);
	lex_error(lx, "%s %g is outside [%g, %g] %s", kw, v, lo, hi, unit);
}

/* A rect this many window widths away is taken for nanometres written as
 * micrometres (a 0.5 um feature as 500 in a 5 um window), and the message
 * says so. */
static const double NM_HINT = 50;

/* Slack when checking that a rect lies inside the window, relative to
 * the window size: inputs written with a few decimals must pass. */
static const double WINDOW_SLACK = 1e-9;
/* Bounds of the resist statement: a millimetre of film, and an index
 * beyond any optical material. */
static const double SPLAT_MAX_THICK = 1e3, SPLAT_MAX_INDEX = 100;

static double number(struct lex *lx, const char *kw, const char *what, const char *s)
{
	double v;
	if (!num_parse(s, &v))
		lex_error(lx, "%s: expected %s, found \"%.40s\"", kw, what, s);
	return v;
}

static void want(struct lex *lx, const char *kw, int n, int lo, int hi, const char *form)
{
	if (n - 1 < lo || n - 1 > hi)
		lex_error(lx, "%s: expected \"%s\"", kw, form);
}

static void add_aberr(struct splat_input *in, size_t *cap, enum splat_aberr_kind k,
		      double w, double hx, double hy, int z, long line)
{
	xgrow(&in->aberr, cap, (size_t)in->naberr + 1, sizeof *in->aberr);
	struct splat_aberr *a = &in->aberr[in->naberr++];
	a->kind = k;
	a->w = w;
	a->hx = hx;
	a->hy = hy;
	a->zernike = z;
	a->line = line;
}

/* "w field hx hy" of the field-dependent Seidel terms. */
static void field_term(struct lex *lx, struct splat_input *in, size_t *cap,
		       enum splat_aberr_kind k, char **tok, int n)
{
	if (n != 5 || strcasecmp(tok[2], "field") != 0)
		lex_error(lx, "%s: expected \"%s w field hx hy\" (w in waves, field "
			  "point as a fraction of the field radius)", tok[0], tok[0]);
	double w = number(lx, tok[0], "the aberration in waves", tok[1]);
	in_range(lx, tok[0], w, -ABERR_MAX, ABERR_MAX, "waves");
	double hx = number(lx, tok[0], "field hx", tok[3]);
	double hy = number(lx, tok[0], "field hy", tok[4]);
	if (hypot(hx, hy) > 1 + 1e-12)
		lex_error(lx, "%s: field point (%g, %g) is outside the field radius 1",
			  tok[0], hx, hy);
	add_aberr(in, cap, k, w, hx, hy, 0, lex_lineno(lx));
}

/* "T PHASE" pair: amplitude transmission 0..1 and phase in degrees. */
static void trans_phase(struct lex *lx, const char *kw, const char *ts, const char *ps,
			double *t, double *ph)
{
	*t = number(lx, kw, "an amplitude transmission", ts);
	if (*t < 0 || *t > 1)
		lex_error(lx, "%s: amplitude transmission %g is outside [0, 1]", kw, *t);
	*ph = number(lx, kw, "a phase in degrees", ps);
}

/* "resist thickness T index n planes N", the pairs in any order (as in
 * bleach(5)'s resist statement). */
static void resist_stack(struct lex *lx, struct splat_input *in, char **tok, int n)
{
	static const char form[] = "resist thickness T index n planes N";
	int got = 0;
	if (n != 7)
		lex_error(lx, "resist: expected \"%s\"", form);
	for (int i = 1; i + 1 < n; i += 2) {
		const char *k = tok[i], *v = tok[i + 1];
		int bit = strcasecmp(k, "thickness") == 0 ? 1 : strcasecmp(k, "index") == 0 ? 2 :
			  strcasecmp(k, "planes") == 0 ? 4 : 0;
		if (!bit)
			lex_error(lx, "resist: unknown word \"%.40s\" (expected thickness, index "
				  "or planes)", k);
		if (got & bit)
			lex_error(lx, "resist: %s given twice", k);
		got |= bit;
		if (bit == 1) {
			in->resist_thick = number(lx, "resist", "a thickness in micrometres", v);
			if (!(in->resist_thick > 0 && in->resist_thick <= SPLAT_MAX_THICK))
				lex_error(lx, "resist: thickness must be in (0, %g] um, found %g",
					  SPLAT_MAX_THICK, in->resist_thick);
		} else if (bit == 2) {
			in->resist_index = number(lx, "resist", "a refractive index", v);
			/* n >= 1 > NA: every direction in the pupil propagates */
			if (!(in->resist_index >= 1 && in->resist_index <= SPLAT_MAX_INDEX))
				lex_error(lx, "resist: index must be in [1, %g], found %g",
					  SPLAT_MAX_INDEX, in->resist_index);
		} else {
			long np;
			if (!num_parse_count(v, 2, SPLAT_MAX_PLANES, &np))
				lex_error(lx, "resist: planes: expected a count from 2 to %d, "
					  "found \"%.40s\"", SPLAT_MAX_PLANES, v);
			in->planes = (int)np;
		}
	}
	if (got != 7)
		lex_error(lx, "resist: expected \"%s\"", form);
	in->resist_line = lex_lineno(lx);
}

/* ---- polygon, gds, clip and window auto (the layout statements) ---- */

/* Most vertices in one polygon statement: the simplicity check is
 * quadratic, and a hand-written polygon is short. */
enum { SPLAT_MAX_POLY = 10000 };

static struct splat_layer *new_layer(struct splat_input *in, size_t *cap, struct lex *lx)
{
	xgrow(&in->mask.layers, cap, (size_t)in->mask.nlayers + 1, sizeof *in->mask.layers);
	struct splat_layer *l = &in->mask.layers[in->mask.nlayers++];
	memset(l, 0, sizeof *l);
	l->t = 1;
	l->phase = 0;
	l->after = in->mask.nrects;
	l->line = lex_lineno(lx);
	l->datatype = -1;
	return l;
}

/* polygon x1 y1 ... xn yn [t T PHASE] */
static void polygon_statement(struct lex *lx, struct splat_input *in, size_t *cap,
			      char **tok, int n)
{
	const char *kw = tok[0];
	int nc = n - 1;
	double t = 1, ph = 0;
	if (nc >= 3 && strcasecmp(tok[n - 3], "t") == 0) {
		trans_phase(lx, kw, tok[n - 2], tok[n - 1], &t, &ph);
		nc -= 3;
	}
	if (nc < 6 || nc % 2 != 0)
		lex_error(lx, "polygon: expected \"polygon x1 y1 x2 y2 x3 y3 ... [t T PHASE]\" "
			  "(at least 3 vertices, x y pairs)");
	if (nc / 2 > SPLAT_MAX_POLY)
		lex_error(lx, "polygon: more than %d vertices", SPLAT_MAX_POLY);
	double *xy = xreallocarray(NULL, (size_t)nc, sizeof *xy);
	for (int i = 0; i < nc; i++)
		xy[i] = number(lx, kw, i % 2 ? "a vertex y" : "a vertex x", tok[i + 1]);
	int nv = poly_dedup(xy, nc / 2);
	int ei, ej, line = 1;
	for (int i = 2; i < nv && line; i++)
		line = (xy[2] - xy[0]) * (xy[2 * i + 1] - xy[1]) ==
		       (xy[3] - xy[1]) * (xy[2 * i] - xy[0]);
	if (nv < 3 || line || !poly_simple(xy, nv, &ei, &ej)) {
		if (nv < 3 || line)
			ei = ej = 0;
		free(xy);
		if (nv < 3 || ei == ej)
			lex_error(lx, "polygon: zero area");
		lex_error(lx, "polygon: not simple: edge %d meets edge %d (edges self-intersect)",
			  ei + 1, ej + 1);
	}
	struct splat_layer *l = new_layer(in, cap, lx);
	l->t = t;
	l->phase = ph;
	l->pxy = xy;
	l->pn = nv;
	poly_set_add(&l->shapes, xy, nv);
}

/* "L" or "L/D", each 0..65535 */
static void layer_spec(struct lex *lx, const char *s, int *layer, int *dt)
{
	char buf[64];
	if (strlen(s) >= sizeof buf)
		lex_error(lx, "gds: expected a layer L or L/D, found \"%.40s\"", s);
	strcpy(buf, s);
	char *slash = strchr(buf, '/');
	long l, d = -1;
	if (slash)
		*slash = '\0';
	if (!num_parse_count(buf, 0, 65535, &l) ||
	    (slash && !num_parse_count(slash + 1, 0, 65535, &d)))
		lex_error(lx, "gds: expected a layer L or L/D (0 to 65535), found \"%.40s\"", s);
	*layer = (int)l;
	*dt = (int)d;
}

/* A relative FILE is relative to the folder of the input file. */
static char *resolve_path(const char *input, const char *file)
{
	if (file[0] == '/' || strcmp(input, "-") == 0 || strcmp(input, "stdin") == 0)
		return xstrdup(file);
	const char *slash = strrchr(input, '/');
	if (!slash)
		return xstrdup(file);
	size_t dl = (size_t)(slash - input) + 1;
	char *p = xmalloc(dl + strlen(file) + 1);
	memcpy(p, input, dl);
	strcpy(p + dl, file);
	return p;
}

/* gds FILE layer L[/D] [cell NAME] [T PHASE] */
static void gds_statement(struct lex *lx, struct splat_input *in, size_t *cap,
			  char **tok, int n)
{
	static const char form[] = "gds FILE layer L[/D] [cell NAME] [T PHASE]";
	if (n < 4)
		lex_error(lx, "gds: expected \"%s\"", form);
	struct splat_layer *l = new_layer(in, cap, lx);
	l->is_gds = 1;
	l->gds_file = resolve_path(lex_name(lx), tok[1]);
	int have_layer = 0;
	for (int i = 2; i < n;) {
		if (strcasecmp(tok[i], "layer") == 0 && i + 1 < n) {
			layer_spec(lx, tok[i + 1], &l->layer, &l->datatype);
			have_layer = 1;
			i += 2;
		} else if (strcasecmp(tok[i], "cell") == 0 && i + 1 < n) {
			free(l->cell);
			l->cell = xstrdup(tok[i + 1]);
			i += 2;
		} else if (i + 2 == n) {
			trans_phase(lx, "gds", tok[i], tok[i + 1], &l->t, &l->phase);
			i += 2;
		} else {
			lex_error(lx, "gds: unexpected \"%.40s\"; expected \"%s\"", tok[i], form);
		}
	}
	if (!have_layer)
		lex_error(lx, "gds: no layer; expected \"%s\"", form);
}

/* Loads the gds layers (window auto needs them all first), sets an auto
 * window, then clips every layer to the window or checks that it lies
 * inside. */
static void finish_layers(struct lex *lx, struct splat_input *in)
{
	struct splat_mask *m = &in->mask;
	double bb[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
	struct gds_lib *g = NULL;
	const char *gpath = NULL;
	for (int k = 0; k < m->nlayers; k++) {
		struct splat_layer *l = &m->layers[k];
		if (!l->is_gds)
			continue;
		char ctx[64];
		snprintf(ctx, sizeof ctx, "%.40s:%ld", lex_name(lx), l->line);
		if (!gpath || strcmp(gpath, l->gds_file) != 0) {
			fmt_gds_free(g);
			g = fmt_gds_read(l->gds_file, ctx);
			gpath = l->gds_file;
		}
		char layers[300];
		if (!fmt_gds_layer_list(g, l->layer, l->datatype, layers, sizeof layers)) {
			char want[32];
			snprintf(want, sizeof want, l->datatype < 0 ? "%d" : "%d/%d", l->layer,
				 l->datatype);
			fmt_gds_free(g);
			die("%s:%ld: gds: %s has no shape on layer %s; its layers: %s", lex_name(lx),
			    l->line, l->gds_file, want, layers[0] ? layers : "none");
		}
		double win[4] = {m->xmin, m->xmax, m->ymin, m->ymax};
		fmt_gds_shapes(g, l->cell, l->layer, l->datatype,
			       in->window_auto ? NULL : win, &l->shapes);
		for (int i = 0; i < l->shapes.n; i++) {
			const double *xy = poly_set_xy(&l->shapes, i);
			for (int v = 0; v < poly_set_nv(&l->shapes, i); v++) {
				bb[0] = fmin(bb[0], xy[2 * v]);
				bb[1] = fmax(bb[1], xy[2 * v]);
				bb[2] = fmin(bb[2], xy[2 * v + 1]);
				bb[3] = fmax(bb[3], xy[2 * v + 1]);
			}
		}
	}
	fmt_gds_free(g);
	if (in->window_auto) {
		if (!(bb[1] > bb[0] && bb[3] > bb[2]))
			lex_error(lx, "window auto: the gds statements give no shape to take "
				  "the window from");
		double mg = in->margin >= 0 ? in->margin : 2 * in->wavelength / in->na;
		m->xmin = bb[0] - mg;
		m->xmax = bb[1] + mg;
		m->ymin = bb[2] - mg;
		m->ymax = bb[3] + mg;
	}
	double sx = WINDOW_SLACK * (m->xmax - m->xmin);
	double sy = WINDOW_SLACK * (m->ymax - m->ymin);
	for (int k = 0; k < m->nlayers; k++) {
		struct splat_layer *l = &m->layers[k];
		struct poly_set c;
		memset(&c, 0, sizeof c);
		for (int i = 0; i < l->shapes.n; i++) {
			const double *xy = poly_set_xy(&l->shapes, i);
			int nv = poly_set_nv(&l->shapes, i);
			if (!l->is_gds && !in->clip) {
				for (int v = 0; v < nv; v++)
					if (xy[2 * v] < m->xmin - sx || xy[2 * v] > m->xmax + sx ||
					    xy[2 * v + 1] < m->ymin - sy || xy[2 * v + 1] > m->ymax + sy)
						die("%s:%ld: polygon is outside the window (give "
						    "\"clip on\" to clip it)", lex_name(lx), l->line);
			}
			double *o;
			int no = poly_clip_rect(xy, nv, m->xmin, m->xmax, m->ymin, m->ymax, &o);
			if (no)
				poly_set_add(&c, o, no);
			free(o);
		}
		poly_set_free(&l->shapes);
		l->shapes = c;
	}
}

/* ---- vector imaging: imaging, immersion, polarization, reduction ---- */

/* The immersion index's bound: beyond any liquid or solid immersion. */
static const double SPLAT_MAX_IMMERSION = 10;

/* The vector-imaging statements; returns 0 if kw is none of them. */
static int vector_statement(struct lex *lx, struct splat_input *in, char **tok, int n)
{
	const char *kw = tok[0];
	if (strcasecmp(kw, "imaging") == 0) {
		if (n != 2 || (strcasecmp(tok[1], "vector") && strcasecmp(tok[1], "scalar")))
			lex_error(lx, "imaging: expected \"imaging vector\" or \"imaging scalar\"");
		in->vector = strcasecmp(tok[1], "vector") == 0;
	} else if (strcasecmp(kw, "immersion") == 0) {
		want(lx, kw, n, 1, 1, "immersion N");
		in->immersion = number(lx, kw, "a refractive index", tok[1]);
		if (!(in->immersion >= 1 && in->immersion <= SPLAT_MAX_IMMERSION))
			lex_error(lx, "immersion: the index must be in [1, %g], found %g",
				  SPLAT_MAX_IMMERSION, in->immersion);
	} else if (strcasecmp(kw, "polarization") == 0) {
		static const char *names[] = {"unpolarized", "x", "y", "te", "tm"};
		int k = 0;
		while (n == 2 && k < 5 && strcasecmp(tok[1], names[k]))
			k++;
		if (n != 2 || k == 5)
			lex_error(lx, "polarization: expected x, y, te, tm or unpolarized");
		in->polarization = (enum splat_pol)k;
	} else if (strcasecmp(kw, "reduction") == 0) {
		want(lx, kw, n, 1, 1, "reduction R|inf");
		if (strcasecmp(tok[1], "inf") == 0) {
			in->reduction = INFINITY;
		} else {
			in->reduction = number(lx, kw, "a reduction ratio or inf", tok[1]);
			if (!(in->reduction >= 1 && in->reduction <= 1e6))
				lex_error(lx, "reduction: expected a ratio from 1 to 1e6 or inf, "
					  "found %g", in->reduction);
		}
	} else {
		return 0;
	}
	return 1;
}

/* na below the immersion index (na may reach it with an immersion
 * statement), and the object-side sine na / R below 1. */
static void check_na(struct lex *lx, const struct splat_input *in)
{
	long line = in->na_line ? in->na_line : 1L;
	if (!(in->na < in->immersion)) {
		if (in->immersion == 1)
			die("%s:%ld: na must be in (0, 1), found %g", lex_name(lx), line, in->na);
		die("%s:%ld: na %g must be below the immersion index %g", lex_name(lx), line,
		    in->na, in->immersion);
	}
	if (!(in->na < in->reduction))
		die("%s:%ld: na %g on the wafer is na / R = %g on the mask, not below 1: "
		    "reduction R must exceed na", lex_name(lx), line, in->na, in->na / in->reduction);
}

/* What the reader keeps between statements: the capacities of the
 * growing arrays and the lines whole-file checks name. */
struct reader {
	struct lex *lx;
	struct splat_input *in;
	size_t acap, rcap, ccap, lcap;
	int have_window;
	long window_line, source_line;
};

/* The optics: wavelength, NA, the source, defocus, the resist stack and
 * the aberrations.  Returns 0 if kw is none of these. */
static int optics_statement(struct reader *rd, const char *kw, char **tok, int n)
{
	struct lex *lx = rd->lx;
	struct splat_input *in = rd->in;
	if (strcasecmp(kw, "wavelength") == 0) {
		want(lx, kw, n, 1, 1, "wavelength micrometres");
		in->wavelength = number(lx, kw, "a wavelength in micrometres", tok[1]);
		if (!(in->wavelength > 0))
			lex_error(lx, "wavelength must be positive");
		in_range(lx, kw, in->wavelength, WAVE_MIN, WAVE_MAX, "um");
	} else if (strcasecmp(kw, "na") == 0) {
		want(lx, kw, n, 1, 1, "na value");
		in->na = number(lx, kw, "a numerical aperture", tok[1]);
		/* below the immersion index: checked at the end (check_na) */
		if (!(in->na > 0 && in->na < SPLAT_MAX_IMMERSION))
			lex_error(lx, "na must be in (0, 1), found %g", in->na);
		in->na_line = lex_lineno(lx);
	} else if (strcasecmp(kw, "sigma") == 0) {
		want(lx, kw, n, 1, 1, "sigma value");
		double s = number(lx, kw, "a partial coherence", tok[1]);
		if (s < 0)
			lex_error(lx, "sigma must not be negative, found %g", s);
		in->source = SPLAT_SRC_CIRCLE;
		in->sigma = s;
		rd->source_line = lex_lineno(lx);
	} else if (strcasecmp(kw, "annular") == 0) {
		want(lx, kw, n, 2, 2, "annular s_in s_out");
		double a = number(lx, kw, "s_in", tok[1]);
		double b = number(lx, kw, "s_out", tok[2]);
		if (a < 0 || b <= a)
			lex_error(lx, "annular: need 0 <= s_in < s_out, found %g %g", a, b);
		in->source = SPLAT_SRC_ANNULAR;
		in->s_in = a;
		in->s_out = b;
		rd->source_line = lex_lineno(lx);
	} else if (strcasecmp(kw, "quadrupole") == 0 || strcasecmp(kw, "dipole") == 0) {
		int quad = strcasecmp(kw, "quadrupole") == 0;
		if (quad)
			want(lx, kw, n, 2, 2, "quadrupole c r");
		else
			want(lx, kw, n, 2, 3, "dipole c r [x|y]");
		double c = number(lx, kw, "the pole centre distance", tok[1]);
		double r = number(lx, kw, "the pole radius", tok[2]);
		if (c < 0 || r <= 0)
			lex_error(lx, "%s: need c >= 0 and r > 0, found %g %g", kw, c, r);
		/* the poles are added as separate discs: they must not overlap */
		double gap = quad ? c * sqrt(2.0) : 2 * c;
		if (gap < 2 * r)
			lex_error(lx, "%s: poles of radius %g at distance %g overlap", kw, r, c);
		in->dipole_y = 0;
		if (!quad && n == 4) {
			if (strcasecmp(tok[3], "y") == 0)
				in->dipole_y = 1;
			else if (strcasecmp(tok[3], "x") != 0)
				lex_error(lx, "dipole: expected x or y, found \"%.40s\"", tok[3]);
		}
		in->source = quad ? SPLAT_SRC_QUADRUPOLE : SPLAT_SRC_DIPOLE;
		in->pole_c = c;
		in->pole_r = r;
		rd->source_line = lex_lineno(lx);
	} else if (strcasecmp(kw, "defocus") == 0) {
		want(lx, kw, n, 1, 1, "defocus micrometres");
		in->defocus = number(lx, kw, "a defocus in micrometres", tok[1]);
		in_range(lx, kw, in->defocus, -DEFOCUS_MAX, DEFOCUS_MAX, "um");
	} else if (strcasecmp(kw, "resist") == 0) {
		resist_stack(lx, in, tok, n);
	} else if (strcasecmp(kw, "coma") == 0) {
		field_term(lx, in, &rd->acap, SPLAT_AB_COMA, tok, n);
	} else if (strcasecmp(kw, "astigmatism") == 0) {
		field_term(lx, in, &rd->acap, SPLAT_AB_ASTIGMATISM, tok, n);
	} else if (strcasecmp(kw, "curvature") == 0) {
		field_term(lx, in, &rd->acap, SPLAT_AB_CURVATURE, tok, n);
	} else if (strcasecmp(kw, "distortion") == 0) {
		field_term(lx, in, &rd->acap, SPLAT_AB_DISTORTION, tok, n);
	} else if (strcasecmp(kw, "spherical") == 0) {
		want(lx, kw, n, 1, 1, "spherical w");
		double w = number(lx, kw, "the aberration in waves", tok[1]);
		in_range(lx, kw, w, -ABERR_MAX, ABERR_MAX, "waves");
		add_aberr(in, &rd->acap, SPLAT_AB_SPHERICAL, w, 0, 0, 0, lex_lineno(lx));
	} else if (strcasecmp(kw, "zernike") == 0) {
		want(lx, kw, n, 2, 2, "zernike N c");
		long z;
		if (!num_parse_count(tok[1], 1, SPLAT_MAX_ZERNIKE, &z))
			lex_error(lx, "zernike: expected a fringe term number 1 to %d, "
				  "found \"%.40s\"", SPLAT_MAX_ZERNIKE, tok[1]);
		double w = number(lx, kw, "a coefficient in waves", tok[2]);
		in_range(lx, kw, w, -ABERR_MAX, ABERR_MAX, "waves");
		add_aberr(in, &rd->acap, SPLAT_AB_ZERNIKE, w, 0, 0, (int)z, lex_lineno(lx));
	} else {
		return 0;
	}
	return 1;
}

/* The mask: background, rect, polygon, gds, clip.  Returns 0 if kw is
 * none of these. */
static int mask_statement(struct reader *rd, const char *kw, char **tok, int n)
{
	struct lex *lx = rd->lx;
	struct splat_input *in = rd->in;
	if (strcasecmp(kw, "background") == 0) {
		if (n == 2 && strcasecmp(tok[1], "dark") == 0) {
			in->mask.bg_t = 0;
			in->mask.bg_phase = 0;
		} else if (n == 2 && strcasecmp(tok[1], "clear") == 0) {
			in->mask.bg_t = 1;
			in->mask.bg_phase = 0;
		} else if (n == 3) {
			trans_phase(lx, kw, tok[1], tok[2], &in->mask.bg_t, &in->mask.bg_phase);
		} else {
			lex_error(lx, "background: expected dark, clear or \"T PHASE\"");
		}
	} else if (strcasecmp(kw, "rect") == 0) {
		if (n != 5 && n != 7)
			lex_error(lx, "rect: expected \"rect x1 y1 x2 y2 [T PHASE]\"");
		struct splat_rect r;
		r.x1 = number(lx, kw, "x1", tok[1]);
		r.y1 = number(lx, kw, "y1", tok[2]);
		r.x2 = number(lx, kw, "x2", tok[3]);
		r.y2 = number(lx, kw, "y2", tok[4]);
		r.t = 1;
		r.phase = 0;
		if (n == 7)
			trans_phase(lx, kw, tok[5], tok[6], &r.t, &r.phase);
		if (r.x1 > r.x2) { double t = r.x1; r.x1 = r.x2; r.x2 = t; }
		if (r.y1 > r.y2) { double t = r.y1; r.y1 = r.y2; r.y2 = t; }
		if (!(r.x2 > r.x1 && r.y2 > r.y1))
			lex_error(lx, "rect: zero width or height");
		r.line = lex_lineno(lx);
		xgrow(&in->mask.rects, &rd->rcap, (size_t)in->mask.nrects + 1, sizeof r);
		in->mask.rects[in->mask.nrects++] = r;
	} else if (strcasecmp(kw, "polygon") == 0) {
		polygon_statement(lx, in, &rd->lcap, tok, n);
	} else if (strcasecmp(kw, "gds") == 0) {
		gds_statement(lx, in, &rd->lcap, tok, n);
	} else if (strcasecmp(kw, "clip") == 0) {
		if (n != 2 || (strcasecmp(tok[1], "on") != 0 && strcasecmp(tok[1], "off") != 0))
			lex_error(lx, "clip: expected \"clip on\" or \"clip off\"");
		in->clip = strcasecmp(tok[1], "on") == 0;
	} else {
		return 0;
	}
	return 1;
}

/* The simulation cell and the outputs: window, grid, contour, cutline.
 * Returns 0 if kw is none of these. */
static int output_statement(struct reader *rd, const char *kw, char **tok, int n)
{
	struct lex *lx = rd->lx;
	struct splat_input *in = rd->in;
	if (strcasecmp(kw, "window") == 0 && n >= 2 && strcasecmp(tok[1], "auto") == 0) {
		in->margin = -1;
		if (n == 4 && strcasecmp(tok[2], "margin") == 0) {
			in->margin = number(lx, kw, "a margin in micrometres", tok[3]);
			if (in->margin < 0)
				lex_error(lx, "window auto: the margin must not be negative");
		} else if (n != 2) {
			lex_error(lx, "window: expected \"window auto [margin m]\"");
		}
		in->window_auto = 1;
		rd->have_window = 1;
		rd->window_line = lex_lineno(lx);
	} else if (strcasecmp(kw, "window") == 0) {
		in->window_auto = 0;
		want(lx, kw, n, 4, 4, "window xmin xmax ymin ymax");
		double w[4];
		for (int i = 0; i < 4; i++)
			w[i] = number(lx, kw, "a window bound", tok[i + 1]);
		if (!(w[1] > w[0] && w[3] > w[2]))
			lex_error(lx, "window: need xmax > xmin and ymax > ymin (zero area)");
		in->mask.xmin = w[0];
		in->mask.xmax = w[1];
		in->mask.ymin = w[2];
		in->mask.ymax = w[3];
		rd->have_window = 1;
		rd->window_line = lex_lineno(lx);
	} else if (strcasecmp(kw, "grid") == 0) {
		want(lx, kw, n, 2, 2, "grid nx ny");
		long nx, ny;
		if (!num_parse_count(tok[1], 2, SPLAT_MAX_GRID, &nx) ||
		    !num_parse_count(tok[2], 2, SPLAT_MAX_GRID, &ny))
			lex_error(lx, "grid: expected two counts from 2 to %d",
				  SPLAT_MAX_GRID);
		in->nx = (int)nx;
		in->ny = (int)ny;
	} else if (strcasecmp(kw, "contour") == 0) {
		want(lx, kw, n, 1, 1, "contour FILE");
		free(in->contour);
		in->contour = xstrdup(tok[1]);
		in->contour_set = 1;
	} else if (strcasecmp(kw, "cutline") == 0) {
		want(lx, kw, n, 6, 6, "cutline x1 y1 x2 y2 npts FILE");
		struct splat_cutline c;
		c.x1 = number(lx, kw, "x1", tok[1]);
		c.y1 = number(lx, kw, "y1", tok[2]);
		c.x2 = number(lx, kw, "x2", tok[3]);
		c.y2 = number(lx, kw, "y2", tok[4]);
		long np;
		if (!num_parse_count(tok[5], 2, SPLAT_MAX_CUTPTS, &np))
			lex_error(lx, "cutline: expected a point count from 2 to %d, "
				  "found \"%.40s\"", SPLAT_MAX_CUTPTS, tok[5]);
		c.npts = (int)np;
		c.line = lex_lineno(lx);
		xgrow(&in->cutlines, &rd->ccap, (size_t)in->ncutlines + 1, sizeof c);
		c.file = xstrdup(tok[6]);
		in->cutlines[in->ncutlines++] = c;
	} else {
		return 0;
	}
	return 1;
}

struct splat_input *fmt_splat_read(const char *path)
{
	struct lex *lx = lex_open(path);
	lex_expect(lx, "splat(5)");
	struct splat_input *in = xcalloc(1, sizeof *in);
	struct reader r = {lx, in, 0, 0, 0, 0, 0, 0, 0};
	in->wavelength = 0.436;
	in->na = 0.28;
	in->source = SPLAT_SRC_CIRCLE;
	in->sigma = 0.5;
	in->nx = in->ny = 51;
	in->mask.bg_t = 0;
	in->mask.bg_phase = 0;
	in->margin = -1;
	in->immersion = 1;
	in->reduction = 4;

	char **tok;
	const int *quoted;
	int n;
	while ((n = lex_line(lx, &tok, &quoted)) > 0) {
		const char *kw = tok[0];
		if (quoted[0])
			lex_error(lx, "unknown statement \"%.40s\"", kw);
		if (!optics_statement(&r, kw, tok, n) && !mask_statement(&r, kw, tok, n) &&
		    !output_statement(&r, kw, tok, n) && !vector_statement(lx, in, tok, n))
			lex_error(lx, "unknown statement \"%.40s\"", kw);
	}

	/* whole-file checks */
	if (!r.have_window)
		lex_error(lx, "no window statement (the simulation cell is required)");
	/* a source direction must propagate: sine sigma NA at most 1 (a
	 * source of sigma 45 at NA 0.28 is light from beyond the horizon) */
	double smax = in->source == SPLAT_SRC_CIRCLE ? in->sigma
		    : in->source == SPLAT_SRC_ANNULAR ? in->s_out : in->pole_c + in->pole_r;
	check_na(lx, in);
	if (smax * in->na > in->immersion)
		die("%s:%ld: the source reaches %g NA = %g, beyond the sine of 90 degrees "
		    "(the largest source radius times NA must be at most %g)",
		    lex_name(lx), r.source_line ? r.source_line : 1L, smax, smax * in->na,
		    in->immersion);
	if (in->mask.nlayers || in->window_auto)
		finish_layers(lx, in);
	const struct splat_mask *m = &in->mask;
	double sx = WINDOW_SLACK * (m->xmax - m->xmin);
	double sy = WINDOW_SLACK * (m->ymax - m->ymin);
	for (int i = 0; i < m->nrects; i++) {
		const struct splat_rect *rc = &m->rects[i];
		if (rc->x1 < m->xmin - sx || rc->x2 > m->xmax + sx ||
		    rc->y1 < m->ymin - sy || rc->y2 > m->ymax + sy)
			die("%s:%ld: rect is outside the window of line %ld%s",
			    lex_name(lx), rc->line, r.window_line,
			    /* a rect of whole hundreds in a window of a few um:
			     * nanometres for micrometres */
			    fmax(fmax(fabs(rc->x1), fabs(rc->x2)), fmax(fabs(rc->y1), fabs(rc->y2))) >=
					    NM_HINT * fmax(m->xmax - m->xmin, m->ymax - m->ymin)
				    ? " (lengths are in micrometres, not nanometres)" : "");
	}
	/* an image stack holds planes * nx * ny values: bound it as one grid */
	if (in->planes &&
	    (double)in->planes * in->nx * in->ny > (double)SPLAT_MAX_GRID * SPLAT_MAX_GRID)
		die("%s:%ld: resist: %d planes of %dx%d points are %.3g values (%.3g GB), "
		    "more than %d x %d: use fewer planes or a coarser grid", lex_name(lx),
		    in->resist_line, in->planes, in->nx, in->ny,
		    (double)in->planes * in->nx * in->ny,
		    8e-9 * in->planes * in->nx * in->ny, SPLAT_MAX_GRID, SPLAT_MAX_GRID);
	if (!in->contour)
		in->contour = xstrdup("splat.cont");
	lex_close(lx);
	return in;
}

void fmt_splat_free(struct splat_input *in)
{
	if (!in)
		return;
	free(in->aberr);
	free(in->mask.rects);
	for (int i = 0; i < in->mask.nlayers; i++) {
		struct splat_layer *l = &in->mask.layers[i];
		poly_set_free(&l->shapes);
		free(l->pxy);
		free(l->gds_file);
		free(l->cell);
	}
	free(in->mask.layers);
	for (int i = 0; i < in->ncutlines; i++)
		free(in->cutlines[i].file);
	free(in->cutlines);
	free(in->contour);
	free(in);
}

static void put(FILE *f, double v)
{
	fputc(' ', f);
	num_print(f, v);
}

/* A file name as one token: quoted when it holds blanks or '#'. */
static void put_name(FILE *f, const char *s)
{
	if (strpbrk(s, " \t#,\"") || !*s)
		fprintf(f, " \"%s\"", s);
	else
		fprintf(f, " %s", s);
}

/* A polygon as given, or a gds statement with its resolved file name
 * (the window a gds statement was clipped to is written as the window). */
static void write_layer(FILE *f, const struct splat_layer *l)
{
	if (l->is_gds) {
		fputs("gds", f);
		put_name(f, l->gds_file);
		fprintf(f, " layer %d", l->layer);
		if (l->datatype >= 0)
			fprintf(f, "/%d", l->datatype);
		if (l->cell) {
			fputs(" cell", f);
			put_name(f, l->cell);
		}
	} else {
		fputs("polygon", f);
		for (int i = 0; i < 2 * l->pn; i++)
			put(f, l->pxy[i]);
		fputs(" t", f);
	}
	put(f, l->t); put(f, l->phase); fputc('\n', f);
}

void fmt_splat_write(const char *path, const struct splat_input *in)
{
	static const char *names[] = {"spherical", "coma", "astigmatism",
				      "curvature", "distortion", "zernike"};
	struct aout *a = aout_open(path);
	FILE *f = a->f;
	fputs("wavelength", f); put(f, in->wavelength); fputc('\n', f);
	fputs("na", f); put(f, in->na); fputc('\n', f);
	switch (in->source) {
	case SPLAT_SRC_CIRCLE:
		fputs("sigma", f); put(f, in->sigma);
		break;
	case SPLAT_SRC_ANNULAR:
		fputs("annular", f); put(f, in->s_in); put(f, in->s_out);
		break;
	case SPLAT_SRC_QUADRUPOLE:
		fputs("quadrupole", f); put(f, in->pole_c); put(f, in->pole_r);
		break;
	case SPLAT_SRC_DIPOLE:
		fputs("dipole", f); put(f, in->pole_c); put(f, in->pole_r);
		fputs(in->dipole_y ? " y" : " x", f);
		break;
	}
	fputc('\n', f);
	fputs("defocus", f); put(f, in->defocus); fputc('\n', f);
	/* the vector statements when not their defaults (older files stay as
	 * they were written) */
	static const char *pols[] = {"unpolarized", "x", "y", "te", "tm"};
	if (in->vector)
		fputs("imaging vector\n", f);
	if (in->immersion != 1) {
		fputs("immersion", f); put(f, in->immersion); fputc('\n', f);
	}
	if (in->polarization != SPLAT_POL_UNPOLARIZED)
		fprintf(f, "polarization %s\n", pols[in->polarization]);
	if (isinf(in->reduction))
		fputs("reduction inf\n", f);
	else if (in->reduction != 4) {
		fputs("reduction", f); put(f, in->reduction); fputc('\n', f);
	}
	if (in->planes) {
		fputs("resist thickness", f); put(f, in->resist_thick);
		fputs(" index", f); put(f, in->resist_index);
		fprintf(f, " planes %d\n", in->planes);
	}
	for (int i = 0; i < in->naberr; i++) {
		const struct splat_aberr *ab = &in->aberr[i];
		fputs(names[ab->kind], f);
		if (ab->kind == SPLAT_AB_ZERNIKE)
			fprintf(f, " %d", ab->zernike);
		put(f, ab->w);
		if (ab->kind != SPLAT_AB_SPHERICAL && ab->kind != SPLAT_AB_ZERNIKE) {
			fputs(" field", f); put(f, ab->hx); put(f, ab->hy);
		}
		fputc('\n', f);
	}
	const struct splat_mask *m = &in->mask;
	fputs("window", f); put(f, m->xmin); put(f, m->xmax); put(f, m->ymin); put(f, m->ymax);
	fputc('\n', f);
	fputs("background", f); put(f, m->bg_t); put(f, m->bg_phase); fputc('\n', f);
	if (in->clip)
		fputs("clip on\n", f);
	int nl = 0;
	for (int i = 0; i <= m->nrects; i++) {
		for (; nl < m->nlayers && m->layers[nl].after == i; nl++)
			write_layer(f, &m->layers[nl]);
		if (i == m->nrects)
			break;
		const struct splat_rect *r = &m->rects[i];
		fputs("rect", f); put(f, r->x1); put(f, r->y1); put(f, r->x2); put(f, r->y2);
		put(f, r->t); put(f, r->phase); fputc('\n', f);
	}
	fprintf(f, "grid %d %d\n", in->nx, in->ny);
	fputs("contour", f); put_name(f, in->contour); fputc('\n', f);
	for (int i = 0; i < in->ncutlines; i++) {
		const struct splat_cutline *c = &in->cutlines[i];
		fputs("cutline", f); put(f, c->x1); put(f, c->y1); put(f, c->x2); put(f, c->y2);
		fprintf(f, " %d", c->npts);
		put_name(f, c->file);
		fputc('\n', f);
	}
	aout_commit(a);
}

void fmt_splat_mask_at(const struct splat_mask *m, double x, double y,
		       double *t, double *phase)
{
	*t = m->bg_t;
	*phase = m->bg_phase;
	if (m->nlayers) {
		/* the last of the rects and layers in file order that covers it */
		int nl = m->nlayers - 1;
		for (int i = m->nrects; i >= 0; i--) {
			for (; nl >= 0 && m->layers[nl].after == i; nl--) {
				const struct splat_layer *l = &m->layers[nl];
				for (int k = 0; k < l->shapes.n; k++)
					if (poly_winding(poly_set_xy(&l->shapes, k),
							 poly_set_nv(&l->shapes, k), x, y)) {
						*t = l->t;
						*phase = l->phase;
						return;
					}
			}
			if (i == 0)
				break;
			const struct splat_rect *r = &m->rects[i - 1];
			if (x >= r->x1 && x <= r->x2 && y >= r->y1 && y <= r->y2) {
				*t = r->t;
				*phase = r->phase;
				return;
			}
		}
		return;
	}
	for (int i = m->nrects - 1; i >= 0; i--) {
		const struct splat_rect *r = &m->rects[i];
		if (x >= r->x1 && x <= r->x2 && y >= r->y1 && y <= r->y2) {
			*t = r->t;
			*phase = r->phase;
			return;
		}
	}
}
