/*
 * fmt_bleach.c - the bleach input file (see fmt_bleach.h, bleach.5).
 *
 * One statement a line: a keyword, then either positional numbers
 * (layer, substrate, dose, develop) or keyword-value pairs (resist,
 * grid, crosslink).  Everything is checked here - ranges, missing and
 * repeated statements, statements that need each other - so that the
 * program never meets an input it cannot simulate.  A repeated statement
 * is an error (except layer, which stacks films top first), because a
 * silently ignored line in a process description is a wrong simulation.
 */
#include "fmt_bleach.h"
#include "filmstack.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

/* Statements, for "given twice" and "missing" checks. */
enum { S_WAVE, S_AMB, S_RESIST, S_SUB, S_DOSE, S_BAKE, S_DEV, S_GRID,
       S_SW, S_XLINK, S_CAR, S_PEB, S_STOCH, S_COUNT };

/* A value of car or peb written ARRHENIUS(A Ea): evaluated once the
 * whole file is read, at peb's temperature. */
struct arrh {
	int used;
	double A, ea;
	double *dst;
	double min, max;
	const char *what;
	long line;
};
enum { ARR_KAMP, ARR_KLOSS, ARR_KQ, ARR_DH, ARR_DQ, ARR_COUNT };

struct parser {
	struct lex *lx;
	long seen[S_COUNT];         /* line of each statement, 0 if absent */
	struct bleach_input *in;
	struct arrh arr[ARR_COUNT];
};

static double number(struct parser *p, const char *tok, const char *what,
		     double min, double max)
{
	double v;
	if (!tok)
		lex_error(p->lx, "missing %s", what);
	if (!num_parse(tok, &v))
		lex_error(p->lx, "expected %s (a number), found \"%.40s\"", what, tok);
	if (!(v >= min && v <= max))
		lex_error(p->lx, "%s %s out of range [%g, %g]", what, tok, min, max);
	return v;
}

static long count(struct parser *p, const char *tok, const char *what,
		  long min, long max)
{
	long v;
	if (!tok)
		lex_error(p->lx, "missing %s", what);
	if (!num_parse_count(tok, min, max, &v))
		lex_error(p->lx, "expected %s (a whole number from %ld to %ld), found \"%.40s\"",
			  what, min, max, tok);
	return v;
}

static void once(struct parser *p, int s, const char *kw)
{
	if (p->seen[s])
		lex_error(p->lx, "%s given twice (first on line %ld)", kw, p->seen[s]);
	p->seen[s] = lex_lineno(p->lx);
}

static void nargs(struct parser *p, char **t, int nt, int lo, int hi, const char *kw)
{
	if (nt - 1 < lo)
		lex_error(p->lx, "%s: expected %d value%s, found %d", kw, lo,
			  lo == 1 ? "" : "s", nt - 1);
	if (nt - 1 > hi)
		lex_error(p->lx, "%s: unexpected \"%.40s\" after %d value%s", kw,
			  t[hi + 1], hi, hi == 1 ? "" : "s");
}

/* Common upper bounds: wide enough for any real process, small enough
 * that no later arithmetic overflows. */
#define BIG_LEN 1e3        /* um */
#define BIG_INDEX 100.0
#define BIG_DILL 1e3       /* 1/um or cm2/mJ */
#define BIG_DOSE 1e6       /* mJ/cm2 */
#define BIG_RATE 1e6       /* um/s */

static void st_resist(struct parser *p, char **t, int nt)
{
	struct bleach_input *in = p->in;
	int got_t = 0, got_n = 0, got_d = 0;
	for (int i = 1; i < nt;) {
		if (strcasecmp(t[i], "thickness") == 0) {
			in->thick = number(p, i + 1 < nt ? t[i + 1] : NULL,
					   "resist thickness", 1e-6, BIG_LEN);
			got_t = 1;
			i += 2;
		} else if (strcasecmp(t[i], "index") == 0) {
			in->index = number(p, i + 1 < nt ? t[i + 1] : NULL,
					   "resist index", 1e-3, BIG_INDEX);
			got_n = 1;
			i += 2;
		} else if (strcasecmp(t[i], "dill") == 0) {
			in->A = number(p, i + 1 < nt ? t[i + 1] : NULL, "Dill A", 0, BIG_DILL);
			in->B = number(p, i + 2 < nt ? t[i + 2] : NULL, "Dill B", 0, BIG_DILL);
			in->C = number(p, i + 3 < nt ? t[i + 3] : NULL, "Dill C", 0, BIG_DILL);
			got_d = 1;
			i += 4;
		} else {
			lex_error(p->lx, "resist: unknown word \"%.40s\" (expected thickness, index or dill)",
				  t[i]);
		}
	}
	if (!got_t)
		lex_error(p->lx, "resist: missing thickness");
	if (!got_n)
		lex_error(p->lx, "resist: missing index");
	if (!got_d)
		lex_error(p->lx, "resist: missing dill A B C");
}

