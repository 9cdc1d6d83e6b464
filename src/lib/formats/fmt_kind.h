/*
 * fmt_kind.h - the kind of a file from its first bytes, so that a reader
 * given a file of another kind says so ("this is a rate file (rval(5));
 * pdraw reads plot3d(5)") instead of failing on its first number.
 */
#ifndef S3D_FMT_KIND_H
#define S3D_FMT_KIND_H

#include <stddef.h>

struct fmt_kind {
	const char *what;       /* "a rate file" */
	const char *page;       /* its manual page, "rval(5)" */
};

/* The kind of the file whose first n bytes are data, or NULL when its
 * head matches none of the kinds below with certainty. */
const struct fmt_kind *fmt_kind_of(const void *data, size_t n);

#endif
