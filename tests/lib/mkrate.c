/*
 * mkrate - test tool: writes a rate file (fmt_rate) sampled from an
 * analytic expression, so that etch and the fast-marching engine can be
 * checked against exact answers (thesis chapter 6-8's analytic fields).
 *
 *   mkrate [-ascii] [-M expr] -o FILE nx ny nz xmin xmax ymin ymax zmin zmax EXPR
 *
 * ny = 1 writes a 2D x-z array (etch2d's input; y = ymin throughout).
 * EXPR is in x, y, z (micrometres): + - * / ^, unary minus, parentheses,
 * exp log sqrt abs sin cos tan atan floor min(a,b) max(a,b), pi.  It is
 * compiled once into a small stack program and evaluated at every point.
 */
#include "args.h"
#include "fmt_rate.h"
#include "num.h"
#include "util.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum op { PUSH, VX, VY, VZ, ADD, SUB, MUL, DIV, POW, NEG, FN1, MIN, MAX };
struct ins { enum op op; double v; double (*fn)(double); };
struct prog { struct ins *ins; size_t n, cap; };

struct parser { const char *s, *p; struct prog *prog; };

static void emit(struct parser *ps, enum op op, double v, double (*fn)(double))
{
	xgrow(&ps->prog->ins, &ps->prog->cap, ps->prog->n + 1, sizeof *ps->prog->ins);
	ps->prog->ins[ps->prog->n++] = (struct ins){op, v, fn};
}

static _Noreturn void perr(struct parser *ps, const char *what)
{
	die("expression:1: %s at offset %d of \"%s\"", what, (int)(ps->p - ps->s), ps->s);
}

static void skipws(struct parser *ps) { while (isspace((unsigned char)*ps->p)) ps->p++; }

static void expr(struct parser *ps);

static void primary(struct parser *ps)
{
	skipws(ps);
	if (*ps->p == '(') {
		ps->p++;
		expr(ps);
		skipws(ps);
		if (*ps->p != ')')
			perr(ps, "expected ')'");
		ps->p++;
	} else if (isdigit((unsigned char)*ps->p) || *ps->p == '.') {
		char *end;
		double v = strtod(ps->p, &end);
		if (end == ps->p)
			perr(ps, "bad number");
		ps->p = end;
		emit(ps, PUSH, v, NULL);
	} else if (isalpha((unsigned char)*ps->p)) {
		char name[16];
		size_t n = 0;
		while (isalnum((unsigned char)*ps->p) && n < sizeof name - 1)
			name[n++] = *ps->p++;
		name[n] = '\0';
		static const struct { const char *name; double (*fn)(double); } fns[] = {
			{"exp", exp}, {"log", log}, {"sqrt", sqrt}, {"abs", fabs}, {"sin", sin},
			{"cos", cos}, {"tan", tan}, {"atan", atan}, {"floor", floor},
		};
		if (!strcmp(name, "x")) { emit(ps, VX, 0, NULL); return; }
		if (!strcmp(name, "y")) { emit(ps, VY, 0, NULL); return; }
		if (!strcmp(name, "z")) { emit(ps, VZ, 0, NULL); return; }
		if (!strcmp(name, "pi")) { emit(ps, PUSH, M_PI, NULL); return; }
		int two = !strcmp(name, "min") || !strcmp(name, "max");
		double (*fn)(double) = NULL;
		for (size_t i = 0; i < sizeof fns / sizeof fns[0]; i++)
			if (!strcmp(name, fns[i].name))
				fn = fns[i].fn;
		if (!fn && !two)
			perr(ps, "unknown name");
		skipws(ps);
		if (*ps->p != '(')
			perr(ps, "expected '(' after a function name");
		ps->p++;
		expr(ps);
		if (two) {
			skipws(ps);
			if (*ps->p != ',')
				perr(ps, "expected ','");
			ps->p++;
			expr(ps);
		}
		skipws(ps);
		if (*ps->p != ')')
			perr(ps, "expected ')'");
		ps->p++;
		if (two)
			emit(ps, name[1] == 'i' ? MIN : MAX, 0, NULL);
		else
			emit(ps, FN1, 0, fn);
	} else {
		perr(ps, "unexpected character");
	}
}

static void unary(struct parser *ps);

/* primary ['^' unary]: right associative, binds tighter than unary minus
 * on its left, so -x^2 is -(x^2) */
static void power(struct parser *ps)
{
	primary(ps);
	skipws(ps);
	if (*ps->p == '^') {
		ps->p++;
		unary(ps);
		emit(ps, POW, 0, NULL);
	}
}

static void unary(struct parser *ps)
{
	skipws(ps);
	if (*ps->p == '-') {
		ps->p++;
		unary(ps);
		emit(ps, NEG, 0, NULL);
	} else if (*ps->p == '+') {
		ps->p++;
		unary(ps);
	} else {
		power(ps);
	}
}

