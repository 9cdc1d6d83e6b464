/*
 * fmt_gds.h - reader of GDSII stream files (layouts), as splat's `gds`
 * statement uses them: the shapes of one layer of one cell, flattened
 * through every SREF and AREF, as polygons in micrometres.
 *
 * The format (Calma GDSII stream, release 3 onwards): a sequence of
 * records, each a big-endian 2-byte length (header included), a record
 * type byte and a data type byte; integers are big-endian two's
 * complement, reals 8-byte excess-64 base-16 floats.  Cells (BGNSTR ..
 * ENDSTR) hold elements: BOUNDARY, PATH, BOX, TEXT, NODE, SREF, AREF.
 *
 * Conventions (see man/man5/splat.5): micrometres = database units x
 * (the second UNITS number, metres per database unit) / 1e-6; a
 * reference applies reflection about x, then magnification, then
 * rotation, then the translation, AREF lattice vectors being in the
 * parent's frame; absolute magnification and angle are honoured; PATH
 * outlines are exact with mitred joins, pathtype 0 flush, 2 extended by
 * half the width, 4 by BGNEXTN/ENDEXTN, 1 round ends within 1 nm.
 */
#ifndef S3D_FMT_GDS_H
#define S3D_FMT_GDS_H

#include "poly.h"

struct gds_lib;         /* opaque */

/* Largest file read (it is held in memory whole), bytes. */
#define FMT_GDS_MAX_BYTES 4e9

/* Reads and checks the record structure of path (a regular file, at most
 * FMT_GDS_MAX_BYTES; .gz is read through gzip); dies with one line
 * "prog: [ctx: ]path: byte N: what is wrong" on a malformed file
 * (truncated, bad record length or type, bad counts, missing cell).  ctx
 * (may be NULL) names who asked, e.g. "mask.in:4". */
struct gds_lib *fmt_gds_read(const char *path, const char *ctx);
void fmt_gds_free(struct gds_lib *g);
/* 1 if some shape of the library (any cell) is on layer/datatype
 * (datatype -1: any); writes the library's layer/datatype pairs of shapes
 * into buf ("1/0, 2/0, 63/0"), for the message of a layer not there. */
int fmt_gds_layer_list(const struct gds_lib *g, int layer, int datatype, char *buf, size_t n);

/* Micrometres per database unit. */
double fmt_gds_um_per_dbu(const struct gds_lib *g);

/* Appends to out the shapes of layer (and datatype, or every datatype if
 * datatype < 0) of cell (NULL: the single top cell; several top cells is
 * an error listing them), flattened, in micrometres.  With win (xmin
 * xmax ymin ymax, micrometres) only shapes whose bounding box meets it
 * are kept (they are not clipped).  Dies on a missing cell, a reference
 * loop or a flattening beyond FMT_GDS_MAX_VISIT instances.  Returns the
 * number of shapes (elements) that contributed. */
enum { FMT_GDS_MAX_VISIT = 50000000 };
long fmt_gds_shapes(const struct gds_lib *g, const char *cell, int layer, int datatype,
		    const double *win, struct poly_set *out);

/* The same without exiting, for fuzzing and for callers that recover:
 * NULL (or -1) with the one-line message in err; nothing leaks. */
struct gds_lib *fmt_gds_read_mem(const char *name, const void *data, size_t len,
				 char *err, size_t errlen);
long fmt_gds_shapes_try(struct gds_lib *g, const char *cell, int layer, int datatype,
			const double *win, struct poly_set *out, char *err, size_t errlen);
/* Lowers the flattening limit (FMT_GDS_MAX_VISIT by default). */
void fmt_gds_set_max_visit(struct gds_lib *g, long n);

#endif
