/*
 * fmt_template.c - drawplot's template-file (see fmt_template.h).  The
 * guide writes "ln_type = 1"; "=" may also be glued to the words or left
 * out, so each unquoted token is split at '=' first.
 */
#include "fmt_template.h"
#include "draw.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

enum { T_LN, T_MKR, T_LABEL, T_NONE };

static int keyword(const char *w)
{
	static const char *ln[] = {"ln_type", "linetype", "line_type"};
	static const char *mk[] = {"mkr_type", "markertype", "marker_type"};
	static const char *lb[] = {"label", "linelabel", "line_label"};
	for (int i = 0; i < 3; i++) {
		if (strcasecmp(w, ln[i]) == 0) return T_LN;
		if (strcasecmp(w, mk[i]) == 0) return T_MKR;
		if (strcasecmp(w, lb[i]) == 0) return T_LABEL;
	}
	return T_NONE;
}

struct piece { char *s; int quoted; };

static int type_value(struct lex *lx, const char *s, int kind)
{
	long v;
	int max = kind == T_LN ? DRAW_NLINETYPES - 1 : DRAW_NMARKERS - 1;
	if (!num_parse_count(s, 0, max, &v))
		lex_error(lx, "%s: expected a whole number from 0 to %d, found \"%.40s\"",
			  kind == T_LN ? "ln_type" : "mkr_type", max, s);
	return (int)v;
}

struct template *fmt_template_read(const char *path)
{
	struct lex *lx = lex_open(path);
	struct template *t = xcalloc(1, sizeof *t);
	size_t cap = 0;
	char **tok;
	const int *quoted;
	int n;
	while ((n = lex_line(lx, &tok, &quoted)) > 0) {
		/* split unquoted tokens at '=' */
		struct piece *p = xreallocarray(NULL, (size_t)n * 2 + 2, sizeof *p);
		size_t np = 0, pcap = (size_t)n * 2 + 2;
		char *buf = NULL;
		size_t blen = 0;
		for (int i = 0; i < n; i++)
			blen += strlen(tok[i]) + 1;
		buf = xmalloc(blen + 1);
		char *w = buf;
		for (int i = 0; i < n; i++) {
			if (quoted[i]) {
				strcpy(w, tok[i]);
				xgrow(&p, &pcap, np + 1, sizeof *p);
				p[np++] = (struct piece){w, 1};
				w += strlen(w) + 1;
				continue;
			}
			const char *s = tok[i];
			while (*s) {
				const char *e = strchr(s, '=');
				size_t m = e ? (size_t)(e - s) : strlen(s);
				if (m > 0) {
					memcpy(w, s, m);
					w[m] = '\0';
					xgrow(&p, &pcap, np + 1, sizeof *p);
					p[np++] = (struct piece){w, 0};
					w += m + 1;
				}
				s += m + (e ? 1 : 0);
			}
		}
		struct template_entry en = {1, 0, NULL, lex_lineno(lx)};
		int positional = 0;
		for (size_t i = 0; i < np; i++) {
			int k = p[i].quoted ? T_NONE : keyword(p[i].s);
			if (k == T_NONE) {
				if (p[i].quoted || positional >= 2) {
					free(en.label);
					lex_error(lx, "unexpected \"%.40s\" (expected ln_type, "
						  "mkr_type or label)", p[i].s);
				}
				if (positional == 0)
					en.ln_type = type_value(lx, p[i].s, T_LN);
				else
					en.mkr_type = type_value(lx, p[i].s, T_MKR);
				positional++;
				continue;
			}
			if (i + 1 >= np) {
				free(en.label);
				lex_error(lx, "%s: missing value", p[i].s);
			}
			i++;
			if (k == T_LABEL) {
				free(en.label);
				en.label = xstrdup(p[i].s);
			} else if (k == T_LN) {
				en.ln_type = type_value(lx, p[i].s, T_LN);
				positional = 2;
			} else {
				en.mkr_type = type_value(lx, p[i].s, T_MKR);
				positional = 2;
			}
		}
		free(p);
		free(buf);
		size_t c = cap;
		xgrow(&t->e, &c, (size_t)t->n + 1, sizeof *t->e);
		cap = c;
		t->e[t->n++] = en;
	}
	if (t->n == 0) {
		lex_close(lx);
		fmt_template_free(t);
		die("%s:1: empty template-file (expected ln_type = N mkr_type = N)", path);
	}
	lex_close(lx);
	return t;
}

void fmt_template_write(const char *path, const struct template *t)
{
	struct aout *a = aout_open(path);
	for (int i = 0; i < t->n; i++) {
		fprintf(a->f, "ln_type = %d mkr_type = %d", t->e[i].ln_type, t->e[i].mkr_type);
		if (t->e[i].label) {
			fputs(" label = \"", a->f);
			for (const char *s = t->e[i].label; *s; s++)
				fputc(*s == '"' ? '\'' : *s, a->f);
			fputc('"', a->f);
		}
		fputc('\n', a->f);
	}
	aout_commit(a);
}

void fmt_template_free(struct template *t)
{
	if (!t)
		return;
	for (int i = 0; i < t->n; i++)
		free(t->e[i].label);
	free(t->e);
	free(t);
}
