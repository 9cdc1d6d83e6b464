/*
 * fmt_options.h - the options-file shared by the plot programs
 * (pdraw(L), contour(L), drawplot(L), drawmask(L)):
 *
 *   keyword value   # comment
 *
 * A value is a number, a "quoted string", on/off, or one word of a fixed
 * set (joinlevel high/low).  Each program passes a table of the keywords
 * it knows with their types and ranges; an unknown keyword, a missing or
 * extra value, or a value out of range is an error naming the line.
 * Keywords are case-insensitive.  See man/man5/options.5.
 */
#ifndef S3D_FMT_OPTIONS_H
#define S3D_FMT_OPTIONS_H

enum opt_type {
	OPT_ONOFF,      /* on/off (also yes/no, true/false, 1/0): num = 1 or 0 */
	OPT_NUM,        /* a number in [min, max] */
	OPT_INT,        /* a whole number in [min, max] */
	OPT_STRING,     /* a quoted string (a bare word is accepted too) */
	OPT_WORD        /* one word of words, "a|b|c", stored lowercase in str */
};

struct opt_spec {
	const char *key;
	enum opt_type type;
	double min, max;    /* OPT_NUM, OPT_INT */
	const char *words;  /* OPT_WORD */
};

struct opt_value {
	int set;            /* 1 if the file gave it */
	long line;          /* where */
	double num;
	char *str;          /* OPT_STRING, OPT_WORD (owned) */
};

/* spec is terminated by an entry whose key is NULL; val has one entry per
 * spec entry and is filled in (entries not in the file keep set = 0).
 * A keyword given twice keeps the last value. */
void fmt_options_read(const char *path, const struct opt_spec *spec,
		      struct opt_value *val);
/* Writes the set entries back in spec order (round-trip and docs). */
void fmt_options_write(const char *path, const struct opt_spec *spec,
		       const struct opt_value *val);
void fmt_options_free(const struct opt_spec *spec, struct opt_value *val);
/* Index of key in spec, or -1. */
int fmt_options_find(const struct opt_spec *spec, const char *key);

#endif