static void st_develop(struct parser *p, char **t, int nt)
{
	struct bleach_input *in = p->in;
	if (nt < 2)
		lex_error(p->lx, "develop: missing model (kim, mack, dill, canegative, enhanced or notch)");
	const char *m = t[1];
	int lo, hi;
	if (strcasecmp(m, "enhanced") == 0) {
		in->model = BLEACH_MACKENH; lo = hi = 5;
	} else if (strcasecmp(m, "notch") == 0) {
		in->model = BLEACH_NOTCH; lo = hi = 5;
	} else if (strcasecmp(m, "kim") == 0) {
		in->model = BLEACH_KIM; lo = 3; hi = 6;
	} else if (strcasecmp(m, "mack") == 0) {
		in->model = BLEACH_MACK; lo = hi = 4;
	} else if (strcasecmp(m, "dill") == 0) {
		in->model = BLEACH_DILL; lo = hi = 3;
	} else if (strcasecmp(m, "canegative") == 0) {
		in->model = BLEACH_CANEG; lo = hi = 3;
	} else {
		lex_error(p->lx, "develop: unknown model \"%.40s\" (expected kim, mack, dill, canegative, enhanced or notch)", m);
	}
	int n = nt - 2;
	if (n < lo || n > hi || (in->model == BLEACH_KIM && n != 3 && n != 6))
		lex_error(p->lx, "develop %s: expected %s values, found %d", m,
			  in->model == BLEACH_KIM ? "3 or 6" : lo == 5 ? "5" : lo == 4 ? "4" : "3", n);
	in->npar = n;
	for (int i = 0; i < n; i++) {
		char what[32];
		snprintf(what, sizeof what, "develop %s parameter %d", m, i + 1);
		in->par[i] = number(p, t[i + 2], what, -BIG_RATE, BIG_RATE);
	}
	const double *r = in->par;
	switch (in->model) {
	case BLEACH_KIM:
		if (!(r[0] > 0 && r[1] > 0))
			lex_error(p->lx, "develop kim: R1 and R2 must be positive");
		if (n == 6 && !(r[3] > 0))
			lex_error(p->lx, "develop kim: R4 must be positive");
		if (n == 6 && (r[4] < 0 || r[5] < 0))
			lex_error(p->lx, "develop kim: R5 and R6 must not be negative");
		break;
	case BLEACH_MACK:
		if (!(r[0] >= 0 && r[1] >= 0))
			lex_error(p->lx, "develop mack: Rmax and Rmin must not be negative");
		if (!(r[2] >= 0 && r[2] < 1))
			lex_error(p->lx, "develop mack: Mth must be in [0, 1)");
		if (!(r[3] > 1 && r[3] <= 1000))
			lex_error(p->lx, "develop mack: n must be above 1 (and at most 1000)");
		break;
	case BLEACH_DILL:
		/* exp(E1 + E2 M + E3 M^2) must stay finite for M in [0, 1] */
		if (fabs(r[0]) + fabs(r[1]) + fabs(r[2]) > 200)
			lex_error(p->lx, "develop dill: |E1| + |E2| + |E3| above 200 overflows");
		break;
	case BLEACH_CANEG:
		if (!(r[0] >= 0 && r[1] >= 0))
			lex_error(p->lx, "develop canegative: Rmax and Rmin must not be negative");
		if (!(r[2] > 0 && r[2] <= 1000))
			lex_error(p->lx, "develop canegative: p must be in (0, 1000]");
		break;
	case BLEACH_MACKENH:
		/* Rmin <= Rresin <= Rmax, all positive: the enhancement and
		 * inhibition constants Rmax/Rresin - 1, Rresin/Rmin - 1 >= 0 */
		if (!(r[1] > 0 && r[1] <= r[2] && r[2] <= r[0]))
			lex_error(p->lx, "develop enhanced: need 0 < Rmin <= Rresin <= Rmax");
		if (!(r[3] > 0 && r[3] <= 1000 && r[4] > 0 && r[4] <= 1000))
			lex_error(p->lx, "develop enhanced: n and l must be in (0, 1000]");
		break;
	case BLEACH_NOTCH:
		if (!(r[0] >= 0 && r[1] >= 0))
			lex_error(p->lx, "develop notch: Rmax and Rmin must not be negative");
		if (!(r[2] >= 0 && r[2] <= 1000))
			lex_error(p->lx, "develop notch: n must be in [0, 1000]");
		if (!(r[3] >= 0 && r[3] < 1))
			lex_error(p->lx, "develop notch: Mth_notch must be in [0, 1)");
		if (!(r[4] > 1 && r[4] <= 1000))
			lex_error(p->lx, "develop notch: n_notch must be above 1 (and at most 1000)");
		break;
	}
}