static void term(struct parser *ps)
{
	unary(ps);
	for (;;) {
		skipws(ps);
		char c = *ps->p;
		if (c != '*' && c != '/')
			return;
		ps->p++;
		unary(ps);
		emit(ps, c == '*' ? MUL : DIV, 0, NULL);
	}
}

static void expr(struct parser *ps)
{
	term(ps);
	for (;;) {
		skipws(ps);
		char c = *ps->p;
		if (c != '+' && c != '-')
			return;
		ps->p++;
		term(ps);
		emit(ps, c == '+' ? ADD : SUB, 0, NULL);
	}
}

static void compile(const char *s, struct prog *prog)
{
	struct parser ps = {s, s, prog};
	expr(&ps);
	skipws(&ps);
	if (*ps.p)
		perr(&ps, "unexpected text");
}

static double eval(const struct prog *prog, double x, double y, double z)
{
	double st[64];
	int sp = 0;
	for (size_t i = 0; i < prog->n; i++) {
		const struct ins *in = &prog->ins[i];
		if (sp > 60)
			die("expression too deeply nested");
		switch (in->op) {
		case PUSH: st[sp++] = in->v; break;
		case VX: st[sp++] = x; break;
		case VY: st[sp++] = y; break;
		case VZ: st[sp++] = z; break;
		case ADD: sp--; st[sp - 1] += st[sp]; break;
		case SUB: sp--; st[sp - 1] -= st[sp]; break;
		case MUL: sp--; st[sp - 1] *= st[sp]; break;
		case DIV: sp--; st[sp - 1] /= st[sp]; break;
		case POW: sp--; st[sp - 1] = pow(st[sp - 1], st[sp]); break;
		case MIN: sp--; st[sp - 1] = fmin(st[sp - 1], st[sp]); break;
		case MAX: sp--; st[sp - 1] = fmax(st[sp - 1], st[sp]); break;
		case NEG: st[sp - 1] = -st[sp - 1]; break;
		case FN1: st[sp - 1] = in->fn(st[sp - 1]); break;
		}
	}
	return st[0];
}

static void fill(const char *what, const struct prog *prog, struct ratefile *r, double *v)
{
	for (int k = 0; k < r->nz; k++)
		for (int j = 0; j < r->ny; j++)
			for (int i = 0; i < r->nx; i++) {
				double f = eval(prog, fmt_rate_x(r, i), fmt_rate_y(r, j), fmt_rate_z(r, k));
				if (!isfinite(f))
					die("%s is not finite at (%g, %g, %g)", what,
					    fmt_rate_x(r, i), fmt_rate_y(r, j), fmt_rate_z(r, k));
				v[fmt_rate_index(r, i, j, k)] = f;
			}
}

static const char usage[] =
	"usage: mkrate [-ascii] [-M expr] -o FILE nx ny nz xmin xmax ymin ymax zmin zmax EXPR\n";

int main(int argc, char **argv)
{
	struct args a;
	args_init(&a, argc, argv);
	int ascii = 0;
	const char *out = NULL, *mexpr = NULL, *pos[10];
	int npos = 0;
	while (a.i < argc) {
		const char *s = argv[a.i];
		if (args_help(&a)) {
			fputs(usage, stdout);
			return 0;
		} else if (args_flag(&a, "-ascii"))
			ascii = 1;
		else if (args_str(&a, "-o", &out) || args_str(&a, "-M", &mexpr))
			;
		else if (s[0] == '-' && isalpha((unsigned char)s[1]) && npos != 9)
			args_unknown(&a);
		else if (npos < 10)
			pos[npos++] = argv[a.i++];
		else
			args_error(&a, "too many arguments"), a.i++;
	}
	if (!out)
		args_error(&a, "no -o FILE");
	if (npos != 10)
		args_error(&a, "expected nx ny nz, six bounds and an expression");
	args_done(&a, usage);
	long n[3];
	double b[6];
	for (int d = 0; d < 3; d++)
		if (!num_parse_count(pos[d], d == 1 ? 1 : 2, RATE_MAX_N, &n[d])) /* ny = 1: 2D */
			die("bad grid size \"%s\"", pos[d]);
	for (int d = 0; d < 6; d++)
		if (!num_parse(pos[3 + d], &b[d]))
			die("bad bound \"%s\"", pos[3 + d]);
	struct prog rp = {0}, mp = {0};
	compile(pos[9], &rp);
	struct ratefile *r = fmt_rate_new((int)n[0], (int)n[1], (int)n[2], b);
	fill("rate", &rp, r, fmt_rate_values(r));
	if (mexpr) {
		compile(mexpr, &mp);
		fill("M", &mp, r, fmt_rate_add_array(r, "M"));
	}
	fmt_rate_write(out, r, ascii);
	fmt_rate_free(r);
	free(rp.ins);
	free(mp.ins);
	return 0;
}
