/*
 * fmt_template.h - the template-file of drawplot(L) -t: one line per
 * line style, cycled over the curves of a plot (thesis Appendix B):
 *
 *   ln_type = 1   mkr_type = 0   label = "Line 1"
 *   2 13                          # bare numbers: line type, marker type
 *
 * Keywords (case-insensitive; "=" optional): ln_type (also linetype,
 * line_type) 0-10, mkr_type (also markertype, marker_type) 0-17, label
 * (also linelabel, line_label) followed by the label, quoted if it has
 * spaces.  '#' starts a comment.  Missing fields default to line type 1,
 * marker 0, no label.  See man/man5/template.5.
 */
#ifndef S3D_FMT_TEMPLATE_H
#define S3D_FMT_TEMPLATE_H

struct template_entry {
	int ln_type;        /* 0-10, draw.h line types */
	int mkr_type;       /* 0-17, draw.h markers */
	char *label;        /* NULL if none (owned) */
	long line;
};

struct template {
	int n;
	struct template_entry *e;
};

/* Reads path; dies "prog: file:line: ..." on an unknown keyword, a value
 * out of range, a missing value, or a file with no entries. */
struct template *fmt_template_read(const char *path);
void fmt_template_write(const char *path, const struct template *t);
void fmt_template_free(struct template *t);

#endif