static void st_crosslink(struct parser *p, char **t, int nt)
{
	struct bleach_input *in = p->in;
	int got = 0;
	for (int i = 1; i < nt; i += 2) {
		const char *v = i + 1 < nt ? t[i + 1] : NULL;
		if (strcasecmp(t[i], "rate") == 0) {
			in->k0 = number(p, v, "crosslink rate k0 (1/s)", 0, 1e30); got |= 1;
		} else if (strcasecmp(t[i], "energy") == 0) {
			in->ea = number(p, v, "crosslink energy Ea (eV)", 0, 100); got |= 2;
		} else if (strcasecmp(t[i], "order") == 0) {
			in->order = number(p, v, "crosslink order m", 1e-3, 100); got |= 4;
		} else if (strcasecmp(t[i], "temperature") == 0) {
			in->temp = number(p, v, "bake temperature (C)", -273.0, 2000); got |= 8;
			if (!(in->temp > -273.15 + 1e-3))
				lex_error(p->lx, "bake temperature must be above absolute zero");
		} else if (strcasecmp(t[i], "time") == 0) {
			in->time = number(p, v, "bake time (s)", 0, 1e7); got |= 16;
		} else {
			lex_error(p->lx, "crosslink: unknown word \"%.40s\" (expected rate, energy, order, temperature or time)",
				  t[i]);
		}
	}
	static const char *names[] = {"rate", "energy", "order", "temperature", "time"};
	for (int b = 0; b < 5; b++)
		if (!(got & (1 << b)))
			lex_error(p->lx, "crosslink: missing %s", names[b]);
	in->have_crosslink = 1;
}

/* Ranges of the car and peb values (bleach.5). */
#define CAR_MAX_RATE 1e6        /* 1/s */
#define CAR_MAX_DIFF 1.0        /* um2/s */
#define CAR_MAX_Q0 10.0
#define CAR_MAX_ORDER 10.0
#define CAR_MAX_TIME 1e4        /* s */
/* PAG concentration, molecules per nm^3: resists hold 0.05 to 1; the
 * bounds only keep the voxel counts finite and positive. */
#define CAR_MIN_PAG 1e-6
#define CAR_MAX_PAG 1e3

/* A rate or diffusivity of car or peb: a number, or ARRHENIUS(A Ea) (the
 * parenthesis may hold spaces: "ARRHENIUS( 1e8 0.9 )").  Consumes the
 * tokens from t[*i]; returns with *i past them. */
static void rate_value(struct parser *p, char **t, int nt, int *i, int slot,
		       double *dst, double max, const char *what)
{
	const char *v = *i < nt ? t[*i] : NULL;
	if (v && strncasecmp(v, "arrhenius(", 10) == 0) {
		/* gather the words up to the closing parenthesis */
		char buf[256];
		size_t len = 0;
		int k = *i;
		for (;;) {
			size_t l = strlen(t[k]);
			if (len + l + 2 > sizeof buf)
				lex_error(p->lx, "%s: ARRHENIUS(...) too long", what);
			memcpy(buf + len, t[k], l);
			len += l;
			buf[len++] = ' ';
			buf[len] = 0;
			if (strchr(t[k], ')'))
				break;
			if (++k >= nt)
				lex_error(p->lx, "%s: ARRHENIUS( without its closing parenthesis", what);
		}
		*i = k + 1;
		char *close = strchr(buf, ')');
		for (const char *c = close + 1; *c; c++)
			if (*c != ' ')
				lex_error(p->lx, "%s: unexpected \"%.40s\" after ARRHENIUS(...)", what, close + 1);
		*close = 0;
		char *words[3];
		int nw = 0;
		for (char *s = strtok(buf + 10, " "); s; s = strtok(NULL, " "))
			if (nw < 3)
				words[nw++] = s;
			else
				nw = 3;
		if (nw != 2)
			lex_error(p->lx, "%s: expected ARRHENIUS(A Ea), two numbers", what);
		struct arrh *a = &p->arr[slot];
		char w[96];
		snprintf(w, sizeof w, "%s prefactor A", what);
		a->A = number(p, words[0], w, 0, 1e30);
		snprintf(w, sizeof w, "%s activation energy Ea (eV)", what);
		a->ea = number(p, words[1], w, 0, 100);
		a->used = 1;
		a->dst = dst;
		a->min = 0;
		a->max = max;
		a->what = what;
		a->line = lex_lineno(p->lx);
		return;
	}
	*dst = number(p, v, what, 0, max);
	*i += 1;
}

