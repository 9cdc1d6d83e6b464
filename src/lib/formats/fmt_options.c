/* fmt_options.c - see fmt_options.h. */
#include "fmt_options.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

int fmt_options_find(const struct opt_spec *spec, const char *key)
{
	for (int i = 0; spec[i].key; i++)
		if (strcasecmp(spec[i].key, key) == 0)
			return i;
	return -1;
}

static char *lower_dup(const char *s)
{
	char *p = xstrdup(s);
	for (char *q = p; *q; q++)
		*q = (char)tolower((unsigned char)*q);
	return p;
}

static int word_in(const char *w, const char *words)
{
	size_t n = strlen(w);
	const char *p = words;
	while (*p) {
		const char *e = strchr(p, '|');
		size_t m = e ? (size_t)(e - p) : strlen(p);
		if (m == n && strncasecmp(p, w, n) == 0)
			return 1;
		if (!e)
			break;
		p = e + 1;
	}
	return 0;
}

static int parse_onoff(const char *s, double *v)
{
	static const char *on[] = {"on", "yes", "true", "1"};
	static const char *off[] = {"off", "no", "false", "0"};
	for (int i = 0; i < 4; i++) {
		if (strcasecmp(s, on[i]) == 0) { *v = 1; return 1; }
		if (strcasecmp(s, off[i]) == 0) { *v = 0; return 1; }
	}
	return 0;
}

void fmt_options_read(const char *path, const struct opt_spec *spec,
		      struct opt_value *val)
{
	struct lex *lx = lex_open(path);
	char **tok;
	const int *quoted;
	int n;
	while ((n = lex_line(lx, &tok, &quoted)) > 0) {
		int i = fmt_options_find(spec, tok[0]);
		if (i < 0 || quoted[0])
			lex_error(lx, "unknown keyword \"%.40s\"", tok[0]);
		const struct opt_spec *s = &spec[i];
		if (n < 2)
			lex_error(lx, "%s: missing value", s->key);
		if (n > 2)
			lex_error(lx, "%s: one value expected, found %d "
				  "(quote a string with spaces)", s->key, n - 1);
		const char *v = tok[1];
		struct opt_value *o = &val[i];
		double x;
		switch (s->type) {
		case OPT_ONOFF:
			if (!parse_onoff(v, &x))
				lex_error(lx, "%s: expected on or off, found \"%.40s\"", s->key, v);
			o->num = x;
			break;
		case OPT_NUM:
		case OPT_INT:
			if (!num_parse(v, &x))
				lex_error(lx, "%s: expected a number, found \"%.40s\"", s->key, v);
			/* the range first: casting 1e30 to long is undefined */
			if (x < s->min || x > s->max)
				lex_error(lx, "%s: %.40s is out of range [%g, %g]",
					  s->key, v, s->min, s->max);
			if (s->type == OPT_INT && x != floor(x))
				lex_error(lx, "%s: expected a whole number, found \"%.40s\"", s->key, v);
			o->num = x;
			break;
		case OPT_STRING:
			free(o->str);
			o->str = xstrdup(v);
			break;
		case OPT_WORD:
			if (!word_in(v, s->words))
				lex_error(lx, "%s: expected one of %s, found \"%.40s\"",
					  s->key, s->words, v);
			free(o->str);
			o->str = lower_dup(v);
			break;
		}
		o->set = 1;
		o->line = lex_lineno(lx);
	}
	lex_close(lx);
}

void fmt_options_write(const char *path, const struct opt_spec *spec,
		       const struct opt_value *val)
{
	struct aout *a = aout_open(path);
	for (int i = 0; spec[i].key; i++) {
		if (!val[i].set)
			continue;
		fprintf(a->f, "%s ", spec[i].key);
		switch (spec[i].type) {
		case OPT_ONOFF:
			fputs(val[i].num != 0 ? "on" : "off", a->f);
			break;
		case OPT_NUM:
		case OPT_INT:
			num_print(a->f, val[i].num);
			break;
		case OPT_STRING:
			fprintf(a->f, "\"%s\"", val[i].str);
			break;
		case OPT_WORD:
			fputs(val[i].str, a->f);
			break;
		}
		fputc('\n', a->f);
	}
	aout_commit(a);
}

void fmt_options_free(const struct opt_spec *spec, struct opt_value *val)
{
	for (int i = 0; spec[i].key; i++) {
		free(val[i].str);
		val[i].str = NULL;
	}
}
