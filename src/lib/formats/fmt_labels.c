/* fmt_labels.c - see fmt_labels.h. */
#include "fmt_labels.h"
#include "lex.h"
#include "util.h"

#include <string.h>

static const char *keys[4] = {"title", "x", "y", "z"};

static char *slot(struct plot_labels *l, int k)
{
	return k == 0 ? l->title : l->axis[k - 1];
}

static const char *cslot(const struct plot_labels *l, int k)
{
	return k == 0 ? l->title : l->axis[k - 1];
}

static void skip_blank(const char **p)
{
	while (**p == ' ' || **p == '\t' || **p == '\r' || **p == '\f' || **p == '\v')
		(*p)++;
}

/* The word at *p (up to a blank), copied into w (cap bytes). */
static void word(const char **p, char *w, size_t cap)
{
	size_t n = 0;
	while (**p && **p != ' ' && **p != '\t' && **p != '\r' && **p != '\f' &&
	       **p != '\v') {
		if (n + 1 < cap)
			w[n++] = **p;
		(*p)++;
	}
	w[n] = '\0';
}

static void parse(struct lex *lx, const char *p, struct plot_labels *l, int nz)
{
	char w[16];
	skip_blank(&p);
	word(&p, w, sizeof w);
	if (strcmp(w, "labels") != 0)
		return;         /* a free comment */
	for (;;) {
		skip_blank(&p);
		if (!*p)
			return;
		word(&p, w, sizeof w);
		int k = 0;
		while (k < 4 && strcmp(w, keys[k]) != 0)
			k++;
		if (k == 4 || (k == 3 && !nz))
			lex_error(lx, "labels: unknown key \"%.12s\" (expected title, x, y%s)",
				  w, nz ? " or z" : "");
		skip_blank(&p);
		if (*p != '"')
			lex_error(lx, "labels: %s: expected a quoted text", keys[k]);
		const char *e = strchr(++p, '"');
		if (!e)
			lex_error(lx, "labels: %s: unterminated quoted text", keys[k]);
		size_t n = (size_t)(e - p);
		if (n >= LABEL_MAX)
			lex_error(lx, "labels: %s: longer than %d characters", keys[k],
				  LABEL_MAX - 1);
		for (size_t i = 0; i < n; i++)
			if ((unsigned char)p[i] < 32 || p[i] == 127)
				lex_error(lx, "labels: %s: a control character in the text",
					  keys[k]);
		memcpy(slot(l, k), p, n);
		slot(l, k)[n] = '\0';
		p = e + 1;
	}
}

void fmt_labels_read(struct lex *lx, struct plot_labels *l, int nz)
{
	memset(l, 0, sizeof *l);
	const char *c;
	while ((c = lex_comment(lx)))
		parse(lx, c, l, nz);
}

int fmt_labels_empty(const struct plot_labels *l)
{
	for (int k = 0; k < 4; k++)
		if (cslot(l, k)[0])
			return 0;
	return 1;
}

void fmt_labels_put(FILE *f, const struct plot_labels *l)
{
	if (fmt_labels_empty(l))
		return;
	fputs("# labels", f);
	for (int k = 0; k < 4; k++)
		if (cslot(l, k)[0])
			fprintf(f, " %s \"%s\"", keys[k], cslot(l, k));
	fputc('\n', f);
}

void fmt_labels_set(struct plot_labels *l, const char *title, const char *x,
		    const char *y, const char *z)
{
	const char *t[4] = {title, x, y, z};
	memset(l, 0, sizeof *l);
	for (int k = 0; k < 4; k++) {
		if (!t[k])
			continue;
		size_t n = strlen(t[k]);
		if (n >= LABEL_MAX || strpbrk(t[k], "\"\n\r\t"))
			die("internal error: label \"%.40s\" cannot be written", t[k]);
		memcpy(slot(l, k), t[k], n + 1);
	}
}

static const struct plot_labels std[] = {
	[LABELS_SURFACE] = {"Developed resist surface", {"x (um)", "y (um)", "z (um)"}},
	[LABELS_TOPVIEW] = {"Developed resist surface, seen from above",
			    {"x (um)", "y (um)", ""}},
	[LABELS_CUT_X] = {"Resist cross-section", {"y (um)", "z (um)", ""}},
	[LABELS_CUT_Y] = {"Resist cross-section", {"x (um)", "z (um)", ""}},
	[LABELS_IMAGE] = {"Aerial image", {"x (um)", "y (um)", "intensity (clear field = 1)"}},
	[LABELS_CUTLINE] = {"Aerial image along a cutline",
			    {"distance along the cut (um)", "intensity (clear field = 1)", ""}},
	[LABELS_PAC] = {"Surface of constant PAC concentration",
			{"x (um)", "y (um)", "z (um)"}},
	[LABELS_PROFILE2D] = {"Developed resist profile", {"x (um)", "z (um)", ""}},
};

const struct plot_labels *fmt_labels_std(enum label_kind k)
{
	return &std[k];
}