static void st_car(struct parser *p, char **t, int nt)
{
	struct bleach_input *in = p->in;
	int got = 0;
	for (int i = 1; i < nt;) {
		const char *kw = t[i++];
		if (strcasecmp(kw, "quencher") == 0) {
			in->q0 = number(p, i < nt ? t[i] : NULL, "car quencher q0", 0, CAR_MAX_Q0);
			i++; got |= 1;
		} else if (strcasecmp(kw, "amplification") == 0) {
			rate_value(p, t, nt, &i, ARR_KAMP, &in->kamp, CAR_MAX_RATE,
				   "car amplification kamp (1/s)");
			got |= 2;
		} else if (strcasecmp(kw, "order") == 0) {
			in->porder = number(p, i < nt ? t[i] : NULL, "car order p", 1e-3, CAR_MAX_ORDER);
			i++; got |= 4;
		} else if (strcasecmp(kw, "loss") == 0) {
			rate_value(p, t, nt, &i, ARR_KLOSS, &in->kloss, CAR_MAX_RATE,
				   "car loss kloss (1/s)");
			got |= 8;
		} else if (strcasecmp(kw, "quenching") == 0) {
			rate_value(p, t, nt, &i, ARR_KQ, &in->kq, CAR_MAX_RATE,
				   "car quenching kq (1/s)");
			got |= 16;
		} else if (strcasecmp(kw, "pag") == 0) {
			if (got & 32)
				lex_error(p->lx, "car: pag given twice");
			in->pag = number(p, i < nt ? t[i] : NULL, "car pag G0 (molecules per nm^3)",
					 CAR_MIN_PAG, CAR_MAX_PAG);
			i++; got |= 32;
		} else {
			lex_error(p->lx, "car: unknown word \"%.40s\" (expected quencher, amplification, "
				  "order, loss, quenching or pag)", kw);
		}
	}
	static const char *names[] = {"quencher", "amplification", "order", "loss", "quenching"};
	for (int b = 0; b < 5; b++)
		if (!(got & (1 << b)))
			lex_error(p->lx, "car: missing %s", names[b]);
	in->line_car = lex_lineno(p->lx);
}

static void st_peb(struct parser *p, char **t, int nt)
{
	struct bleach_input *in = p->in;
	int got = 0;
	for (int i = 1; i < nt;) {
		const char *kw = t[i++];
		if (strcasecmp(kw, "time") == 0) {
			in->peb_time = number(p, i < nt ? t[i] : NULL, "peb time (s)", 0, CAR_MAX_TIME);
			i++; got |= 1;
		} else if (strcasecmp(kw, "dacid") == 0) {
			rate_value(p, t, nt, &i, ARR_DH, &in->dacid, CAR_MAX_DIFF,
				   "peb dacid Dh (um2/s)");
			got |= 2;
		} else if (strcasecmp(kw, "dquencher") == 0) {
			rate_value(p, t, nt, &i, ARR_DQ, &in->dquench, CAR_MAX_DIFF,
				   "peb dquencher Dq (um2/s)");
			got |= 4;
		} else if (strcasecmp(kw, "temperature") == 0) {
			in->peb_temp = number(p, i < nt ? t[i] : NULL, "peb temperature (C)", -273.0, 2000);
			if (!(in->peb_temp > -273.15 + 1e-3))
				lex_error(p->lx, "peb temperature must be above absolute zero");
			i++; got |= 8;
		} else {
			lex_error(p->lx, "peb: unknown word \"%.40s\" (expected time, dacid, dquencher "
				  "or temperature)", kw);
		}
	}
	static const char *names[] = {"time", "dacid", "dquencher"};
	for (int b = 0; b < 3; b++)
		if (!(got & (1 << b)))
			lex_error(p->lx, "peb: missing %s", names[b]);
	in->line_peb = lex_lineno(p->lx);
}

/* stochastic seed S [photons on|off] [acid on|off] [bake linear|full] */
static void st_stochastic(struct parser *p, char **t, int nt)
{
	struct bleach_input *in = p->in;
	int got = 0;
	in->noise_photons = in->noise_acid = 1;
	in->bake_full = 0;
	for (int i = 1; i < nt; i += 2) {
		const char *kw = t[i], *v = i + 1 < nt ? t[i + 1] : NULL;
		int bit = strcasecmp(kw, "seed") == 0 ? 1 : strcasecmp(kw, "photons") == 0 ? 2 :
			  strcasecmp(kw, "acid") == 0 ? 4 : strcasecmp(kw, "bake") == 0 ? 8 : 0;
		if (!bit)
			lex_error(p->lx, "stochastic: unknown word \"%.40s\" (expected seed, photons, "
				  "acid or bake)", kw);
		if (got & bit)
			lex_error(p->lx, "stochastic: %s given twice", kw);
		got |= bit;
		if (bit == 1) {
			in->seed = count(p, v, "stochastic seed", 0, BLEACH_MAX_SEED);
			continue;
		}
		if (bit == 8) {
			if (!v)
				lex_error(p->lx, "stochastic: bake: expected linear or full");
			in->bake_full = strcasecmp(v, "full") == 0;
			if (!in->bake_full && strcasecmp(v, "linear") != 0)
				lex_error(p->lx, "stochastic: bake: expected linear or full, found "
					  "\"%.40s\"", v);
			continue;
		}
		if (!v)
			lex_error(p->lx, "stochastic: %s: expected on or off", kw);
		int on = strcasecmp(v, "on") == 0;
		if (!on && strcasecmp(v, "off") != 0)
			lex_error(p->lx, "stochastic: %s: expected on or off, found \"%.40s\"", kw, v);
		*(bit == 2 ? &in->noise_photons : &in->noise_acid) = on;
	}
	if (!(got & 1))
		lex_error(p->lx, "stochastic: missing seed");
	if (!in->noise_photons && !in->noise_acid)
		lex_error(p->lx, "stochastic: photons and acid both off draw nothing");
	in->stochastic = 1;
	in->line_stochastic = lex_lineno(p->lx);
}

static void st_grid(struct parser *p, char **t, int nt)
{
	struct bleach_input *in = p->in;
	int got = 0;
	for (int i = 1; i < nt; i += 2) {
		const char *v = i + 1 < nt ? t[i + 1] : NULL;
		if (strcasecmp(t[i], "nx") == 0) {
			in->nx = (int)count(p, v, "grid nx", 2, BLEACH_MAX_NXY); got |= 1;
		} else if (strcasecmp(t[i], "ny") == 0) {
			in->ny = (int)count(p, v, "grid ny", 2, BLEACH_MAX_NXY); got |= 2;
		} else if (strcasecmp(t[i], "nz") == 0) {
			in->nz = (int)count(p, v, "grid nz", 2, BLEACH_MAX_NZ); got |= 4;
		} else {
			lex_error(p->lx, "grid: unknown word \"%.40s\" (expected nx, ny or nz)", t[i]);
		}
	}
	if ((got & 3) == 1 || (got & 3) == 2)
		lex_error(p->lx, "grid: give both nx and ny, or neither");
	if (got == 0)
		lex_error(p->lx, "grid: expected nx, ny and/or nz");
	if (got & 4)
		in->line_nz = lex_lineno(p->lx);
}

static void statement(struct parser *p, char **t, int nt)
{
	struct bleach_input *in = p->in;
	const char *kw = t[0];
	if (strcasecmp(kw, "wavelength") == 0) {
		once(p, S_WAVE, "wavelength");
		nargs(p, t, nt, 1, 1, kw);
		in->wavelength = number(p, t[1], "wavelength (um)", 1e-3, 100);
	} else if (strcasecmp(kw, "ambient") == 0) {
		once(p, S_AMB, "ambient");
		nargs(p, t, nt, 1, 1, kw);
		in->ambient = number(p, t[1], "ambient index", 1e-3, BIG_INDEX);
	} else if (strcasecmp(kw, "resist") == 0) {
		once(p, S_RESIST, "resist");
		st_resist(p, t, nt);
	} else if (strcasecmp(kw, "layer") == 0) {
		nargs(p, t, nt, 3, 3, kw);
		if (in->nlayers >= BLEACH_MAX_LAYERS)
			lex_error(p->lx, "more than %d layers", BLEACH_MAX_LAYERS);
		struct bleach_layer *l = &in->layers[in->nlayers++];
		l->thick = number(p, t[1], "layer thickness (um)", 0, BIG_LEN);
		l->n = number(p, t[2], "layer index n", 1e-3, BIG_INDEX);
		l->k = number(p, t[3], "layer extinction k", 0, BIG_INDEX);
	} else if (strcasecmp(kw, "substrate") == 0) {
		once(p, S_SUB, "substrate");
		nargs(p, t, nt, 2, 2, kw);
		in->sub_n = number(p, t[1], "substrate index n", 1e-3, BIG_INDEX);
		in->sub_k = number(p, t[2], "substrate extinction k", 0, BIG_INDEX);
	} else if (strcasecmp(kw, "dose") == 0) {
		once(p, S_DOSE, "dose");
		nargs(p, t, nt, 1, 1, kw);
		in->dose = number(p, t[1], "dose (mJ/cm2)", 0, BIG_DOSE);
		if (in->dose == 0)      /* nothing exposed: no pattern to develop */
			lex_error(p->lx, "dose 0: nothing is exposed; give a dose in mJ/cm2 above 0");
		in->line_dose = lex_lineno(p->lx);
	} else if (strcasecmp(kw, "bake") == 0 || strcasecmp(kw, "bake3d") == 0) {
		once(p, S_BAKE, "bake");
		if (nt != 3 || strcasecmp(t[1], "diffusion") != 0)
			lex_error(p->lx, "%s: expected \"diffusion LENGTH\"", kw);
		in->diffusion = number(p, t[2], "bake diffusion length (um)", 0, BIG_LEN);
		in->bake = strcasecmp(kw, "bake3d") == 0 ? BAKE_3D : BAKE_Z;
	} else if (strcasecmp(kw, "develop") == 0) {
		once(p, S_DEV, "develop");
		st_develop(p, t, nt);
	} else if (strcasecmp(kw, "crosslink") == 0) {
		once(p, S_XLINK, "crosslink");
		st_crosslink(p, t, nt);
	} else if (strcasecmp(kw, "car") == 0) {
		once(p, S_CAR, "car");
		st_car(p, t, nt);
	} else if (strcasecmp(kw, "peb") == 0) {
		once(p, S_PEB, "peb");
		st_peb(p, t, nt);
	} else if (strcasecmp(kw, "stochastic") == 0) {
		once(p, S_STOCH, "stochastic");
		st_stochastic(p, t, nt);
	} else if (strcasecmp(kw, "grid") == 0) {
		once(p, S_GRID, "grid");
		st_grid(p, t, nt);
	} else if (strcasecmp(kw, "standingwaves") == 0) {
		once(p, S_SW, "standingwaves");
		nargs(p, t, nt, 1, 1, kw);
		if (strcasecmp(t[1], "on") == 0)
			in->standing = 1;
		else if (strcasecmp(t[1], "off") == 0)
			in->standing = 0;
		else
			lex_error(p->lx, "standingwaves: expected on or off, found \"%.40s\"", t[1]);
	} else {
		lex_error(p->lx, "unknown statement \"%.40s\"", kw);
	}
}

static void parse(struct lex *lx, struct bleach_input *in)
{
	struct parser p;
	memset(&p, 0, sizeof p);
	memset(in, 0, sizeof *in);
	p.lx = lx;
	p.in = in;
	in->ambient = 1.0;
	in->standing = 1;
	in->bake = BAKE_NONE;
	in->peb_temp = NAN;
	char **t;
	int nt;
	long last = 0;
	while ((nt = lex_line(lx, &t, NULL)) > 0) {
		last = lex_lineno(lx);
		statement(&p, t, nt);
	}
	/* Missing statements are reported at the last line read, the place
	 * where the reader expected them at the latest. */
	static const struct { int s; const char *what; } need[] = {
		{S_WAVE, "wavelength"}, {S_RESIST, "resist"},
		{S_SUB, "substrate"}, {S_DOSE, "dose"}, {S_DEV, "develop"},
	};
	for (size_t i = 0; i < sizeof need / sizeof need[0]; i++)
		if (!p.seen[need[i].s])
			die("%s:%ld: no %s statement", lex_name(lx), last, need[i].what);
	if (in->model == BLEACH_CANEG && !in->have_crosslink)
		die("%s:%ld: develop canegative needs a crosslink statement",
		    lex_name(lx), p.seen[S_DEV]);
	if (in->model != BLEACH_CANEG && in->have_crosslink)
		die("%s:%ld: crosslink is only for develop canegative",
		    lex_name(lx), p.seen[S_XLINK]);
	if (p.seen[S_CAR] && !p.seen[S_PEB])
		die("%s:%ld: car needs a peb statement (the post-exposure bake)",
		    lex_name(lx), p.seen[S_CAR]);
	if (p.seen[S_PEB] && !p.seen[S_CAR])
		die("%s:%ld: peb needs a car statement (the resist's reaction constants)",
		    lex_name(lx), p.seen[S_PEB]);
	if (p.seen[S_STOCH] && !(p.seen[S_CAR] && in->pag > 0))
		die("%s:%ld: stochastic needs the PAG concentration: a car statement with pag G0",
		    lex_name(lx), p.seen[S_STOCH]);
	if (p.seen[S_CAR]) {
		in->have_car = 1;
		if (p.seen[S_BAKE])
			die("%s:%ld: bake is not for a car resist (its bake is the peb statement)",
			    lex_name(lx), p.seen[S_BAKE]);
		if (p.seen[S_XLINK])
			die("%s:%ld: crosslink is not for a car resist",
			    lex_name(lx), p.seen[S_XLINK]);
		for (int k = 0; k < ARR_COUNT; k++) {
			struct arrh *a = &p.arr[k];
			if (!a->used)
				continue;
			if (isnan(in->peb_temp))
				die("%s:%ld: %s: ARRHENIUS needs the peb temperature", lex_name(lx),
				    a->line, a->what);
			double v = a->A * exp(-a->ea / (BLEACH_KB_EV * (in->peb_temp + 273.15)));
			if (!(v >= a->min && v <= a->max))
				die("%s:%ld: %s: ARRHENIUS gives %g at %g C, out of range [%g, %g]",
				    lex_name(lx), a->line, a->what, v, in->peb_temp, a->min, a->max);
			*a->dst = v;
		}
		double L = sqrt(2 * (in->dacid > in->dquench ? in->dacid : in->dquench) * in->peb_time);
		if (L > 10 * in->thick)
			die("%s:%ld: peb diffusion length sqrt(2 D t) = %g um is above ten resist "
			    "thicknesses", lex_name(lx), p.seen[S_PEB], L);
	}
	if (in->diffusion > 10 * in->thick && in->bake != BAKE_NONE)
		die("%s:%ld: bake diffusion length %g um is above ten resist thicknesses "
		    "(lengths are in micrometres: %g nm is %g)", lex_name(lx), p.seen[S_BAKE],
		    in->diffusion, in->diffusion, in->diffusion / 1000);
	if (in->nz == 0)
		in->nz = fmt_bleach_default_nz(in);
	/* the standing waves must be sampled (two points a period at least):
	 * a 700 um resist on 300 points is most likely 700 nm */
	double period = in->wavelength / (2 * in->index);
	double dz = in->thick / (in->nz - 1);
	if (in->standing && dz > period / 2)
		die("%s:%ld: resist thickness %g um on %d points is %g um a point, more than "
		    "half the standing-wave period %g um%s", lex_name(lx),
		    in->line_nz && in->line_nz > p.seen[S_RESIST] ? in->line_nz : p.seen[S_RESIST],
		    in->thick, in->nz, dz, period,
		    in->thick > 20 ? ": nanometres? (or more points with grid nz)" :
		    " (more points with grid nz)");
}

int fmt_bleach_default_nz(const struct bleach_input *in)
{
	double period = in->wavelength / (2 * in->index);
	double nz = ceil(40 * in->thick / period) + 1;
	if (nz < 50)
		nz = 50;
	if (nz > BLEACH_MAX_NZ)
		nz = BLEACH_MAX_NZ;
	return (int)nz;
}

void fmt_bleach_read(const char *path, struct bleach_input *in)
{
	struct lex *lx = lex_open(path);
	lex_expect(lx, "bleach(5)");
	parse(lx, in);
	lex_close(lx);
}

void fmt_bleach_parse(const char *name, const char *text, struct bleach_input *in)
{
	struct lex *lx = lex_from_memory(name, text, strlen(text));
	parse(lx, in);
	lex_close(lx);
}

static void kv(FILE *f, const char *key, double v)
{
	fprintf(f, " %s ", key);
	num_print(f, v);
}

void fmt_bleach_write(const char *path, const struct bleach_input *in)
{
	struct aout *a = aout_open(path);
	FILE *f = a->f;
	fputs("wavelength ", f);
	num_print(f, in->wavelength);
	if (in->ambient != 1.0) {
		fputs("\nambient ", f);
		num_print(f, in->ambient);
	}
	fputs("\nresist", f);
	kv(f, "thickness", in->thick);
	kv(f, "index", in->index);
	double abc[3] = {in->A, in->B, in->C};
	fputs(" dill ", f);
	num_print_row(f, abc, 3);
	for (int i = 0; i < in->nlayers; i++) {
		double l[3] = {in->layers[i].thick, in->layers[i].n, in->layers[i].k};
		fputs("layer ", f);
		num_print_row(f, l, 3);
	}
	double s[2] = {in->sub_n, in->sub_k};
	fputs("substrate ", f);
	num_print_row(f, s, 2);
	fputs("dose ", f);
	num_print(f, in->dose);
	fputc('\n', f);
	if (!in->standing)
		fputs("standingwaves off\n", f);
	if (in->bake != BAKE_NONE) {
		fputs(in->bake == BAKE_3D ? "bake3d diffusion " : "bake diffusion ", f);
		num_print(f, in->diffusion);
		fputc('\n', f);
	}
	static const char *mname[] = {"kim", "mack", "dill", "canegative", "enhanced", "notch"};
	fprintf(f, "develop %s ", mname[in->model]);
	num_print_row(f, in->par, in->npar);
	if (in->have_crosslink) {
		fputs("crosslink", f);
		kv(f, "rate", in->k0);
		kv(f, "energy", in->ea);
		kv(f, "order", in->order);
		kv(f, "temperature", in->temp);
		kv(f, "time", in->time);
		fputc('\n', f);
	}
	if (in->have_car) {
		/* rates as evaluated (an ARRHENIUS value is written as its number) */
		fputs("car", f);
		kv(f, "quencher", in->q0);
		kv(f, "amplification", in->kamp);
		kv(f, "order", in->porder);
		kv(f, "loss", in->kloss);
		kv(f, "quenching", in->kq);
		if (in->pag > 0)
			kv(f, "pag", in->pag);
		fputs("\npeb", f);
		kv(f, "time", in->peb_time);
		kv(f, "dacid", in->dacid);
		kv(f, "dquencher", in->dquench);
		if (!isnan(in->peb_temp))
			kv(f, "temperature", in->peb_temp);
		fputc('\n', f);
	}
	if (in->stochastic)
		fprintf(f, "stochastic seed %ld photons %s acid %s%s\n", in->seed,
			in->noise_photons ? "on" : "off", in->noise_acid ? "on" : "off",
			in->bake_full ? " bake full" : "");
	if (in->nx > 0)
		fprintf(f, "grid nx %d ny %d nz %d\n", in->nx, in->ny, in->nz);
	else
		fprintf(f, "grid nz %d\n", in->nz);
	aout_commit(a);
}

/* Numbered statements (calib).  A line is split at blanks and commas and
 * ends at '#', as lex_line splits it; a token is a number when num_parse
 * takes all of it.  The statement must be on one line only, since
 * "the K-th number of layer" would otherwise not say which layer. */
static int is_blank(char c)
{
	return c == ' ' || c == '\t' || c == '\r' || c == ',' || c == '\f' || c == '\v';
}

double fmt_bleach_number(const char *name, const char *text, const char *stmt, int k,
			 size_t *off, size_t *len, long *line)
{
	long found = 0, lineno = 0;
	double value = 0;
	for (const char *s = text; *s; ) {
		const char *eol = strchr(s, '\n');
		if (!eol)
			eol = s + strlen(s);
		const char *hash = memchr(s, '#', (size_t)(eol - s));
		const char *end = hash ? hash : eol;
		lineno++;
		int tok = 0, nnum = 0;
		for (const char *t = s; t < end; ) {
			while (t < end && is_blank(*t))
				t++;
			if (t == end)
				break;
			const char *te = t;
			while (te < end && !is_blank(*te))
				te++;
			size_t tl = (size_t)(te - t);
			if (tok == 0 && (tl != strlen(stmt) || strncasecmp(t, stmt, tl) != 0))
				break;
			if (tok == 0 && found)
				die("%s:%ld: %s is also on line %ld: which one to change is not clear",
				    name, lineno, stmt, found);
			if (tok == 0)
				found = lineno;
			char buf[64];
			double v;
			if (tok > 0 && tl < sizeof buf) {
				memcpy(buf, t, tl);
				buf[tl] = '\0';
				if (num_parse(buf, &v) && ++nnum == k) {
					value = v;
					*off = (size_t)(t - text);
					*len = tl;
				}
			}
			tok++;
			t = te;
		}
		if (found == lineno && nnum < k)
			die("%s:%ld: %s has %d number%s, not %d", name, lineno, stmt, nnum,
			    nnum == 1 ? "" : "s", k);
		s = *eol ? eol + 1 : eol;
	}
	if (!found)
		die("%s: no %s statement", name, stmt);
	*line = found;
	return value;
}

char *fmt_bleach_set_number(const char *name, const char *text, const char *stmt, int k,
			    double v)
{
	size_t off, len;
	long line;
	fmt_bleach_number(name, text, stmt, k, &off, &len, &line);
	char num[NUM_BUFSZ];
	num_fmt(num, v);
	size_t n = strlen(text), nl = strlen(num);
	char *out = xmalloc(n - len + nl + 1);
	memcpy(out, text, off);
	memcpy(out + off, num, nl);
	memcpy(out + off + nl, text + off + len, n - off - len + 1);
	return out;
}

void fmt_bleach_film(const struct bleach_input *in, struct filmstack *fs,
		     struct film_layer *layers)
{
	for (int l = 0; l < in->nlayers; l++) {
		layers[l].thick = in->layers[l].thick;
		layers[l].n = in->layers[l].n;
		layers[l].k = in->layers[l].k;
	}
	fs->lambda = in->wavelength;
	fs->n0 = in->ambient;
	fs->nr = in->index;
	/* the unexposed resist (M = 1): alpha = A + B, k = alpha lambda / (4 pi) */
	fs->kr = (in->A + in->B) * in->wavelength / (4 * M_PI);
	fs->thick = in->thick;
	fs->nlayers = in->nlayers;
	fs->layers = layers;
	fs->sub_n = in->sub_n;
	fs->sub_k = in->sub_k;
}
